/* SPDX-License-Identifier: BSD-3-Clause */
// Open CASCADE reads the IGES files libprojcurve writes.
//
// Writes (1) two surfaces and a curve, (2) a surface with a hand-made
// projection result (one branch: pcurve 126, 3D curve 126, curve on surface
// 142) and (3) the projections of two cases of tests/data/cases, then loads each with IGESControl_Reader: the load must succeed, the
// model must hold exactly the entities written (by type), and the
// transferred shapes must be non-null with faces/edges where expected. For
// (1) the geometry OCCT builds must be ours: its surfaces and curve agree
// with the library's evaluation at sample parameters to 1e-12 relative.
// For (2) and (3) each curve on surface is converted by OCCT's own IGES
// geometry transfer (IGESToBRep): its 3D curve C(t) and its surface
// composed with its pcurve, S(p(t)), must agree to 1e-12 relative with the
// branch's curve and with the library's surface at the (u, v) of the
// branch's pieces (projcurve_result_piece_pcurve), at samples over every
// piece. (4) Branches joined across the seams of a full cylinder and a
// torus: one 142 per seam segment, each pcurve inside OCCT's bounds of its
// surface (to 1e-12 of the width) and OCCT's S(p(t)) within 2 eps_D of its
// 3D curve (each compact form is within eps_D of the projection); the
// same for the face pieces of the B-rep cases cyl_analytic_seam_conical
// and sphere_analytic_conical_outside (across their face's seam), each
// face's result written with projcurve_iges_writer_add_result. (5) A
// whole-shape result (projcurve_iges_writer_add_shape_result) on the 2x2
// shell: one composite curve (102) of four members, transferred.
#include <cstdlib>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <IGESGeom_BSplineCurve.hxx>
#include <IGESGeom_BSplineSurface.hxx>
#include <IGESGeom_CompositeCurve.hxx>
#include <IGESGeom_CurveOnSurface.hxx>
#include <IGESToBRep_BasicCurve.hxx>
#include <IGESToBRep_BasicSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
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

std::map<int, int> occt_entity_types(IGESControl_Reader &reader)
{
    std::map<int, int> count;
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    for (Standard_Integer i = 1; i <= model->NbEntities(); ++i)
        ++count[model->Entity(i)->TypeNumber()];
    return count;
}

int count_shapes(const TopoDS_Shape &shape, TopAbs_ShapeEnum kind)
{
    int n = 0;
    for (TopExp_Explorer e(shape, kind); e.More(); e.Next())
        ++n;
    return n;
}

// Loads path with OCCT and checks the entity counts by type and that
// something was transferred (faces >= min_faces, edges >= min_edges).
void check_file(const std::string &path, const std::map<int, int> &expected, int min_faces,
                int min_edges)
{
    IGESControl_Reader reader;
    const IFSelect_ReturnStatus st = reader.ReadFile(path.c_str());
    CHECK(st == IFSelect_RetDone);
    if (st != IFSelect_RetDone)
        return;
    const std::map<int, int> got = occt_entity_types(reader);
    for (const auto &kv : expected) {
        const auto it = got.find(kv.first);
        const int n = it == got.end() ? 0 : it->second;
        if (n != kv.second)
            pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT sees %d entities of type %d, wrote %d",
                            path.c_str(), n, kv.first, kv.second);
        ++pc_test_checks;
    }
    int total = 0;
    for (const auto &kv : got)
        total += kv.second;
    int written = 0;
    for (const auto &kv : expected)
        written += kv.second;
    CHECK(total == written);
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    CHECK(!shape.IsNull());
    if (shape.IsNull())
        return;
    const int faces = count_shapes(shape, TopAbs_FACE), edges = count_shapes(shape, TopAbs_EDGE);
    std::printf("%s: %d entities, %d faces, %d edges\n", path.c_str(), total, faces, edges);
    CHECK(faces >= min_faces);
    CHECK(edges >= min_edges);
}

