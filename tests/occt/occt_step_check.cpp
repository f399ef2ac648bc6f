/* SPDX-License-Identifier: BSD-3-Clause */
// Open CASCADE reads the STEP files libprojcurve writes.
//
// Writes (1) two surfaces (one rational) and two curves (one rational),
// in millimetres and in inches, and (2) the projections of two cases of
// tests/data/cases and of a circle over a plane (rational compact forms) as
// SURFACE_CURVEs of their compact forms, then loads each
// with STEPControl_Reader: the load and the transfer must succeed, the
// shape must hold one face per surface and one free edge per curve or
// branch, and OCCT's geometry must be ours. The file holds every double
// exactly (17 digits), so only the evaluation's rounding separates OCCT's
// curves and surfaces from ours: they agree to 1e-12 relative at samples
// (far inside eps_D); the inch file comes back scaled by 25.4 (OCCT works in
// millimetres), which checks the unit. For each SURFACE_CURVE its PCURVE,
// converted by OCCT (StepToGeom) on the surface it names, gives S(q(t))
// equal to ours, and OCCT's own 3D curve and S(q(t)) lie within the file's
// uncertainty of each other (the two forms of one curve). Branches joined
// across the seams of a full cylinder and a torus give one SURFACE_CURVE
// per seam segment, each PCURVE inside OCCT's bounds of its surface (to
// 1e-12 of the width); so do the face pieces of the B-rep cases
// cyl_analytic_seam_conical and sphere_analytic_conical_outside (pieces
// that cross their face's seam), each face's result written with
// projcurve_step_writer_add_result. A whole-shape result
// (projcurve_step_writer_add_shape_result) on the 2x2 shell: one
// COMPOSITE_CURVE of four segments over B-splines OCCT converts, meeting
// within the chaining tolerance, transferred as four edges.
#include <cstdlib>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_BSplineCurve.hxx>
#include <StepGeom_BSplineSurface.hxx>
#include <StepGeom_CompositeCurve.hxx>
#include <StepGeom_CompositeCurveSegment.hxx>
#include <StepGeom_Pcurve.hxx>
#include <StepGeom_PcurveOrSurface.hxx>
#include <StepGeom_SurfaceCurve.hxx>
#include <StepRepr_DefinitionalRepresentation.hxx>
#include <StepToGeom.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

extern "C" {
#include "check.h"
#include "projcurve.h"
#include "shapes.h"
#include "trace/result.h"
}

