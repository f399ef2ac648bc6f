/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench occt: the shared cases through Open CASCADE, side by side
 * with libprojcurve in the same run.
 *
 * Directional cases go through BRepProj_Projection (the curve as an edge,
 * the surface as a face), orthogonal ones through GeomProjLib::Project. Both
 * sides get the very same NURBS geometry (our parsed data rebuilt as
 * Geom_BSplineSurface / Geom_BSplineCurve), both results are measured against
 * the same independent oracle (exact.h, deviation.h), and the time ratio
 * ours / theirs is the median of ratios taken run by run.
 */
#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepProj_Projection.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <GeomProjLib.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Dir.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

extern "C" {
#include "bench.h"
#include "cases.h"
#include "deviation.h"
#include "exact.h"
#include "json.h"
#include "measure.h"
#include "occt_geometry.h"
#include "svg.h"
}

namespace {

const int OCCT_REPS = 5;
const double OCCT_MIN_RUN_S = 0.02;
/* Matched-accuracy runs ask for no less than this fraction of the model
 * size (Open CASCADE can be exact to rounding on simple shapes). */
const double MATCH_TOL_FLOOR = 1e-10;
/* The control points our results may join into one curve to be measured. */
const size_t MEASURE_CONTROL_POINTS = 100000000;
/* Quick runs (CI) take only these. */
const char *const quick_cases[] = {"song_yong_example1", "ortho_nurbs_half_cylinder"};

/* Distinct knots and multiplicities of a clamped knot vector. */
void split_knots(const double *k, size_t n, std::vector<double> &values, std::vector<int> &mults)
{
    for (size_t i = 0; i < n; ++i) {
        if (!values.empty() && k[i] == values.back()) {
            ++mults.back();
        } else {
            values.push_back(k[i]);
            mults.push_back(1);
        }
    }
}

void fill_array(const std::vector<double> &v, TColStd_Array1OfReal &a)
{
    for (size_t i = 0; i < v.size(); ++i)
        a.SetValue(static_cast<int>(i) + 1, v[i]);
}

void fill_array(const std::vector<int> &v, TColStd_Array1OfInteger &a)
{
    for (size_t i = 0; i < v.size(); ++i)
        a.SetValue(static_cast<int>(i) + 1, v[i]);
}

Handle(Geom_BSplineSurface) make_surface(const pcb_nurbs_data &d)
{
    std::vector<double> ku, kv;
    std::vector<int> mu, mv;
    split_knots(d.knots_u, d.n_u + static_cast<size_t>(d.deg_u) + 1, ku, mu);
    split_knots(d.knots_v, d.n_v + static_cast<size_t>(d.deg_v) + 1, kv, mv);
    const int nu = static_cast<int>(d.n_u), nv = static_cast<int>(d.n_v);
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const size_t idx = static_cast<size_t>(j) * d.n_u + static_cast<size_t>(i);
            poles.SetValue(i + 1, j + 1,
                           gp_Pnt(d.ctrl[3 * idx], d.ctrl[3 * idx + 1], d.ctrl[3 * idx + 2]));
            weights.SetValue(i + 1, j + 1, d.weights[idx]);
        }
    TColStd_Array1OfReal aku(1, static_cast<int>(ku.size())), akv(1, static_cast<int>(kv.size()));
    TColStd_Array1OfInteger amu(1, static_cast<int>(mu.size())),
        amv(1, static_cast<int>(mv.size()));
    fill_array(ku, aku);
    fill_array(kv, akv);
    fill_array(mu, amu);
    fill_array(mv, amv);
    if (d.rational)
        return new Geom_BSplineSurface(poles, weights, aku, akv, amu, amv, d.deg_u, d.deg_v);
    return new Geom_BSplineSurface(poles, aku, akv, amu, amv, d.deg_u, d.deg_v);
}