// Samples per direction when comparing OCCT's geometry with ours, and the
// agreement asked: the file holds every double exactly (17 digits), so
// only the evaluation's rounding separates the two.
constexpr int kSamples = 7;
constexpr double kAgreeRel = 1e-12;

double distance(const gp_Pnt &a, const double b[3])
{
    return std::sqrt((a.X() - b[0]) * (a.X() - b[0]) + (a.Y() - b[1]) * (a.Y() - b[1]) +
                     (a.Z() - b[2]) * (a.Z() - b[2]));
}

// Largest distance between a face's surface and ours over a grid of our
// domain (OCCT keeps the parameters of entity 128).
double surface_gap(const TopoDS_Shape &face, const projcurve_surface *s)
{
    Handle(Geom_Surface) g = BRep_Tool::Surface(TopoDS::Face(face));
    double d[4], gap = 0.0;
    CHECK_OK(projcurve_surface_domain(ctx, s, d));
    for (int i = 0; i < kSamples; ++i)
        for (int j = 0; j < kSamples; ++j) {
            const double u = d[0] + (d[1] - d[0]) * i / (kSamples - 1.0);
            const double v = d[2] + (d[3] - d[2]) * j / (kSamples - 1.0);
            double p[3];
            CHECK_OK(projcurve_surface_eval(ctx, s, u, v, 0, p));
            gap = std::max(gap, distance(g->Value(u, v), p));
        }
    return gap;
}

double curve_gap(const TopoDS_Shape &edge, const projcurve_curve *c)
{
    Standard_Real first = 0.0, last = 0.0;
    Handle(Geom_Curve) g = BRep_Tool::Curve(TopoDS::Edge(edge), first, last);
    if (g.IsNull())
        return HUGE_VAL;
    double t0, t1, gap = 0.0;
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    for (int i = 0; i < kSamples; ++i) {
        const double t = t0 + (t1 - t0) * i / (kSamples - 1.0);
        double p[3];
        CHECK_OK(projcurve_curve_eval(ctx, c, t, 0, p));
        gap = std::max(gap, distance(g->Value(t), p));
    }
    return gap;
}

// Every surface and curve written has a face / an edge in OCCT's transfer
// of path that matches it; scale is the size of the geometry.
void check_same_geometry(const std::string &path, const std::vector<const projcurve_surface *> &ss,
                         const std::vector<const projcurve_curve *> &cs, double scale)
{
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        return; // reported by check_file
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    for (const projcurve_surface *s : ss) {
        double best = HUGE_VAL;
        for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
            best = std::min(best, surface_gap(e.Current(), s));
        if (!(best <= kAgreeRel * scale))
            pc_test_fail_at(__FILE__, __LINE__, "%s: no OCCT face within %g of a surface (%g)",
                            path.c_str(), kAgreeRel * scale, best);
        ++pc_test_checks;
    }
    for (const projcurve_curve *c : cs) {
        double best = HUGE_VAL;
        for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next())
            best = std::min(best, curve_gap(e.Current(), c));
        if (!(best <= kAgreeRel * scale))
            pc_test_fail_at(__FILE__, __LINE__, "%s: no OCCT edge within %g of the curve (%g)",
                            path.c_str(), kAgreeRel * scale, best);
        ++pc_test_checks;
    }
}

// (u, v) at s in [0, 1] of a piece's pcurve: a Bezier curve of degree
// `degree` with (u, v) control points, by de Casteljau.
void bezier_uv(int degree, const double *uv_ctrl, double s, double uv[2])
{
    double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
    std::copy(uv_ctrl, uv_ctrl + 2 * (degree + 1), w);
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i <= degree - r; ++i)
            for (int k = 0; k < 2; ++k)
                w[2 * i + k] = (1.0 - s) * w[2 * i + k] + s * w[2 * (i + 1) + k];
    uv[0] = w[0];
    uv[1] = w[1];
}