namespace {

projcurve_context *ctx = nullptr;

// Samples per direction / per knot span, and the agreement asked of two
// evaluations of the same exact data.
constexpr int kSamples = 7;
constexpr double kAgreeRel = 1e-12;

double distance(const gp_Pnt &a, const double b[3], double scale = 1.0)
{
    return std::sqrt((a.X() - scale * b[0]) * (a.X() - scale * b[0]) +
                     (a.Y() - scale * b[1]) * (a.Y() - scale * b[1]) +
                     (a.Z() - scale * b[2]) * (a.Z() - scale * b[2]));
}

struct loaded {
    std::vector<TopoDS_Face> faces; // the free faces of the transferred shape
    std::vector<TopoDS_Edge> edges; // its free edges (not a face's boundary)
    Handle(StepData_StepModel) model;
    bool ok = false;
};

// Reads and transfers path; the shape's faces and free edges.
loaded load(STEPControl_Reader &reader, const std::string &path)
{
    loaded l;
    const IFSelect_ReturnStatus st = reader.ReadFile(path.c_str());
    CHECK(st == IFSelect_RetDone);
    if (st != IFSelect_RetDone)
        return l;
    l.model = reader.StepModel();
    CHECK(reader.TransferRoots() >= 1);
    const TopoDS_Shape shape = reader.OneShape();
    CHECK(!shape.IsNull());
    if (shape.IsNull())
        return l;
    // A geometric set is transferred as a compound of faces and edges.
    std::vector<TopoDS_Shape> todo{shape};
    for (size_t k = 0; k < todo.size() && k < 100000; ++k) {
        const TopoDS_Shape s = todo[k];
        if (s.ShapeType() == TopAbs_FACE)
            l.faces.push_back(TopoDS::Face(s));
        else if (s.ShapeType() == TopAbs_EDGE)
            l.edges.push_back(TopoDS::Edge(s));
        else if (s.ShapeType() == TopAbs_COMPOUND)
            for (TopoDS_Iterator it(s); it.More(); it.Next())
                todo.push_back(it.Value());
    }
    std::printf("%s: %d entities, %zu faces, %zu free edges\n", path.c_str(),
                l.model.IsNull() ? 0 : l.model->NbEntities(), l.faces.size(), l.edges.size());
    l.ok = true;
    return l;
}

// Largest distance between a face's surface and ours (scaled) over a grid.
double surface_gap(const TopoDS_Face &face, const projcurve_surface *s, double scale)
{
    Handle(Geom_Surface) g = BRep_Tool::Surface(face);
    double d[4], gap = 0.0;
    CHECK_OK(projcurve_surface_domain(ctx, s, d));
    for (int i = 0; i < kSamples; ++i)
        for (int j = 0; j < kSamples; ++j) {
            const double u = d[0] + (d[1] - d[0]) * i / (kSamples - 1.0);
            const double v = d[2] + (d[3] - d[2]) * j / (kSamples - 1.0);
            double p[3];
            CHECK_OK(projcurve_surface_eval(ctx, s, u, v, 0, p));
            gap = std::max(gap, distance(g->Value(u, v), p, scale));
        }
    return gap;
}

// Largest distance between an edge's curve and ours (scaled), sampled per
// knot span of ours.
double curve_gap(const TopoDS_Edge &edge, const projcurve_curve *c, double scale)
{
    Standard_Real first = 0.0, last = 0.0;
    Handle(Geom_Curve) g = BRep_Tool::Curve(edge, first, last);
    if (g.IsNull())
        return HUGE_VAL;
    int degree = 0;
    size_t n = 0, nk = 0;
    CHECK_OK(projcurve_curve_nurbs_info(ctx, c, &degree, &n, &nk, nullptr));
    std::vector<double> knots(nk);
    CHECK_OK(projcurve_curve_nurbs_data(ctx, c, nullptr, nullptr, knots.data()));
    double gap = 0.0;
    for (size_t k = static_cast<size_t>(degree); k < n; ++k)
        for (int i = 0; i < kSamples; ++i) {
            const double t = knots[k] + (knots[k + 1] - knots[k]) * i / (kSamples - 1.0);
            double p[3];
            CHECK_OK(projcurve_curve_eval(ctx, c, t, 0, p));
            gap = std::max(gap, distance(g->Value(t), p, scale));
        }
    return gap;
}

// Every surface has a face and every curve an edge of OCCT's that is it.
void check_same_geometry(const loaded &l, const std::vector<const projcurve_surface *> &ss,
                         const std::vector<const projcurve_curve *> &cs, double size,
                         double scale, const char *what)
{
    CHECK(l.faces.size() == ss.size());
    CHECK(l.edges.size() == cs.size());
    for (const projcurve_surface *s : ss) {
        double best = HUGE_VAL;
        for (const TopoDS_Face &f : l.faces)
            best = std::min(best, surface_gap(f, s, scale));
        if (!(best <= kAgreeRel * size * scale))
            pc_test_fail_at(__FILE__, __LINE__, "%s: no OCCT face within %g of a surface (%g)",
                            what, kAgreeRel * size * scale, best);
        ++pc_test_checks;
    }
    for (const projcurve_curve *c : cs) {
        double best = HUGE_VAL;
        for (const TopoDS_Edge &e : l.edges)
            best = std::min(best, curve_gap(e, c, scale));
        if (!(best <= kAgreeRel * size * scale))
            pc_test_fail_at(__FILE__, __LINE__, "%s: no OCCT edge within %g of a curve (%g)",
                            what, kAgreeRel * size * scale, best);
        ++pc_test_checks;
    }
}

projcurve_surface *plane()
{
    const double ctrl[] = {0, 0, 0, 10, 0, 0, 0, 10, 1, 10, 10, 1};
    const double k[] = {0, 0, 1, 1};
    projcurve_surface *s = nullptr;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, ctrl, nullptr, k, k, &s));
    return s;
}

projcurve_surface *quarter_cylinder()
{
    const double w = 0.70710678118654752;
    const double ctrl[] = {3, 0, 0, 3, 0, 3, 0, 0, 3, 3, 5, 0, 3, 5, 3, 0, 5, 3};
    const double weights[] = {1, w, 1, 1, w, 1};
    const double ku[] = {0, 0, 0, 1, 1, 1}, kv[] = {0, 0, 1, 1};
    projcurve_surface *s = nullptr;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 2, 1, 3, 2, ctrl, weights, ku, kv, &s));
    return s;
}