Handle(Geom_BSplineCurve) make_curve(const pcb_nurbs_data &d)
{
    std::vector<double> k;
    std::vector<int> m;
    split_knots(d.knots_u, d.n_u + static_cast<size_t>(d.deg_u) + 1, k, m);
    const int n = static_cast<int>(d.n_u);
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) {
        const size_t s = static_cast<size_t>(i);
        poles.SetValue(i + 1, gp_Pnt(d.ctrl[3 * s], d.ctrl[3 * s + 1], d.ctrl[3 * s + 2]));
        weights.SetValue(i + 1, d.weights[s]);
    }
    TColStd_Array1OfReal ak(1, static_cast<int>(k.size()));
    TColStd_Array1OfInteger am(1, static_cast<int>(m.size()));
    fill_array(k, ak);
    fill_array(m, am);
    if (d.rational)
        return new Geom_BSplineCurve(poles, weights, ak, am, d.deg_u);
    return new Geom_BSplineCurve(poles, ak, am, d.deg_u);
}

/* One case on the Open CASCADE side. */
struct occt_case {
    const pcb_case *c = nullptr;
    Handle(Geom_BSplineSurface) surface;
    Handle(Geom_BSplineCurve) curve;
    TopoDS_Face face;
    TopoDS_Edge edge;
    /* The last result: its edges (for the deviation) and branch count. */
    std::vector<TopoDS_Edge> edges;
    std::vector<BRepAdaptor_Curve> adaptors;
    int branches = 0;
    std::string error;
    std::string note;
};

/* Runs the projection once, keeping the result in oc. Returns false (with
 * oc.error) when Open CASCADE fails or throws. */
bool occt_project(occt_case &oc, bool keep)
{
    try {
        if (oc.c->orthogonal) {
            Handle(Geom_Curve) r = GeomProjLib::Project(oc.curve, oc.surface);
            if (keep) {
                oc.edges.clear();
                oc.branches = r.IsNull() ? 0 : 1;
                if (!r.IsNull())
                    oc.edges.push_back(BRepBuilderAPI_MakeEdge(r).Edge());
            }
            return true;
        }
        const gp_Dir dir(oc.c->dir[0], oc.c->dir[1], oc.c->dir[2]);
        BRepProj_Projection proj(oc.edge, oc.face, dir);
        if (keep) {
            oc.edges.clear();
            oc.branches = 0;
            /* Not done = an empty section: an empty result, which the
             * deviation check judges like any other. */
            if (!proj.IsDone()) {
                oc.note = "BRepProj_Projection: empty section";
                return true;
            }
            for (proj.Init(); proj.More(); proj.Next())
                ++oc.branches;
            for (TopExp_Explorer e(proj.Shape(), TopAbs_EDGE); e.More(); e.Next())
                oc.edges.push_back(TopoDS::Edge(e.Current()));
        }
        return true;
    } catch (const Standard_Failure &f) {
        oc.error = std::string("Open CASCADE: ") + f.GetMessageString();
    } catch (...) {
        oc.error = "Open CASCADE threw";
    }
    return false;
}

int occt_work(void *user, size_t n)
{
    occt_case *oc = static_cast<occt_case *>(user);
    for (size_t i = 0; i < n; ++i)
        if (!occt_project(*oc, false))
            return 1;
    return 0;
}

struct ours_work_data {
    const pcb_case *c;
    const projcurve_options *opts;
};

int ours_work(void *user, size_t n)
{
    const ours_work_data *w = static_cast<const ours_work_data *>(user);
    for (size_t i = 0; i < n; ++i) {
        projcurve_result *r = nullptr;
        const projcurve_status st = pcb_case_project(nullptr, w->c, w->opts, &r);
        projcurve_result_destroy(r);
        if (st != PROJCURVE_OK)
            return 1;
    }
    return 0;
}

int occt_domain(void *user, size_t i, double range[2])
{
    occt_case *oc = static_cast<occt_case *>(user);
    range[0] = oc->adaptors[i].FirstParameter();
    range[1] = oc->adaptors[i].LastParameter();
    return std::isfinite(range[0]) && std::isfinite(range[1]) ? 0 : -1;
}