// Samples per composed piece (its ends included) when comparing a written
// curve on surface with the branch it came from.
constexpr int kPieceSamples = 5;

// Every curve on surface (142) of path, in file order, is branch i of r on
// s: OCCT's 3D curve and its surface composed with its pcurve, both built
// by IGESToBRep from the entities, are compared with the branch's curve
// and with S at the (u, v) of the branch's pieces.
void check_curves_on_surface(const std::string &path, const projcurve_surface *s,
                             const projcurve_result *r, double scale)
{
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        return; // reported by check_file
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    std::vector<Handle(IGESGeom_CurveOnSurface)> cos;
    for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
        Handle(IGESGeom_CurveOnSurface) c =
            Handle(IGESGeom_CurveOnSurface)::DownCast(model->Entity(i));
        if (!c.IsNull())
            cos.push_back(c);
    }
    const size_t n_branches = projcurve_result_branch_count(r);
    CHECK(cos.size() == n_branches);
    IGESToBRep_BasicCurve curves;
    IGESToBRep_BasicSurface surfaces;
    for (size_t b = 0; b < std::min(cos.size(), n_branches); ++b) {
        Handle(IGESGeom_BSplineSurface) gs =
            Handle(IGESGeom_BSplineSurface)::DownCast(cos[b]->Surface());
        Handle(IGESGeom_BSplineCurve) g2 =
            Handle(IGESGeom_BSplineCurve)::DownCast(cos[b]->CurveUV());
        Handle(IGESGeom_BSplineCurve) g3 =
            Handle(IGESGeom_BSplineCurve)::DownCast(cos[b]->Curve3D());
        CHECK(!gs.IsNull() && !g2.IsNull() && !g3.IsNull());
        if (gs.IsNull() || g2.IsNull() || g3.IsNull())
            continue;
        Handle(Geom_Surface) occt_s = surfaces.TransferBSplineSurface(gs);
        Handle(Geom2d_Curve) occt_p = curves.Transfer2dBSplineCurve(g2);
        Handle(Geom_Curve) occt_c = curves.TransferBSplineCurve(g3);
        CHECK(!occt_s.IsNull() && !occt_p.IsNull() && !occt_c.IsNull());
        if (occt_s.IsNull() || occt_p.IsNull() || occt_c.IsNull())
            continue;
        projcurve_curve *ours = nullptr;
        size_t n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(ctx, r, b, nullptr, nullptr, nullptr, nullptr,
                                              &n_pieces));
        CHECK_OK(projcurve_result_branch_curve(ctx, r, b, &ours));
        CHECK(n_pieces > 0);
        double curve_gap = 0.0, on_surface_gap = 0.0, worst_t = 0.0;
        for (size_t k = 0; ours != nullptr && k < n_pieces; ++k) {
            int degree = 0;
            double range[2], uv_ctrl[2 * PROJCURVE_MAX_PCURVE_POINTS];
            CHECK_OK(projcurve_result_piece(ctx, r, b, k, nullptr, nullptr, nullptr, range,
                                            nullptr));
            CHECK_OK(projcurve_result_piece_pcurve(ctx, r, b, k, &degree, uv_ctrl));
            for (int i = 0; i < kPieceSamples; ++i) {
                const double f = i / (kPieceSamples - 1.0);
                const double t = range[0] + f * (range[1] - range[0]);
                double p[3], uv[2], q[3];
                CHECK_OK(projcurve_curve_eval(ctx, ours, t, 0, p));
                const double gap_c = distance(occt_c->Value(t), p);
                bezier_uv(degree, uv_ctrl, f, uv);
                CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, q));
                const gp_Pnt2d puv = occt_p->Value(t);
                const double gap_s = distance(occt_s->Value(puv.X(), puv.Y()), q);
                if (std::max(gap_c, gap_s) > std::max(curve_gap, on_surface_gap))
                    worst_t = t;
                curve_gap = std::max(curve_gap, gap_c);
                on_surface_gap = std::max(on_surface_gap, gap_s);
            }
        }
        if (!(curve_gap <= kAgreeRel * scale) || !(on_surface_gap <= kAgreeRel * scale))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: 142 #%zu: OCCT's 3D curve is %g from the branch's, its S(p(t)) "
                            "%g from ours (worst at t = %.17g; allowed %g)",
                            path.c_str(), b, curve_gap, on_surface_gap, worst_t,
                            kAgreeRel * scale);
        ++pc_test_checks;
        projcurve_curve_destroy(ours);
    }
}