projcurve_curve *cubic()
{
    const double ctrl[] = {0, 0, 5, 3, 4, 6, 6, -1, 5, 9, 2, 7};
    const double knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
    projcurve_curve *c = nullptr;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 3, 4, ctrl, nullptr, knots, &c));
    return c;
}

projcurve_curve *half_circle()
{
    const double ctrl[] = {1, 0, 0.5, 1, 1.7320508075688772, 0.5, 0, 1.1547005383792515, 0.5,
                           -1, 1.7320508075688772, 0.5, -1, 0, 0.5};
    const double weights[] = {1, 0.5, 1, 0.5, 1};
    const double knots[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    projcurve_curve *c = nullptr;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 2, 5, ctrl, weights, knots, &c));
    return c;
}

void geometry(const std::string &dir)
{
    projcurve_surface *s1 = plane(), *s2 = quarter_cylinder();
    projcurve_curve *c1 = cubic(), *c2 = half_circle();
    const double units[2] = {1e-3, 0.0254};
    for (int k = 0; k < 2; ++k) {
        projcurve_step_writer *w = nullptr;
        CHECK_OK(projcurve_step_writer_create(ctx, &w));
        CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s1));
        CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s2));
        CHECK_OK(projcurve_step_writer_add_curve(ctx, w, c1));
        CHECK_OK(projcurve_step_writer_add_curve(ctx, w, c2));
        CHECK_OK(projcurve_step_writer_set_length_unit(ctx, w, units[k]));
        const std::string path = dir + (k == 0 ? "/occt_geometry_mm.step" : "/occt_geometry_in.stp");
        CHECK_OK(projcurve_step_writer_write(ctx, w, path.c_str()));
        projcurve_step_writer_destroy(w);
        STEPControl_Reader reader;
        const loaded l = load(reader, path);
        if (l.ok)
            check_same_geometry(l, {s1, s2}, {c1, c2}, 10.0, units[k] / 1e-3, path.c_str());
    }
    projcurve_curve_destroy(c1);
    projcurve_curve_destroy(c2);
    projcurve_surface_destroy(s1);
    projcurve_surface_destroy(s2);
}

// The SURFACE_CURVEs of the file in file order, each as OCCT converts its
// parts: the 3D curve, the pcurve and the surface the pcurve names.
struct occt_surface_curve {
    Handle(Geom_BSplineCurve) curve;
    Handle(Geom2d_BSplineCurve) pcurve;
    Handle(Geom_BSplineSurface) surface;
};

std::vector<occt_surface_curve> surface_curves(const Handle(StepData_StepModel) & model)
{
    std::vector<occt_surface_curve> out;
    for (Standard_Integer i = 1; !model.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(StepGeom_SurfaceCurve) sc = Handle(StepGeom_SurfaceCurve)::DownCast(model->Value(i));
        if (sc.IsNull())
            continue;
        occt_surface_curve o;
        Handle(StepGeom_BSplineCurve) c3 = Handle(StepGeom_BSplineCurve)::DownCast(sc->Curve3d());
        if (!c3.IsNull())
            o.curve = StepToGeom::MakeBSplineCurve(c3);
        Handle(StepGeom_Pcurve) pc =
            sc->NbAssociatedGeometry() == 1 ? sc->AssociatedGeometryValue(1).Pcurve() : nullptr;
        if (!pc.IsNull()) {
            Handle(StepGeom_BSplineSurface) bs =
                Handle(StepGeom_BSplineSurface)::DownCast(pc->BasisSurface());
            if (!bs.IsNull())
                o.surface = StepToGeom::MakeBSplineSurface(bs);
            Handle(StepRepr_DefinitionalRepresentation) rep = pc->ReferenceToCurve();
            if (!rep.IsNull() && rep->NbItems() == 1) {
                Handle(StepGeom_BSplineCurve) c2 =
                    Handle(StepGeom_BSplineCurve)::DownCast(rep->ItemsValue(1));
                if (!c2.IsNull())
                    o.pcurve = StepToGeom::MakeBSplineCurve2d(c2);
            }
        }
        out.push_back(o);
    }
    return out;
}