int occt_eval(void *user, size_t i, double s, double p[3])
{
    occt_case *oc = static_cast<occt_case *>(user);
    const gp_Pnt q = oc->adaptors[i].Value(s);
    p[0] = q.X();
    p[1] = q.Y();
    p[2] = q.Z();
    return 0;
}

/* One libprojcurve configuration measured against Open CASCADE. */
struct ours_run {
    double tol = NAN;       /* eps_D used */
    double ms = NAN;        /* median ms per projection */
    double occt_ms = NAN;   /* Open CASCADE, timed alternately with it */
    double ratio = NAN;     /* median of per-run ratios ours / occt */
    double dev = NAN;       /* measured deviation */
    double branches = NAN;
    /* The compact forms (src/fit/): poles over the branches, largest
     * degree, the 3D curves' measured deviation, the pcurves' poles. */
    double poles = NAN, degree = NAN, compact_dev = NAN, pcurve_poles = NAN;
};

struct row {
    std::string name, mode, status;
    ours_run at_case_tol;   /* the case's eps_D */
    ours_run matched;       /* eps_D = Open CASCADE's measured deviation */
    ours_run straight_at_case_tol, straight_matched; /* the same with straight pcurves */
    /* Ours at eps_D = Open CASCADE's deviation also where ours was the more
     * accurate at the case's eps_D: the compact poles at equal accuracy
     * (not timed). */
    ours_run poles_at_occt_dev;
    double occt_dev = NAN, occt_branches = NAN;
    double occt_poles = NAN, occt_degree = NAN; /* of its result's B-spline edges */
    /* The pair reported as ours / occt: `matched` when Open CASCADE is the
     * more accurate at the case tolerance, else `at_case_tol`. */
    const ours_run &reported() const
    {
        return std::isfinite(matched.ms) ? matched : at_case_tol;
    }
    const ours_run &straight_reported() const
    {
        return std::isfinite(straight_matched.ms) ? straight_matched : straight_at_case_tol;
    }
};

bool build_occt_side(occt_case &oc)
{
    pcb_nurbs_data sd, cd;
    if (pcb_surface_data(oc.c->surface, &sd) != 0) {
        oc.error = "surface data";
        return false;
    }
    if (pcb_curve_data(oc.c->curve, &cd) != 0) {
        pcb_nurbs_data_free(&sd);
        oc.error = "curve data (callback curve?)";
        return false;
    }
    bool ok = true;
    try {
        oc.surface = make_surface(sd);
        oc.curve = make_curve(cd);
        oc.face = BRepBuilderAPI_MakeFace(oc.surface, Precision::Confusion()).Face();
        oc.edge = BRepBuilderAPI_MakeEdge(oc.curve).Edge();
    } catch (const Standard_Failure &f) {
        oc.error = std::string("building geometry: ") + f.GetMessageString();
        ok = false;
    }
    pcb_nurbs_data_free(&sd);
    pcb_nurbs_data_free(&cd);
    return ok;
}