// The compact forms (projcurve_iges_writer_add_result) as Open CASCADE
// reads them: each 142's 3D curve is a Geom_BSplineCurve of degree at most
// Geom_BSplineCurve::MaxDegree() (25) with the poles of our compact curve,
// and agrees with it, and S at OCCT's pcurve agrees with S at ours, at
// kPieceSamples parameters per knot span.
void check_compact_curves(const std::string &path, const projcurve_surface *s,
                          const projcurve_result *r, double scale)
{
    IGESControl_Reader reader;
    CHECK(reader.ReadFile(path.c_str()) == IFSelect_RetDone);
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    std::vector<Handle(IGESGeom_CurveOnSurface)> cos;
    for (Standard_Integer i = 1; !model.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(IGESGeom_CurveOnSurface) c =
            Handle(IGESGeom_CurveOnSurface)::DownCast(model->Entity(i));
        if (!c.IsNull())
            cos.push_back(c);
    }
    CHECK(cos.size() == projcurve_result_branch_count(r));
    IGESToBRep_BasicCurve curves;
    IGESToBRep_BasicSurface surfaces;
    for (size_t b = 0; b < cos.size() && b < projcurve_result_branch_count(r); ++b) {
        Handle(IGESGeom_BSplineSurface) gs =
            Handle(IGESGeom_BSplineSurface)::DownCast(cos[b]->Surface());
        Handle(IGESGeom_BSplineCurve) g2 =
            Handle(IGESGeom_BSplineCurve)::DownCast(cos[b]->CurveUV());
        Handle(IGESGeom_BSplineCurve) g3 =
            Handle(IGESGeom_BSplineCurve)::DownCast(cos[b]->Curve3D());
        CHECK(!gs.IsNull() && !g2.IsNull() && !g3.IsNull());
        if (gs.IsNull() || g2.IsNull() || g3.IsNull())
            continue;
        Handle(Geom_Surface) occt_s = surfaces.TransferBSplineSurface(gs);
        Handle(Geom2d_Curve) occt_p = curves.Transfer2dBSplineCurve(g2);
        Handle(Geom_BSplineCurve) occt_c =
            Handle(Geom_BSplineCurve)::DownCast(curves.TransferBSplineCurve(g3));
        CHECK(!occt_s.IsNull() && !occt_p.IsNull() && !occt_c.IsNull());
        projcurve_curve *ours = nullptr, *pcurve = nullptr;
        CHECK_OK(projcurve_result_branch_compact_curve(ctx, r, b, &ours));
        CHECK_OK(projcurve_result_branch_compact_pcurve(ctx, r, b, &pcurve));
        if (occt_s.IsNull() || occt_p.IsNull() || occt_c.IsNull() || !ours || !pcurve) {
            projcurve_curve_destroy(ours);
            projcurve_curve_destroy(pcurve);
            continue;
        }
        int degree = 0;
        size_t n_poles = 0, n_knots = 0;
        CHECK_OK(projcurve_curve_nurbs_info(ctx, ours, &degree, &n_poles, &n_knots, nullptr));
        CHECK(occt_c->Degree() == degree && occt_c->Degree() <= Geom_BSplineCurve::MaxDegree());
        CHECK(occt_c->NbPoles() == static_cast<int>(n_poles));
        std::vector<double> knots(n_knots);
        CHECK_OK(projcurve_curve_nurbs_data(ctx, ours, nullptr, nullptr, knots.data()));
        double gap_c = 0.0, gap_s = 0.0;
        for (size_t k = static_cast<size_t>(degree); k < n_poles; ++k)
            for (int i = 0; i < kPieceSamples; ++i) {
                const double t = knots[k] + i / (kPieceSamples - 1.0) * (knots[k + 1] - knots[k]);
                double p[3], uv[3], q[3];
                CHECK_OK(projcurve_curve_eval(ctx, ours, t, 0, p));
                CHECK_OK(projcurve_curve_eval(ctx, pcurve, t, 0, uv));
                CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, q));
                const gp_Pnt2d puv = occt_p->Value(t);
                gap_c = std::max(gap_c, distance(occt_c->Value(t), p));
                gap_s = std::max(gap_s, distance(occt_s->Value(puv.X(), puv.Y()), q));
            }
        if (!(gap_c <= kAgreeRel * scale) || !(gap_s <= kAgreeRel * scale))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: 142 #%zu: OCCT's compact 3D curve is %g from ours, its "
                            "S(p(t)) %g from ours (allowed %g)",
                            path.c_str(), b, gap_c, gap_s, kAgreeRel * scale);
        ++pc_test_checks;
        std::printf("%s: branch %zu: OCCT reads the compact curve of degree %d with %d poles\n",
                    path.c_str(), b, occt_c->Degree(), occt_c->NbPoles());
        projcurve_curve_destroy(ours);
        projcurve_curve_destroy(pcurve);
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