// Writes result r on s as STEP and checks what OCCT reads (see the top).
void check_written(const std::string &dir, const char *name, const projcurve_surface *s,
                   const projcurve_result *r)
{
    const size_t n = projcurve_result_branch_count(r);
    CHECK(n > 0);
    projcurve_step_writer *w = nullptr;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_result(ctx, w, s, r));
    const std::string path = dir + "/occt_" + name + ".step";
    CHECK_OK(projcurve_step_writer_write(ctx, w, path.c_str()));
    projcurve_step_writer_destroy(w);

    double d[4], corners[2][3];
    CHECK_OK(projcurve_surface_domain(ctx, s, d));
    CHECK_OK(projcurve_surface_eval(ctx, s, d[0], d[2], 0, corners[0]));
    CHECK_OK(projcurve_surface_eval(ctx, s, d[1], d[3], 0, corners[1]));
    const double size = std::max(1.0, std::hypot(corners[1][0] - corners[0][0],
                                                 corners[1][1] - corners[0][1],
                                                 corners[1][2] - corners[0][2]));
    std::vector<projcurve_curve *> curves(n, nullptr), pcurves(n, nullptr);
    for (size_t b = 0; b < n; ++b) {
        CHECK_OK(projcurve_result_branch_compact_curve(ctx, r, b, &curves[b]));
        CHECK_OK(projcurve_result_branch_compact_pcurve(ctx, r, b, &pcurves[b]));
    }
    // the uncertainty the file states, as the library reads it back
    double uncertainty = 0.0;
    projcurve_model *back = nullptr;
    CHECK_OK(projcurve_model_read_file(ctx, path.c_str(), &back));
    CHECK(back != nullptr && projcurve_model_precision(back, &uncertainty));
    projcurve_model_destroy(back);
    STEPControl_Reader reader;
    const loaded l = load(reader, path);
    if (l.ok)
        check_same_geometry(l, {s}, std::vector<const projcurve_curve *>(curves.begin(), curves.end()),
                            size, 1.0, path.c_str());
    const std::vector<occt_surface_curve> scs = surface_curves(l.model);
    CHECK(scs.size() == n);
    for (size_t b = 0; b < std::min(n, scs.size()); ++b) {
        const occt_surface_curve &o = scs[b];
        CHECK(!o.curve.IsNull() && !o.pcurve.IsNull() && !o.surface.IsNull());
        if (o.curve.IsNull() || o.pcurve.IsNull() || o.surface.IsNull() || !curves[b])
            continue;
        int degree = 0;
        size_t n_poles = 0, n_knots = 0;
        CHECK_OK(projcurve_curve_nurbs_info(ctx, pcurves[b], &degree, &n_poles, &n_knots, nullptr));
        // a closed curve (closed_curve .T.: a circle) OCCT makes periodic,
        // with the repeated pole dropped; the samples below compare it
        CHECK(o.pcurve->Degree() == degree);
        CHECK(o.pcurve->NbPoles() == static_cast<int>(n_poles) ||
              (o.pcurve->IsPeriodic() && o.pcurve->NbPoles() < static_cast<int>(n_poles)));
        std::vector<double> knots(n_knots);
        CHECK_OK(projcurve_curve_nurbs_data(ctx, pcurves[b], nullptr, nullptr, knots.data()));
        double gap_s = 0.0, gap_forms = 0.0;
        for (size_t k = static_cast<size_t>(degree); k < n_poles; ++k)
            for (int i = 0; i < kSamples; ++i) {
                const double t = knots[k] + (knots[k + 1] - knots[k]) * i / (kSamples - 1.0);
                double uv[3], q[3];
                CHECK_OK(projcurve_curve_eval(ctx, pcurves[b], t, 0, uv));
                CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, q));
                const gp_Pnt2d puv = o.pcurve->Value(t);
                const gp_Pnt on = o.surface->Value(puv.X(), puv.Y());
                gap_s = std::max(gap_s, distance(on, q));
                gap_forms = std::max(gap_forms, on.Distance(o.curve->Value(t)));
            }
        if (!(gap_s <= kAgreeRel * size))
            pc_test_fail_at(__FILE__, __LINE__, "%s: branch %zu: OCCT's S(q(t)) is %g from ours",
                            path.c_str(), b, gap_s);
        ++pc_test_checks;
        // the two forms of the one curve, both as OCCT reads them, within
        // the uncertainty the file states (the fits' measured errors)
        if (!(gap_forms <= uncertainty * (1.0 + 1e-9) + kAgreeRel * size))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: branch %zu: OCCT's 3D curve and S(q(t)) are %g apart (> %g)",
                            path.c_str(), b, gap_forms, uncertainty);
        ++pc_test_checks;
        std::printf("%s: branch %zu: pcurve degree %d, %d poles; forms %g apart\n", path.c_str(),
                    b, o.pcurve->Degree(), o.pcurve->NbPoles(), gap_forms);
    }
    for (size_t b = 0; b < n; ++b) {
        projcurve_curve_destroy(curves[b]);
        projcurve_curve_destroy(pcurves[b]);
    }
}