/* Our side once at the options' tolerance: branches and deviation. */
bool measure_ours(const pcb_case *c, const projcurve_options *opts, const pcb_exact &ex,
                  const pcb_sampling &sampling, ours_run &run, std::string &status)
{
    projcurve_context *ctx = nullptr;
    projcurve_result *res = nullptr;
    pcb_result_curves rc = {nullptr, 0}, compact = {nullptr, 0};
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    /* the joined pieces of a tight eps_D (straight pieces: ~20,000 of
     * degree p + q) pass the default limit; they are only sampled here */
    projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, MEASURE_CONTROL_POINTS);
    projcurve_status st = pcb_case_project(ctx, c, opts, &res);
    if (st == PROJCURVE_OK)
        st = pcb_result_curves_init(ctx, res, &rc);
    double pcurve_degree = 0.0;
    if (st == PROJCURVE_OK)
        st = pcb_result_compact_curves_init(ctx, res, &compact, &run.poles, &run.degree,
                                            &run.pcurve_poles, &pcurve_degree);
    bool ok = st == PROJCURVE_OK;
    if (!ok) {
        status = std::string("ours: ") + projcurve_status_string(st) + ": " +
                 projcurve_context_message(ctx);
    } else {
        run.branches = static_cast<double>(projcurve_result_branch_count(res));
        double pieces = 0.0;
        projcurve_result_stat(nullptr, res, PROJCURVE_STAT_PIECES, &pieces);
        const size_t per_curve = std::max(
            sampling.min_per_curve, static_cast<size_t>(pieces * double(sampling.per_piece)));
        const pcb_curve_set set = pcb_result_curve_set(&rc);
        pcb_deviation dev;
        ok = pcb_measure_deviation(&ex, &set, per_curve, &dev) == 0;
        run.dev = dev.hausdorff;
        const pcb_curve_set compact_set = pcb_result_curve_set(&compact);
        ok = ok && pcb_measure_deviation(&ex, &compact_set, sampling.min_per_curve, &dev) == 0;
        run.compact_dev = dev.hausdorff;
        if (!ok)
            status = "deviation of our result";
    }
    pcb_result_curves_free(&rc);
    pcb_result_curves_free(&compact);
    projcurve_result_destroy(res);
    projcurve_context_destroy(ctx);
    return ok;
}

bool measure_occt(occt_case &oc, const pcb_exact &ex, const pcb_sampling &sampling, row &r)
{
    if (!occt_project(oc, true))
        return false;
    r.occt_branches = oc.branches;
    r.occt_poles = r.occt_degree = 0.0;
    for (const TopoDS_Edge &e : oc.edges) {
        Standard_Real first = 0.0, last = 0.0;
        Handle(Geom_Curve) g = BRep_Tool::Curve(e, first, last);
        Handle(Geom_TrimmedCurve) trimmed = Handle(Geom_TrimmedCurve)::DownCast(g);
        if (!trimmed.IsNull())
            g = trimmed->BasisCurve();
        Handle(Geom_BSplineCurve) bs = Handle(Geom_BSplineCurve)::DownCast(g);
        if (bs.IsNull()) {
            r.occt_poles = NAN; /* not a B-spline: no pole count */
            continue;
        }
        r.occt_poles += bs->NbPoles();
        r.occt_degree = std::max(r.occt_degree, static_cast<double>(bs->Degree()));
    }
    oc.adaptors.clear();
    for (const TopoDS_Edge &e : oc.edges)
        oc.adaptors.emplace_back(e);
    pcb_curve_set set = {oc.adaptors.size(), occt_domain, occt_eval, &oc};
    pcb_deviation dev;
    /* Open CASCADE's edges are B-splines of a few dozen spans: the minimum
     * per curve samples them as densely as our pieces. */
    if (pcb_measure_deviation(&ex, &set, sampling.min_per_curve, &dev) != 0) {
        oc.error = "deviation of the Open CASCADE result";
        return false;
    }
    r.occt_dev = dev.hausdorff;
    return true;
}

bool is_quick_case(const char *name)
{
    for (const char *q : quick_cases)
        if (!std::strcmp(name, q))
            return true;
    return false;
}

/* Measures and times one configuration of ours (eps_D = tol) against
 * Open CASCADE (or alone when oc is null). */
bool run_ours(const pcb_args *args, const pcb_case *c, double tol, const pcb_exact &ex,
              occt_case *oc, ours_run &run, std::string &status)
{
    const pcb_sampling sampling = pcb_sampling_for(args->quick);
    projcurve_options *opts = nullptr;
    run.tol = tol;
    bool ok = pcb_ok(nullptr, pcb_case_options(nullptr, c, &opts), "occt: options") &&
              pcb_ok(nullptr,
                     projcurve_options_set_double(nullptr, opts, PROJCURVE_OPT_TOL_DISTANCE, tol),
                     "occt: tolerance") &&
              measure_ours(c, opts, ex, sampling, run, status);
    if (ok) {
        const pcb_timing timing = pcb_timing_for(args, OCCT_REPS, OCCT_MIN_RUN_S);
        ours_work_data w = {c, opts};
        pcb_pair pair;
        double s = NAN;
        if (oc && pcb_time_pair(&timing, ours_work, &w, occt_work, oc, &pair) == 0) {
            run.ms = 1e3 * pair.a_s;
            run.occt_ms = 1e3 * pair.b_s;
            run.ratio = pair.ratio;
        } else if (!oc && pcb_time_median(&timing, ours_work, &w, &s) == 0) {
            run.ms = 1e3 * s;
        } else {
            ok = false;
            status = "a timed run failed";
        }
    }
    projcurve_options_destroy(opts);
    return ok;
}