// One branch along v = 0.5 of the plane, composed as one line piece.
projcurve_result *line_result()
{
    projcurve_result *r = nullptr;
    pc_branch *b = nullptr;
    CHECK_OK(pc_result_create(ctx, 3, &r));
    CHECK_OK(pc_result_add_branch(ctx, r, &b));
    for (int i = 0; i <= 8; ++i) {
        const double t = i / 8.0, p[3] = {t, 0.1 + 0.8 * t, 0.5};
        CHECK_OK(pc_branch_add_point(ctx, b, 3, p));
    }
    const double uv[4] = {0.1, 0.5, 0.9, 0.5}, ctrl[6] = {1, 5, 0.5, 9, 5, 0.5};
    CHECK_OK(pc_branch_add_piece(ctx, b, 1, 0.0, 1.0, uv, ctrl, nullptr));
    return r;
}

// Projects the case's curve onto its surface along dir, writes the result
// and checks OCCT sees a 126 pair and a 142 per branch.
void check_case(const std::string &dir_out, const char *name, const double dir[3])
{
    projcurve_model *in = nullptr;
    const std::string path = std::string("cases/") + name + ".igs";
    if (projcurve_model_read_file(ctx, pc_test_data_path(path.c_str()), &in) != PROJCURVE_OK) {
        std::printf("%s not available: skipped\n", path.c_str());
        return;
    }
    const projcurve_surface *s = projcurve_model_surface(in, 0);
    projcurve_result *r = nullptr;
    CHECK_OK(projcurve_project_directional(ctx, s, projcurve_model_curve(in, 0), dir, nullptr, &r));
    const int branches = static_cast<int>(projcurve_result_branch_count(r));
    CHECK(branches > 0);
    projcurve_iges_writer *w = nullptr;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, w, s, r));
    const std::string out = dir_out + "/occt_" + name + ".igs";
    CHECK_OK(projcurve_iges_writer_write(ctx, w, out.c_str()));
    projcurve_iges_writer_destroy(w);
    check_file(out, {{128, 1}, {126, 2 * branches}, {142, branches}}, 0, branches);
    double d[4];
    CHECK_OK(projcurve_surface_domain(ctx, s, d));
    double corners[2][3];
    CHECK_OK(projcurve_surface_eval(ctx, s, d[0], d[2], 0, corners[0]));
    CHECK_OK(projcurve_surface_eval(ctx, s, d[1], d[3], 0, corners[1]));
    const double size = std::max(1.0, std::hypot(corners[1][0] - corners[0][0],
                                                 corners[1][1] - corners[0][1],
                                                 corners[1][2] - corners[0][2]));
    check_curves_on_surface(out, s, r, size);
    // the default output: the compact forms
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, s, r));
    const std::string compact = dir_out + "/occt_compact_" + name + ".igs";
    CHECK_OK(projcurve_iges_writer_write(ctx, w, compact.c_str()));
    projcurve_iges_writer_destroy(w);
    check_file(compact, {{128, 1}, {126, 2 * branches}, {142, branches}}, 0, branches);
    check_compact_curves(compact, s, r, size);
    projcurve_result_destroy(r);
    projcurve_model_destroy(in);
}