void check_case(const std::string &dir, const char *name, const double direction[3])
{
    projcurve_model *in = nullptr;
    const std::string input = std::string("cases/") + name + ".igs";
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path(input.c_str()), &in));
    if (in == nullptr)
        return;
    const projcurve_surface *s = projcurve_model_surface(in, 0);
    projcurve_result *r = nullptr;
    CHECK_OK(projcurve_project_directional(ctx, s, projcurve_model_curve(in, 0), direction,
                                           nullptr, &r));
    if (r != nullptr)
        check_written(dir, name, s, r);
    projcurve_result_destroy(r);
    projcurve_model_destroy(in);
}

// A circle over a plane: its compact forms are in the circle's rational
// space (the complex rational entities in 2D and 3D).
void check_circle(const std::string &dir)
{
    pc_shape_surface plane = pc_shape_plane(3, 3, 4, 4);
    const double centre[3] = {0.1, 0.2, 0.7}, down[3] = {0.0, 0.0, -1.0};
    pc_shape_curve circle = pc_shape_circle(centre, 0.6);
    projcurve_surface *s = pc_shape_surface_create(&plane);
    projcurve_curve *c = pc_shape_curve_create(&circle);
    projcurve_result *r = nullptr;
    CHECK_OK(projcurve_project_directional(ctx, s, c, down, nullptr, &r));
    if (r != nullptr)
        check_written(dir, "circle_over_plane", s, r);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&plane);
    pc_shape_curve_free(&circle);
}

// A line projected orthogonally around a closed shape, written as STEP:
// one SURFACE_CURVE per seam segment, each pcurve inside the bounds OCCT
// gives its surface, its S(q(t)) within 2 eps_D of its 3D curve (each
// compact form is within eps_D of the projection; the file's uncertainty,
// the fits' errors measured at their check samples, is exceeded by dense
// samples by a few percent here, so it is not the bound).
//
// The result r onto s written by projcurve_step_writer_add_result and read
// back: `segments` SURFACE_CURVEs, each checked as above.
void check_written_seams(const std::string &path, const projcurve_surface *s,
                         const projcurve_result *r, size_t segments)
{
    projcurve_step_writer *w = nullptr;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_result(ctx, w, s, r));
    CHECK_OK(projcurve_step_writer_write(ctx, w, path.c_str()));
    projcurve_step_writer_destroy(w);
    double uncertainty = 0.0, box[6];
    projcurve_model *back = nullptr;
    CHECK_OK(projcurve_model_read_file(ctx, path.c_str(), &back));
    CHECK(back != nullptr && projcurve_model_precision(back, &uncertainty));
    projcurve_model_destroy(back);
    CHECK_OK(projcurve_surface_bounds(ctx, s, box));
    const double size = std::max({box[3] - box[0], box[4] - box[1], box[5] - box[2]});
    STEPControl_Reader reader;
    const loaded l = load(reader, path);
    CHECK(l.edges.size() == segments);
    const std::vector<occt_surface_curve> scs = surface_curves(l.model);
    CHECK(scs.size() == segments);
    for (size_t k = 0; k < scs.size(); ++k) {
        const occt_surface_curve &o = scs[k];
        CHECK(!o.curve.IsNull() && !o.pcurve.IsNull() && !o.surface.IsNull());
        if (o.curve.IsNull() || o.pcurve.IsNull() || o.surface.IsNull())
            continue;
        double u1, u2, v1, v2;
        o.surface->Bounds(u1, u2, v1, v2);
        const double t0 = o.pcurve->FirstParameter(), t1 = o.pcurve->LastParameter();
        double outside = 0.0, gap = 0.0;
        for (int i = 0; i <= 200; ++i) {
            const double t = t0 + (t1 - t0) * i / 200.0;
            const gp_Pnt2d uv = o.pcurve->Value(t);
            outside = std::max({outside, (u1 - uv.X()) / (u2 - u1), (uv.X() - u2) / (u2 - u1),
                                (v1 - uv.Y()) / (v2 - v1), (uv.Y() - v2) / (v2 - v1)});
            gap = std::max(gap, o.surface->Value(uv.X(), uv.Y()).Distance(o.curve->Value(t)));
        }
        const double allowed = 2.0 * r->stats.tol_distance + kAgreeRel * size;
        if (!(outside <= kAgreeRel) || !(gap <= allowed))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: SURFACE_CURVE %zu: its pcurve leaves the surface's bounds by "
                            "%g of the width, S(q(t)) is %g from its 3D curve (allowed %g)",
                            path.c_str(), k, outside, gap, allowed);
        ++pc_test_checks;
        std::printf("%s: SURFACE_CURVE %zu over [%g, %g]: inside the bounds, forms %g apart "
                    "(uncertainty %g)\n",
                    path.c_str(), k, t0, t1, gap, uncertainty);
    }
}