/* One case, both sides; false when our side failed (Open CASCADE failing
 * is a finding, recorded in the status, not a failure of the bench). */
bool run_case(const pcb_args *args, const pcb_case *c, row &r)
{
    r.name = c->name;
    r.mode = c->orthogonal ? "orthogonal" : "directional";
    if (c->error[0]) {
        r.status = std::string("not loaded: ") + c->error;
        return std::strncmp(c->name, "real_", 5) == 0;
    }
    pcb_exact ex;
    std::memset(&ex, 0, sizeof ex);
    const pcb_sampling sampling = pcb_sampling_for(args->quick);
    projcurve_context *ctx = nullptr;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    const projcurve_status st =
        pcb_exact_sample(ctx, &ex, c->surface, c->curve, c->orthogonal, c->dir,
                         sampling.exact_samples);
    if (st != PROJCURVE_OK) {
        r.status = std::string("exact samples: ") + projcurve_status_string(st) + ": " +
                   projcurve_context_message(ctx);
        projcurve_context_destroy(ctx);
        return false;
    }
    projcurve_context_destroy(ctx);
    occt_case oc;
    oc.c = c;
    const bool occt_ok = build_occt_side(oc) && measure_occt(oc, ex, sampling, r);
    r.status = occt_ok ? oc.note : oc.error;
    std::string ours_status;
    bool ok = run_ours(args, c, c->tol_dist, ex, occt_ok ? &oc : nullptr, r.at_case_tol,
                       ours_status);
    /* Equal accuracy: when Open CASCADE is the more accurate, run ours again
     * with eps_D set to its measured deviation (floored, so that a perfect
     * answer does not ask for an impossible tolerance). */
    const double floor_tol = MATCH_TOL_FLOOR * ex.size;
    /* Quick runs (CI) stop at the case tolerance: the matched run is the
     * same code with a finer eps_D, and the slowest part under sanitizers. */
    if (ok && occt_ok && !args->quick && std::isfinite(r.occt_dev) &&
        r.occt_dev < r.at_case_tol.dev)
        ok = run_ours(args, c, std::max(r.occt_dev, floor_tol), ex, &oc, r.matched, ours_status);
    /* The same two runs with straight pcurves (PROJCURVE_OPT_PCURVE_DEGREE 1). */
    pcb_case straight = *c;
    straight.pcurve_degree = 1;
    if (ok)
        ok = run_ours(args, &straight, c->tol_dist, ex, occt_ok ? &oc : nullptr,
                      r.straight_at_case_tol, ours_status);
    if (ok && occt_ok && !args->quick && std::isfinite(r.occt_dev) &&
        r.occt_dev < r.straight_at_case_tol.dev)
        ok = run_ours(args, &straight, std::max(r.occt_dev, floor_tol), ex, &oc, r.straight_matched,
                      ours_status);
    if (ok && occt_ok && !args->quick && std::isfinite(r.occt_dev)) {
        const pcb_sampling dense = pcb_sampling_for(0);
        projcurve_options *opts = nullptr;
        r.poles_at_occt_dev.tol = std::max(r.occt_dev, floor_tol);
        ok = pcb_case_options(nullptr, c, &opts) == PROJCURVE_OK &&
             projcurve_options_set_double(nullptr, opts, PROJCURVE_OPT_TOL_DISTANCE,
                                          r.poles_at_occt_dev.tol) == PROJCURVE_OK &&
             measure_ours(c, opts, ex, dense, r.poles_at_occt_dev, ours_status);
        projcurve_options_destroy(opts);
    }
    if (!ok)
        r.status = ours_status;
    pcb_exact_free(&ex);
    return ok;
}