// A line projected orthogonally around a closed shape (u = 0 and u = 1 on
// the half-plane y = 0, x > 0; the torus's v seam on its outer equator),
// written as IGES; OCCT reads one 142 per seam segment, each pcurve
// inside its surface's bounds.
//
// The result r onto s written by projcurve_iges_writer_add_result and read
// back: `segments` curves on surface, each checked as above.
void check_written_seams(const std::string &path, const projcurve_surface *s,
                         const projcurve_result *r, int segments)
{
    projcurve_iges_writer *w = nullptr;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path.c_str()));
    projcurve_iges_writer_destroy(w);
    check_file(path, {{128, 1}, {126, 2 * segments}, {142, segments}}, 0, segments);
    double box[6];
    CHECK_OK(projcurve_surface_bounds(ctx, s, box));
    const double size = std::max({box[3] - box[0], box[4] - box[1], box[5] - box[2]});
    const double gap_allowed = 2.0 * r->stats.tol_distance + kAgreeRel * size;
    IGESControl_Reader reader;
    CHECK(reader.ReadFile(path.c_str()) == IFSelect_RetDone);
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    IGESToBRep_BasicCurve curves;
    IGESToBRep_BasicSurface surfaces;
    int seen_cos = 0;
    for (Standard_Integer i = 1; !model.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(IGESGeom_CurveOnSurface) cos =
            Handle(IGESGeom_CurveOnSurface)::DownCast(model->Entity(i));
        if (cos.IsNull())
            continue;
        ++seen_cos;
        Handle(IGESGeom_BSplineSurface) gs =
            Handle(IGESGeom_BSplineSurface)::DownCast(cos->Surface());
        Handle(IGESGeom_BSplineCurve) g2 = Handle(IGESGeom_BSplineCurve)::DownCast(cos->CurveUV());
        Handle(IGESGeom_BSplineCurve) g3 = Handle(IGESGeom_BSplineCurve)::DownCast(cos->Curve3D());
        CHECK(!gs.IsNull() && !g2.IsNull() && !g3.IsNull());
        if (gs.IsNull() || g2.IsNull() || g3.IsNull())
            continue;
        Handle(Geom_Surface) occt_s = surfaces.TransferBSplineSurface(gs);
        Handle(Geom2d_Curve) occt_p = curves.Transfer2dBSplineCurve(g2);
        Handle(Geom_Curve) occt_c = curves.TransferBSplineCurve(g3);
        CHECK(!occt_s.IsNull() && !occt_p.IsNull() && !occt_c.IsNull());
        if (occt_s.IsNull() || occt_p.IsNull() || occt_c.IsNull())
            continue;
        double u1, u2, v1, v2;
        occt_s->Bounds(u1, u2, v1, v2);
        const double t0 = occt_p->FirstParameter(), t1 = occt_p->LastParameter();
        double outside = 0.0, gap = 0.0;
        for (int k = 0; k <= 200; ++k) {
            const double t = t0 + (t1 - t0) * k / 200.0;
            const gp_Pnt2d uv = occt_p->Value(t);
            outside = std::max({outside, (u1 - uv.X()) / (u2 - u1), (uv.X() - u2) / (u2 - u1),
                                (v1 - uv.Y()) / (v2 - v1), (uv.Y() - v2) / (v2 - v1)});
            gap = std::max(gap, occt_s->Value(uv.X(), uv.Y()).Distance(occt_c->Value(t)));
        }
        if (!(outside <= kAgreeRel) || !(gap <= gap_allowed))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: 142 #%d: its pcurve leaves the surface's bounds by %g of the "
                            "width, S(p(t)) is %g from its 3D curve (allowed %g)",
                            path.c_str(), seen_cos, outside, gap, gap_allowed);
        ++pc_test_checks;
        std::printf("%s: 142 #%d over [%g, %g]: inside the bounds, forms %g apart\n",
                    path.c_str(), seen_cos, t0, t1, gap);
    }
    CHECK(seen_cos == segments);
}