void check_seam_case(const std::string &dir, const char *name, pc_shape_surface shape,
                     const double p0[3], const double p1[3], size_t jumps)
{
    projcurve_surface *s = pc_shape_surface_create(&shape);
    pc_shape_surface_free(&shape);
    const double ctrl[6] = {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]};
    const double knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = nullptr;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, ctrl, nullptr, knots, &c));
    projcurve_result *r = nullptr;
    if (s && c)
        CHECK_OK(projcurve_project_orthogonal(ctx, s, c, nullptr, &r));
    projcurve_curve_destroy(c);
    if (r == nullptr) {
        projcurve_surface_destroy(s);
        return;
    }
    size_t seen = 0;
    for (size_t b = 0; b < r->n_branches; ++b)
        seen += r->branches[b].n_seams;
    CHECK(seen == jumps);
    check_written_seams(dir + "/occt_seams_" + name + ".step", s, r, r->n_branches + jumps);
    projcurve_result_destroy(r);
    projcurve_surface_destroy(s);
}

// The face pieces of a B-rep case of tests/data/cases-brep projected from
// its eye (projcurve_project_shape), each face's result written with
// projcurve_step_writer_add_result on the face's surface: a piece that
// crosses its face's seam has its jumps (projcurve_result_branch_seam_count)
// and is written as one SURFACE_CURVE per seam segment, each PCURVE inside
// the surface's bounds (before face pieces kept their jumps, the cylinder's
// piece was one PCURVE with u up to 7.49 on [0, 2 pi], which OCCT
// rejected). `jumps` is the count the case must give (the curve crosses
// the seam of each face it meets once).
void check_face_seam_case(const std::string &dir, const char *name, const char *model_file,
                          const double eye[3], double eps_d, size_t jumps)
{
    projcurve_model *model = nullptr, *curves = nullptr;
    const std::string mpath = std::string("cases-brep/") + model_file;
    const std::string cpath = std::string("cases-brep/") + name + ".curves.igs";
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path(mpath.c_str()), &model));
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path(cpath.c_str()), &curves));
    projcurve_options *o = nullptr;
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    projcurve_shape_result *sr = nullptr;
    if (model && curves && projcurve_model_shape_count(model) > 0 &&
        projcurve_model_curve_count(curves) > 0)
        CHECK_OK(projcurve_project_shape(ctx, projcurve_model_shape(model, 0),
                                         projcurve_model_curve(curves, 0),
                                         PROJCURVE_PROJECT_CONICAL, eye, o, &sr));
    CHECK(sr != nullptr);
    const projcurve_shape *shape = sr ? projcurve_model_shape(model, 0) : nullptr;
    size_t seen = 0;
    for (size_t i = 0; sr && i < projcurve_shape_result_face_count(sr); ++i) {
        size_t fi = 0;
        const projcurve_result *fr = nullptr;
        projcurve_status fs = PROJCURVE_OK;
        CHECK_OK(projcurve_shape_result_face(ctx, sr, i, &fi, &fr, &fs, nullptr));
        if (fr == nullptr || projcurve_result_branch_count(fr) == 0)
            continue;
        size_t face_jumps = 0;
        for (size_t b = 0; b < projcurve_result_branch_count(fr); ++b) {
            size_t n = 0;
            CHECK_OK(projcurve_result_branch_seam_count(ctx, fr, b, &n));
            face_jumps += n;
        }
        seen += face_jumps;
        const projcurve_surface *s = projcurve_face_surface(projcurve_shape_face(shape, fi));
        check_written_seams(dir + "/occt_face_seams_" + name + "_" + std::to_string(fi) +
                                ".step",
                            s, fr, projcurve_result_branch_count(fr) + face_jumps);
    }
    CHECK(seen == jumps);
    std::printf("%s: %zu seam jump(s) over its face pieces\n", name, seen);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(o);
    projcurve_model_destroy(curves);
    projcurve_model_destroy(model);
}