void write_json(const pcb_args *args, const std::vector<row> &rows)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) != 0)
        return;
    pcb_json_object_begin(&j, nullptr);
    pcb_json_array_begin(&j, "cases");
    for (const row &r : rows) {
        pcb_json_object_begin(&j, nullptr);
        const ours_run &rep = r.reported();
        pcb_json_string(&j, "name", r.name.c_str());
        pcb_json_number(&j, "ours_ms", rep.ms);
        pcb_json_number(&j, "occt_ms", rep.occt_ms);
        pcb_json_number(&j, "ours_deviation", rep.dev);
        pcb_json_number(&j, "occt_deviation", r.occt_dev);
        pcb_json_number(&j, "ours_branches", rep.branches);
        pcb_json_number(&j, "occt_branches", r.occt_branches);
        pcb_json_number(&j, "ours_over_occt", rep.ratio);
        pcb_json_number(&j, "ours_tol_dist", rep.tol);
        pcb_json_string(&j, "mode", r.mode.c_str());
        pcb_json_number(&j, "case_tol_dist", r.at_case_tol.tol);
        pcb_json_number(&j, "case_tol_ours_ms", r.at_case_tol.ms);
        pcb_json_number(&j, "case_tol_occt_ms", r.at_case_tol.occt_ms);
        pcb_json_number(&j, "case_tol_ours_over_occt", r.at_case_tol.ratio);
        pcb_json_number(&j, "case_tol_ours_deviation", r.at_case_tol.dev);
        const ours_run &line = r.straight_reported();
        pcb_json_number(&j, "ours_poles", rep.poles);
        pcb_json_number(&j, "ours_pcurve_poles_timed", rep.pcurve_poles);
        pcb_json_number(&j, "case_tol_ours_poles", r.at_case_tol.poles);
        pcb_json_number(&j, "straight_ours_ms", line.ms);
        pcb_json_number(&j, "straight_occt_ms", line.occt_ms);
        pcb_json_number(&j, "straight_ours_over_occt", line.ratio);
        pcb_json_number(&j, "straight_ours_deviation", line.dev);
        pcb_json_number(&j, "straight_ours_tol_dist", line.tol);
        pcb_json_number(&j, "straight_ours_poles", line.poles);
        const ours_run &pol =
            std::isfinite(r.poles_at_occt_dev.tol) ? r.poles_at_occt_dev : r.reported();
        pcb_json_number(&j, "ours_compact_tol_dist", pol.tol);
        pcb_json_number(&j, "ours_compact_poles", pol.poles);
        pcb_json_number(&j, "ours_compact_degree", pol.degree);
        pcb_json_number(&j, "ours_compact_deviation", pol.compact_dev);
        pcb_json_number(&j, "ours_pcurve_poles", pol.pcurve_poles);
        pcb_json_number(&j, "occt_poles", r.occt_poles);
        pcb_json_number(&j, "occt_degree", r.occt_degree);
        pcb_json_number(&j, "poles_over_occt", pol.poles / r.occt_poles);
        pcb_json_string(&j, "status", r.status.empty() ? "ok" : r.status.c_str());
        pcb_json_object_end(&j);
    }
    pcb_json_array_end(&j);
    pcb_json_string(&j, "occt_version", OCC_VERSION_COMPLETE);
    pcb_json_int(&j, "quick", args->quick);
    pcb_json_object_end(&j);
    if (pcb_json_close(&j) != 0)
        std::fprintf(stderr, "occt: cannot write %s\n", args->json_path);
}