void check_seam_case(const std::string &dir_out, const char *name, pc_shape_surface shape,
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
    check_written_seams(dir_out + "/occt_seams_" + name + ".igs", s, r,
                        static_cast<int>(r->n_branches + jumps));
    projcurve_result_destroy(r);
    projcurve_surface_destroy(s);
}

// The face pieces of a B-rep case of tests/data/cases-brep projected from
// its eye (projcurve_project_shape), each face's result written with
// projcurve_iges_writer_add_result on the face's surface: a piece that
// crosses its face's seam has its jumps (projcurve_result_branch_seam_count)
// and is written as one 142 per seam segment, each pcurve inside the
// surface's bounds. `jumps` is the count the case must give.
void check_face_seam_case(const std::string &dir_out, const char *name, const char *model_file,
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
        check_written_seams(dir_out + "/occt_face_seams_" + name + "_" + std::to_string(fi) +
                                ".igs",
                            s, fr, static_cast<int>(projcurve_result_branch_count(fr) + face_jumps));
    }
    CHECK(seen == jumps);
    std::printf("%s: %zu seam jump(s) over its face pieces\n", name, seen);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(o);
    projcurve_model_destroy(curves);
    projcurve_model_destroy(model);
}

} // namespace

// occt_iges_check --file PATH N: a file written elsewhere (the command's
// -o out.igs of tests/cli/check_faces.py): OCCT reads it, sees N curves on
// surface (142) and transfers something.
int check_given_file(const std::string &path, int n)
{
    IGESControl_Reader reader;
    const IFSelect_ReturnStatus st = reader.ReadFile(path.c_str());
    CHECK(st == IFSelect_RetDone);
    if (st != IFSelect_RetDone)
        return pc_test_finish("occt_iges_check --file");
    const std::map<int, int> got = occt_entity_types(reader);
    const auto it = got.find(142);
    const int found = it == got.end() ? 0 : it->second;
    if (found != n)
        pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT sees %d curves on surface (142), expected %d",
                        path.c_str(), found, n);
    ++pc_test_checks;
    CHECK(reader.TransferRoots() >= 1);
    std::printf("%s: %d curves on surface\n", path.c_str(), found);
    return pc_test_finish("occt_iges_check --file");
}

// The member counts of "4,5,1" (an empty list for "").
std::vector<int> count_list(const std::string &text)
{
    std::vector<int> out;
    size_t pos = 0;
    while (pos < text.size() && out.size() < 100000) {
        const size_t comma = text.find(',', pos);
        const std::string item = text.substr(pos, comma == std::string::npos ? comma : comma - pos);
        out.push_back(std::atoi(item.c_str()));
        if (comma == std::string::npos)
            break;
        pos = comma + 1;
    }
    return out;
}

std::string list_text(const std::vector<int> &v)
{
    std::string s;
    for (size_t i = 0; i < v.size(); ++i)
        s += (i ? "," : "") + std::to_string(v[i]);
    return s;
}