// occt_step_check --file PATH N TOL: a file written elsewhere (the
// command's -o out.step of tests/cli/check_faces.py): OCCT reads it, finds
// N SURFACE_CURVEs, and on each S(q(t)) lies within TOL of the 3D curve.
int check_given_file(const std::string &path, size_t n, double tol)
{
    STEPControl_Reader reader;
    const loaded l = load(reader, path);
    const std::vector<occt_surface_curve> scs = surface_curves(l.model);
    if (scs.size() != n)
        pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT finds %zu SURFACE_CURVEs, expected %zu",
                        path.c_str(), scs.size(), n);
    ++pc_test_checks;
    for (size_t k = 0; k < scs.size(); ++k) {
        const occt_surface_curve &o = scs[k];
        CHECK(!o.curve.IsNull() && !o.pcurve.IsNull() && !o.surface.IsNull());
        if (o.curve.IsNull() || o.pcurve.IsNull() || o.surface.IsNull())
            continue;
        const double t0 = o.pcurve->FirstParameter(), t1 = o.pcurve->LastParameter();
        double gap = 0.0, u_lo = INFINITY, u_hi = -INFINITY;
        for (int i = 0; i <= 100; ++i) {
            const double t = t0 + (t1 - t0) * i / 100.0;
            const gp_Pnt2d uv = o.pcurve->Value(t);
            u_lo = std::min(u_lo, uv.X());
            u_hi = std::max(u_hi, uv.X());
            gap = std::max(gap, o.surface->Value(uv.X(), uv.Y()).Distance(o.curve->Value(t)));
        }
        double u1, u2, v1, v2;
        o.surface->Bounds(u1, u2, v1, v2);
        if (!(gap <= tol))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: SURFACE_CURVE %zu over t [%g, %g] (3D curve [%g, %g]): forms "
                            "%g apart (> %g); pcurve u in [%g, %g], surface u in [%g, %g]",
                            path.c_str(), k, t0, t1, o.curve->FirstParameter(),
                            o.curve->LastParameter(), gap, tol, u_lo, u_hi, u1, u2);
        ++pc_test_checks;
    }
    return pc_test_finish("occt_step_check --file");
}

} // namespace

// A whole-shape result (projcurve_step_writer_add_shape_result): the U
// curve of shell_2x2_bspline_oblique onto the 2x2 shell, one connected
// curve of four face pieces. OCCT finds one COMPOSITE_CURVE of four
// segments, each over a B-spline that OCCT converts, consecutive ones
// meeting within the chaining tolerance (OCCT's own evaluation), and
// transfers the set.
void check_shape_result(const std::string &dir)
{
    projcurve_model *shell = nullptr, *curves = nullptr;
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path("cases-brep/shell_2x2.step"), &shell));
    CHECK_OK(projcurve_model_read_file(
        ctx, pc_test_data_path("cases-brep/shell_2x2_bspline_oblique.curves.igs"), &curves));
    if (shell == nullptr || curves == nullptr)
        return;
    const double d[3] = {0.2, -0.1, -1.0};
    projcurve_shape_result *r = nullptr;
    CHECK_OK(projcurve_project_shape(ctx, projcurve_model_shape(shell, 0),
                                     projcurve_model_curve(curves, 0),
                                     PROJCURVE_PROJECT_DIRECTIONAL, d, nullptr, &r));
    projcurve_step_writer *w = nullptr;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_shape_result(ctx, w, r));
    const std::string path = dir + "/occt_shape_result.step";
    CHECK_OK(projcurve_step_writer_write(ctx, w, path.c_str()));
    projcurve_step_writer_destroy(w);
    const double tol = projcurve_shape_result_chain_tolerance(r);

    STEPControl_Reader reader;
    const loaded l = load(reader, path);
    std::vector<int> segments;
    for (Standard_Integer i = 1; !l.model.IsNull() && i <= l.model->NbEntities(); ++i) {
        Handle(StepGeom_CompositeCurve) cc = Handle(StepGeom_CompositeCurve)::DownCast(l.model->Value(i));
        if (cc.IsNull())
            continue;
        segments.push_back(cc->NbSegments());
        gp_Pnt last;
        for (Standard_Integer k = 1; k <= cc->NbSegments(); ++k) {
            Handle(StepGeom_BSplineCurve) b =
                Handle(StepGeom_BSplineCurve)::DownCast(cc->SegmentsValue(k)->ParentCurve());
            CHECK(!b.IsNull() && cc->SegmentsValue(k)->SameSense());
            Handle(Geom_BSplineCurve) g = b.IsNull() ? nullptr : StepToGeom::MakeBSplineCurve(b);
            CHECK(!g.IsNull());
            if (g.IsNull())
                continue;
            if (k > 1)
                CHECK(last.Distance(g->Value(g->FirstParameter())) <= tol);
            last = g->Value(g->LastParameter());
        }
    }
    CHECK(segments.size() == 1 && segments[0] == 4);
    // the composite is transferred as a wire of one edge per segment
    int edges = 0;
    for (TopExp_Explorer e(reader.OneShape(), TopAbs_EDGE); e.More() && edges < 100000; e.Next())
        ++edges;
    CHECK(edges == 4);
    std::printf("%s: %zu composite curves, %d edges\n", path.c_str(), segments.size(), edges);
    projcurve_shape_result_destroy(r);
    projcurve_model_destroy(shell);
    projcurve_model_destroy(curves);
}