/* Deviation against time, one point per case and library. */
void write_svg(const pcb_args *args, const std::vector<row> &rows)
{
    if (!args->svg_path)
        return;
    std::vector<double> ours_t, ours_d, occt_t, occt_d;
    for (const row &r : rows) {
        ours_t.push_back(r.reported().ms);
        ours_d.push_back(r.reported().dev);
        occt_t.push_back(r.reported().occt_ms);
        occt_d.push_back(r.occt_dev);
    }
    const pcb_series series[2] = {{"libprojcurve", ours_t.data(), ours_d.data(), rows.size()},
                                  {"Open CASCADE", occt_t.data(), occt_d.data(), rows.size()}};
    const pcb_plot plot = {"cases: accuracy against time", "ms per projection",
                           "measured deviation", 1, 1, series, 2};
    if (pcb_svg_write(args->svg_path, &plot, 1) != 0)
        std::fprintf(stderr, "occt: cannot write %s\n", args->svg_path);
}

void print_run(const row &r, const char *mode, const ours_run &run, const char *status)
{
    std::printf("%-30s %-5s %9.2e %10.3f %10.3f %9.4f %11.3e %11.3e %5.0f %5.0f %6.0f %6.0f "
                "%7.0f %s\n",
                *mode ? r.name.c_str() : "", mode, run.tol, run.ms, run.occt_ms, run.ratio,
                run.dev, r.occt_dev, run.branches, r.occt_branches, run.poles, run.pcurve_poles,
                r.occt_poles, status);
}

}  // namespace

extern "C" int pcb_cmd_occt(const pcb_args *args)
{
    pcb_case_list list;
    const pcb_real_cases real = args->quick ? PCB_REAL_NONE : PCB_REAL_ALL;
    if (pcb_cases_load(args->data_dir, real, &list) != 0)
        return 2;
    pcb_print_banner("occt: libprojcurve and Open CASCADE " OCC_VERSION_COMPLETE
                     " on the same geometry",
                     args);
    std::printf("%-30s %-5s %9s %10s %10s %9s %11s %11s %5s %5s %6s %6s %7s %s\n", "case", "mode",
                "eps_D", "ours_ms", "occt_ms", "ours/occt", "ours_dev", "occt_dev", "br_us",
                "br_oc", "3d_pl", "uv_pl", "occt_pl", "status");
    std::vector<row> rows;
    int rc = 0;
    for (size_t i = 0; i < list.n; ++i) {
        const pcb_case *c = &list.items[i];
        if (args->quick && !is_quick_case(c->name))
            continue;
        row r;
        if (!run_case(args, c, r))
            rc = 1;
        print_run(r, c->orthogonal ? "orth" : "dir", r.at_case_tol,
                  r.status.empty() ? "ok" : r.status.c_str());
        if (std::isfinite(r.matched.ms))
            print_run(r, "", r.matched, "eps_D = Open CASCADE's deviation");
        print_run(r, "", r.straight_at_case_tol, "straight pcurves");
        if (std::isfinite(r.straight_matched.ms))
            print_run(r, "", r.straight_matched,
                      "straight pcurves, eps_D = Open CASCADE's deviation");
        std::fflush(stdout);
        rows.push_back(r);
    }
    std::printf("\ncompact results against Open CASCADE's, at equal accuracy (ours run with eps_D = "
                "Open CASCADE's measured deviation)\n");
    std::printf("%-30s %9s %11s %11s %8s %6s %8s %6s %8s %8s\n", "case", "eps_D", "ours_dev",
                "occt_dev", "3d_poles", "3d_deg", "occt_pl", "oc_deg", "poles/oc", "uv_poles");
    for (const row &r : rows) {
        const ours_run &rep =
            std::isfinite(r.poles_at_occt_dev.tol) ? r.poles_at_occt_dev : r.reported();
        std::printf("%-30s %9.2e %11.3e %11.3e %8.0f %6.0f %8.0f %6.0f %8.3f %8.0f\n",
                    r.name.c_str(), rep.tol, rep.compact_dev, r.occt_dev, rep.poles, rep.degree,
                    r.occt_poles, r.occt_degree, rep.poles / r.occt_poles, rep.pcurve_poles);
    }
    write_json(args, rows);
    write_svg(args, rows);
    pcb_cases_free(&list);
    return rc;
}