// occt_iges_check --composites PATH M1,M2,...: a file with the composite
// curves of projcurve_iges_writer_add_shape_result (the command's --faces
// -o out.igs): OCCT finds one 102 per connected curve, in file order with
// M1, M2, ... members, and transfers at least one edge per member.
void check_composites(const std::string &path, const std::vector<int> &members)
{
    IGESControl_Reader reader;
    const IFSelect_ReturnStatus st = reader.ReadFile(path.c_str());
    CHECK(st == IFSelect_RetDone);
    if (st != IFSelect_RetDone)
        return;
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    std::vector<int> got;
    int total = 0;
    for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
        Handle(IGESGeom_CompositeCurve) cc = Handle(IGESGeom_CompositeCurve)::DownCast(model->Entity(i));
        if (!cc.IsNull())
            got.push_back(cc->NbCurves());
    }
    for (int m : members)
        total += m;
    if (got != members)
        pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT sees composite curves (102) of %s members, "
                        "expected %s", path.c_str(), list_text(got).c_str(),
                        list_text(members).c_str());
    ++pc_test_checks;
    CHECK(reader.TransferRoots() >= 1);
    const int edges = count_shapes(reader.OneShape(), TopAbs_EDGE);
    if (edges < total)
        pc_test_fail_at(__FILE__, __LINE__, "%s: OCCT transfers %d edges for %d members",
                        path.c_str(), edges, total);
    ++pc_test_checks;
    std::printf("%s: %zu composite curves (%s members), %d edges\n", path.c_str(), got.size(),
                list_text(got).c_str(), edges);
}

// The U curve of shell_2x2_bspline_oblique onto the 2x2 shell (one
// connected curve of four face pieces), written with
// projcurve_iges_writer_add_shape_result: OCCT sees one 102 of four members.
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
    projcurve_iges_writer *w = nullptr;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_shape_result(ctx, w, r));
    const std::string path = dir + "/occt_shape_result.igs";
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path.c_str()));
    projcurve_iges_writer_destroy(w);
    check_composites(path, {4});
    projcurve_shape_result_destroy(r);
    projcurve_model_destroy(shell);
    projcurve_model_destroy(curves);
}

int main(int argc, char **argv)
{
    if (argc == 4 && std::string(argv[1]) == "--file")
        return check_given_file(argv[2], std::atoi(argv[3]));
    if (argc == 4 && std::string(argv[1]) == "--composites") {
        check_composites(argv[2], count_list(argv[3]));
        return pc_test_finish("occt_iges_check --composites");
    }
    const std::string dir = argc > 1 ? argv[1] : ".";
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_surface *s1 = plane(), *s2 = quarter_cylinder();
    projcurve_curve *c = cubic();

    projcurve_iges_writer *w = nullptr;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, s1));
    CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, s2));
    CHECK_OK(projcurve_iges_writer_add_curve(ctx, w, c));
    const std::string geometry = dir + "/occt_geometry.igs";
    CHECK_OK(projcurve_iges_writer_write(ctx, w, geometry.c_str()));
    projcurve_iges_writer_destroy(w);
    check_file(geometry, {{128, 2}, {126, 1}}, 2, 1);
    check_same_geometry(geometry, {s1, s2}, {c}, 10.0);

    projcurve_result *r = line_result();
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, s1, r));
    const std::string projected = dir + "/occt_result.igs";
    CHECK_OK(projcurve_iges_writer_write(ctx, w, projected.c_str()));
    projcurve_iges_writer_destroy(w);
    // The 142 is the only root (it references the rest), so OCCT transfers
    // it as an edge on the surface; the surface is there as entity 128.
    check_file(projected, {{128, 1}, {126, 2}, {142, 1}}, 0, 1);
    check_curves_on_surface(projected, s1, r, 10.0);

    const double minus_x[3] = {-1.0, 0.0, 0.0}, minus_z[3] = {0.0, 0.0, -1.0};
    check_case(dir, "song_yong_example1", minus_x);
    check_case(dir, "fold_c_sheet_jump", minus_z);
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

    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s1);
    projcurve_surface_destroy(s2);
    projcurve_context_destroy(ctx);
    return pc_test_finish("occt_iges_check");
}