// occt_step_check --composites PATH M1,M2,...: a file with one
// COMPOSITE_CURVE per connected curve (the command's --faces -o out.step
// of tests/cli/check_faces.py): OCCT reads it and finds the composites in
// instance order with M1, M2, ... segments, each over a B-spline it
// converts.
int check_given_composites(const std::string &path, const std::string &counts)
{
    std::vector<int> want;
    for (size_t pos = 0; pos < counts.size() && want.size() < 100000;) {
        const size_t comma = counts.find(',', pos);
        want.push_back(std::atoi(counts.substr(pos, comma - pos).c_str()));
        if (comma == std::string::npos)
            break;
        pos = comma + 1;
    }
    STEPControl_Reader reader;
    const loaded l = load(reader, path);
    std::vector<int> got;
    for (Standard_Integer i = 1; !l.model.IsNull() && i <= l.model->NbEntities(); ++i) {
        Handle(StepGeom_CompositeCurve) cc =
            Handle(StepGeom_CompositeCurve)::DownCast(l.model->Value(i));
        if (cc.IsNull())
            continue;
        got.push_back(cc->NbSegments());
        for (Standard_Integer k = 1; k <= cc->NbSegments(); ++k) {
            Handle(StepGeom_BSplineCurve) b =
                Handle(StepGeom_BSplineCurve)::DownCast(cc->SegmentsValue(k)->ParentCurve());
            CHECK(!b.IsNull() && !StepToGeom::MakeBSplineCurve(b).IsNull());
        }
    }
    if (got != want) {
        std::string text;
        for (const int g : got)
            text += (text.empty() ? "" : ",") + std::to_string(g);
        pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT finds COMPOSITE_CURVEs of %s segments, "
                        "expected %s", path.c_str(), text.c_str(), counts.c_str());
    }
    ++pc_test_checks;
    return pc_test_finish("occt_step_check --composites");
}

int main(int argc, char **argv)
{
    if (argc == 4 && std::string(argv[1]) == "--composites")
        return check_given_composites(argv[2], argv[3]);
    if (argc == 5 && std::string(argv[1]) == "--file")
        return check_given_file(argv[2], std::strtoul(argv[3], nullptr, 10),
                                std::strtod(argv[4], nullptr));
    const std::string dir = argc > 1 ? argv[1] : ".";
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    geometry(dir);
    const double minus_x[3] = {-1.0, 0.0, 0.0}, minus_z[3] = {0.0, 0.0, -1.0};
    check_case(dir, "song_yong_example1", minus_x);
    check_case(dir, "fold_c_sheet_jump", minus_z);
    check_circle(dir);
    const double cyl0[3] = {2, -1, 0.5}, cyl1[3] = {2, 1, 1.5};
    check_seam_case(dir, "cylinder", pc_shape_cylinder(1.0, 2.0), cyl0, cyl1, 1);
    const double tor0[3] = {3, -1, -0.6}, tor1[3] = {3, 1, 0.4};
    check_seam_case(dir, "torus", pc_shape_torus(2.0, 0.5), tor0, tor1, 2);
    // the eyes and tolerances of tests/data/cases-brep/MANIFEST.tsv
    const double cyl_eye[3] = {0, 0, 10}, sphere_eye[3] = {0, 0, 40};
    check_face_seam_case(dir, "cyl_analytic_seam_conical", "cylinder_analytic.step", cyl_eye,
                         1e-3, 1);
    check_face_seam_case(dir, "sphere_analytic_conical_outside", "sphere_analytic.step",
                         sphere_eye, 1e-3, 2);
    check_shape_result(dir);
    projcurve_context_destroy(ctx);
    return pc_test_finish("occt_step_check");
}
