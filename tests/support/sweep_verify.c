/* SPDX-License-Identifier: BSD-3-Clause */
#include "sweep_verify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "on_surface.h"

#define PI 3.14159265358979323846

/* A composed piece lies on S exactly up to rounding (on_surface.h: 1e-12 of
 * the size seen, on degree-30 pieces 2e-15); 1e-9 leaves room for the
 * rational, high-degree real surfaces and still sits far below any eps_D. */
#define ON_SURFACE_REL 1e-9
/* Rounding allowance of the point checks, relative to the surface size. */
#define ROUND_REL 1e-9
/* The library promises pieces within eps_D of the exact projection
 * (Hausdorff distance); the check measures that distance on samples and
 * allows 1e-3 of eps_D for the measure's own rounding and iteration
 * tolerances (golden section to 1e-17 of the bracket, Newton to rounding). */
#define HAUSDORFF_SLACK (1.0 + 1e-3)
/* Searches of the whole domain for t*, and golden-section searches of the
 * nearest exact point, per result: beyond, a sample that the local search
 * does not clear counts as failed unsearched (a result that many samples
 * fail has failed anyway; this bounds the verifier's time). */
#define MAX_SCANS 2000
/* Samples of each piece for the soundness check (intervals), and of each
 * piece's polyline for the coverage distance (refined by golden section). */
#define PIECE_INTERVALS 8
#define COVER_INTERVALS 32
/* The search for t*: a scan of the piece's t range (widened by half) and,
 * when that finds no t* within the tolerance, of the whole domain; each
 * local minimum of the scan is refined by golden section to the double
 * precision of t (80 iterations shrink the bracket by 0.618^80 ~ 1e-17). */
#define T_SCAN 16
#define T_GLOBAL_SCAN 512
#define T_MINIMA 8
/* The search for the nearest exact point: a scan of exact_distance (one
 * Newton each) over a t window, its local minima refined by golden section
 * (the distance need not be unimodal in t where S folds). */
#define T_EXACT_SCAN 32
#define GOLDEN_ITER 80
/* Newton for the exact foot point: quadratic convergence from within
 * ~eps_D; 40 iterations are far more than a converging start needs. */
#define NEWTON_ITER 40
/* The descent where Newton fails (foot_descent): steps, and halvings of
 * each (2^-60 of a step is below the rounding of u, v). */
#define DESCENT_ITER 200
#define DESCENT_HALVINGS 60
/* Descents per result: beyond, a failed Newton counts as no exact point
 * again (this bounds the verifier's time on results whose samples are
 * wrong by the hundred: ~7 s on the slowest linkrods.step case). */
#define MAX_DESCENTS 8000
/* The brute-force search of the nearest foot for a sample the scans do
 * not clear (dense_nearest_foot): t values over the piece's widened range,
 * local minima refined, and runs per result (each ~2e4 evaluations). */
#define DENSE_T 2048
#define DENSE_MINIMA 4
#define MAX_DENSE_SCANS 32
/* Units in the last place of u, v a converged Newton iterate may be off
 * (the rounding of the step and of the evaluation). */
#define ULP_SLACK 4.0
/* Feet per t of the orthogonal completeness check (the grid's local
 * minima, refined); more are not checked. */
#define MAX_FEET 16
#define MAX_HITS 64

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub3(const double a[3], const double b[3], double out[3])
{
    for (int c = 0; c < 3; ++c)
        out[c] = a[c] - b[c];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm3(const double a[3])
{
    return sqrt(dot3(a, a));
}

static double dist3(const double a[3], const double b[3])
{
    double d[3];
    sub3(a, b, d);
    return norm3(d);
}

/* One piece as the accessors give it, kept for the coverage check. */
typedef struct piece {
    int degree;
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS];
    double weights[PROJCURVE_MAX_PIECE_POINTS];
    double range[2];
    double poly[3 * (COVER_INTERVALS + 1)];
} piece;

typedef struct verifier {
    const pc_sweep_input *in;
    pc_sweep_report *rep;
    double t0, t1;
    double dir_unit[3];
    piece *pieces;
    size_t n_pieces;
    size_t scans; /* global t* and nearest_exact searches so far (MAX_SCANS) */
    size_t descents; /* foot_descent runs so far (MAX_DESCENTS) */
    size_t dense_scans; /* dense_nearest_foot runs so far (MAX_DENSE_SCANS) */
} verifier;

static void curve_point(const verifier *vf, double t, double out[3])
{
    double f[3] = {NAN, NAN, NAN};
    t = fmin(fmax(t, vf->t0), vf->t1);
    if (projcurve_curve_eval(NULL, vf->in->curve, t, 0, f) != PROJCURVE_OK)
        f[0] = f[1] = f[2] = NAN;
    memcpy(out, f, sizeof f);
}

/* Distance from x to the line P(t) + lambda axis (axis unit); *lambda gets
 * (x - P(t)).axis. */
static double line_gap(const verifier *vf, const double x[3], const double axis[3], double t,
                       double *lambda)
{
    double p[3], w[3], c[3];
    curve_point(vf, t, p);
    sub3(x, p, w);
    cross3(w, axis, c);
    if (lambda)
        *lambda = dot3(w, axis);
    return norm3(c);
}

/* Golden-section minimum of line_gap over [a, b]. */
static double golden(const verifier *vf, const double x[3], const double axis[3], double a,
                     double b)
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = line_gap(vf, x, axis, c, NULL), fd = line_gap(vf, x, axis, d, NULL);
    for (int k = 0; k < GOLDEN_ITER && b - a > 0.0; ++k) {
        if (fc <= fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a);
            fc = line_gap(vf, x, axis, c, NULL);
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a);
            fd = line_gap(vf, x, axis, d, NULL);
        }
    }
    return fc <= fd ? c : d;
}

/* The t in [lo, hi] whose line along axis passes nearest x: the local
 * minima of a scan of n + 1 points, refined. With `front`, only t with
 * (x - P(t)).axis >= -front_tol count; *behind_only is set when some t
 * passes within gap_tol but only behind. Returns the gap (HUGE_VAL if no
 * t counts). */
static double best_t(const verifier *vf, const double x[3], const double axis[3], double lo,
                     double hi, int n, int front, double front_tol, double gap_tol, double *t_out,
                     int *behind_only)
{
    double best = HUGE_VAL;
    double gaps[T_GLOBAL_SCAN + 1];
    for (int k = 0; k <= n; ++k)
        gaps[k] = line_gap(vf, x, axis, lo + (hi - lo) * k / n, NULL);
    int refined = 0;
    for (int k = 0; k <= n && refined < T_MINIMA; ++k) {
        if ((k > 0 && gaps[k - 1] < gaps[k]) || (k < n && gaps[k + 1] < gaps[k]))
            continue;
        ++refined;
        const double a = lo + (hi - lo) * (k > 0 ? k - 1 : 0) / n;
        const double b = lo + (hi - lo) * (k < n ? k + 1 : n) / n;
        const double t = golden(vf, x, axis, a, b);
        double lambda;
        const double gap = line_gap(vf, x, axis, t, &lambda);
        if (front && lambda < -front_tol) {
            if (gap <= gap_tol)
                *behind_only = 1;
            continue;
        }
        if (gap < best) {
            best = gap;
            *t_out = t;
        }
    }
    if (best <= gap_tol)
        *behind_only = 0;
    return best;
}

static double ulp(double x)
{
    return nextafter(fabs(x), INFINITY) - fabs(x);
}

/* Newton on (S - p).Su = (S - p).Sv = 0 from (u, v), kept in the domain.
 * Returns 1 when it converged to an interior critical point of the
 * distance; *local_min says whether it is a local minimum. */
static int foot_newton(const verifier *vf, const double p[3], double uv[2], double foot[3],
                       int *local_min)
{
    const pc_oracle_mesh *m = vf->in->mesh;
    const double *dom = m->domain;
    double u = uv[0], v = uv[1];
    for (int it = 0; it < NEWTON_ITER; ++it) {
        double f[18];
        if (projcurve_surface_eval(NULL, vf->in->surface, u, v, 2, f) != PROJCURVE_OK)
            return 0;
        const double *s = f, *su = f + 3, *sv = f + 6, *suu = f + 9, *suv = f + 12, *svv = f + 15;
        double w[3];
        sub3(s, p, w);
        const double g0 = dot3(w, su), g1 = dot3(w, sv);
        const double a = dot3(su, su) + dot3(w, suu), b = dot3(su, sv) + dot3(w, suv);
        const double d = dot3(sv, sv) + dot3(w, svv);
        const double det = a * d - b * b;
        if (!(fabs(det) > 0.0))
            return 0;
        const double du = -(d * g0 - b * g1) / det, dv = -(a * g1 - b * g0) / det;
        const double un = fmin(fmax(u + du, dom[0]), dom[1]);
        const double vn = fmin(fmax(v + dv, dom[2]), dom[3]);
        const int done = fabs(un - u) <= 1e-15 * (dom[1] - dom[0]) + 1e-300 &&
                         fabs(vn - v) <= 1e-15 * (dom[3] - dom[2]) + 1e-300;
        u = un, v = vn;
        if (done || it == NEWTON_ITER - 1) {
            /* A critical point to what doubles resolve: g to rounding of
             * the size, plus what one ulp of u or v changes it by (where
             * S_vv is huge, as in a knot cluster that makes a crease, one
             * ulp of v moves g by far more than rounding). */
            const double eu = ULP_SLACK * ulp(u), ev = ULP_SLACK * ulp(v);
            const double round = ROUND_REL * vf->in->size;
            if (fabs(g0) > round * norm3(su) + fabs(a) * eu + fabs(b) * ev ||
                fabs(g1) > round * norm3(sv) + fabs(b) * eu + fabs(d) * ev)
                return 0;
            *local_min = det > 0.0 && a > 0.0;
            uv[0] = u, uv[1] = v;
            memcpy(foot, s, 3 * sizeof *s);
            return 1;
        }
    }
    return 0;
}

/* Whether (u, v) is a critical point of |S - p| to what doubles resolve
 * (the test of foot_newton's last iterate, at the point itself). */
static int critical_at(const verifier *vf, const double p[3], const double uv[2],
                       double foot[3], int *local_min)
{
    double f[18];
    if (projcurve_surface_eval(NULL, vf->in->surface, uv[0], uv[1], 2, f) != PROJCURVE_OK)
        return 0;
    const double *su = f + 3, *sv = f + 6;
    double w[3];
    sub3(f, p, w);
    const double g0 = dot3(w, su), g1 = dot3(w, sv);
    const double a = dot3(su, su) + dot3(w, f + 9), b = dot3(su, sv) + dot3(w, f + 12);
    const double d = dot3(sv, sv) + dot3(w, f + 15);
    const double eu = ULP_SLACK * ulp(uv[0]), ev = ULP_SLACK * ulp(uv[1]);
    const double round = ROUND_REL * vf->in->size;
    if (fabs(g0) > round * norm3(su) + fabs(a) * eu + fabs(b) * ev ||
        fabs(g1) > round * norm3(sv) + fabs(b) * eu + fabs(d) * ev)
        return 0;
    *local_min = a * d - b * b > 0.0 && a > 0.0;
    memcpy(foot, f, 3 * sizeof *f);
    return 1;
}

/* A descent on |S - p|^2 / 2 from (u, v): the Newton step where the
 * Hessian is positive definite, else the gradient step, halved until the
 * distance decreases; then foot_newton from where it stopped. On a fold
 * (the v lines of linkrods.step surface 11 reverse, Sv ~ 2e-3 |Su|, the
 * squared distance has a minimum on the fold edge and a maximum 1e-3 of v
 * away) the plain Newton from a point 1e-8 from the foot jumps across the
 * fold for most t; the descent cannot. DESCENT_ITER steps of at most
 * DESCENT_HALVINGS halvings each; when they are used up the result is
 * whatever foot_newton makes of the last point. */
static int foot_descent(const verifier *vf, const double p[3], double uv[2], double foot[3],
                        int *local_min)
{
    const double *dom = vf->in->mesh->domain;
    double u = uv[0], v = uv[1];
    for (int it = 0; it < DESCENT_ITER; ++it) {
        double f[18];
        if (projcurve_surface_eval(NULL, vf->in->surface, u, v, 2, f) != PROJCURVE_OK)
            return 0;
        const double *su = f + 3, *sv = f + 6;
        double w[3];
        sub3(f, p, w);
        const double e0 = dot3(w, w), g0 = dot3(w, su), g1 = dot3(w, sv);
        const double a = dot3(su, su) + dot3(w, f + 9), b = dot3(su, sv) + dot3(w, f + 12);
        const double d = dot3(sv, sv) + dot3(w, f + 15), det = a * d - b * b;
        double du, dv;
        if (det > 0.0 && a > 0.0) {
            du = -(d * g0 - b * g1) / det, dv = -(a * g1 - b * g0) / det;
        } else {
            const double scale = dot3(su, su) + dot3(sv, sv);
            if (!(scale > 0.0))
                return 0;
            du = -g0 / scale, dv = -g1 / scale;
        }
        int moved = 0;
        for (int h = 0; h < DESCENT_HALVINGS && !moved; ++h, du *= 0.5, dv *= 0.5) {
            const double un = fmin(fmax(u + du, dom[0]), dom[1]);
            const double vn = fmin(fmax(v + dv, dom[2]), dom[3]);
            double q[3], wq[3];
            if (projcurve_surface_eval(NULL, vf->in->surface, un, vn, 0, q) != PROJCURVE_OK)
                return 0;
            sub3(q, p, wq);
            if (dot3(wq, wq) < e0)
                u = un, v = vn, moved = 1;
        }
        if (!moved)
            break; /* no step lowers the distance: at a minimum to rounding */
    }
    uv[0] = u, uv[1] = v;
    if (foot_newton(vf, p, uv, foot, local_min))
        return 1;
    uv[0] = u, uv[1] = v; /* Newton left again: the descent's point itself */
    return critical_at(vf, p, uv, foot, local_min);
}

static void bezier_uv(int degree, const double *uv, double s, double out[2])
{
    double work[2 * PROJCURVE_MAX_PCURVE_POINTS];
    memcpy(work, uv, (size_t)(2 * (degree + 1)) * sizeof *work);
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i <= degree - r; ++i)
            for (int c = 0; c < 2; ++c)
                work[2 * i + c] = (1.0 - s) * work[2 * i + c] + s * work[2 * (i + 1) + c];
    out[0] = work[0], out[1] = work[1];
}

/* Records the first wrong sample: its t*, with the gap of its line and
 * lambda there (a diagnosis for the failure list). */
static void note_wrong(const verifier *vf, const double x[3], const double axis[3], double t)
{
    pc_sweep_report *rep = vf->rep;
    if (!isnan(rep->wrong_t))
        return;
    rep->wrong_t = t;
    rep->wrong_gap = line_gap(vf, x, axis, t, &rep->wrong_lambda);
}

/* The exact projection point of P(t) nearest the surface point with
 * parameters uv: the test's Newton iteration (ray_oracle's polish for the
 * ray, foot_newton for the foot, foot_descent where that fails) started
 * there. Returns the distance from x
 * to it, HUGE_VAL if the iteration fails. */
static double exact_distance(verifier *vf, const double x[3], const double uv[2], double t)
{
    double p[3], exact[3];
    curve_point(vf, t, p);
    if (vf->in->orthogonal) {
        double fuv[2] = {uv[0], uv[1]};
        int local_min = 0;
        if (!foot_newton(vf, p, fuv, exact, &local_min)) {
            if (vf->descents >= MAX_DESCENTS)
                return HUGE_VAL;
            ++vf->descents;
            fuv[0] = uv[0], fuv[1] = uv[1];
            if (!foot_descent(vf, p, fuv, exact, &local_min))
                return HUGE_VAL;
        }
    } else {
        pc_oracle_hit h;
        if (!pc_oracle_check_hit(vf->in->mesh, p, vf->dir_unit, uv[0], uv[1], 1.0, &h) ||
            projcurve_surface_eval(NULL, vf->in->surface, h.u, h.v, 0, exact) != PROJCURVE_OK)
            return HUGE_VAL;
    }
    return dist3(x, exact);
}

/* Golden section of exact_distance over [a, b]. */
static double golden_exact(verifier *vf, const double x[3], const double uv[2], double a,
                           double b)
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = exact_distance(vf, x, uv, c), fd = exact_distance(vf, x, uv, d);
    for (int k = 0; k < GOLDEN_ITER && b - a > 0.0; ++k) {
        if (fc <= fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a);
            fc = exact_distance(vf, x, uv, c);
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a);
            fd = exact_distance(vf, x, uv, d);
        }
    }
    return fmin(fc, fd);
}

/* The distance from x to the exact projection curve over t in [lo, hi]:
 * exact_distance at n + 1 points, each local minimum (T_MINIMA at most)
 * refined by golden section between its neighbours. A scan, not one golden
 * section: where S folds, the distance is not unimodal in t (below). */
static double nearest_exact(verifier *vf, const double x[3], const double uv[2], double lo,
                            double hi, int n)
{
    double d[T_EXACT_SCAN + 1];
    for (int k = 0; k <= n; ++k)
        d[k] = exact_distance(vf, x, uv, lo + (hi - lo) * k / n);
    double best = HUGE_VAL;
    int refined = 0;
    for (int k = 0; k <= n && refined < T_MINIMA; ++k) {
        best = fmin(best, d[k]);
        if (d[k] == HUGE_VAL || (k > 0 && d[k - 1] < d[k]) || (k < n && d[k + 1] < d[k]))
            continue;
        ++refined;
        const double a = lo + (hi - lo) * (k > 0 ? k - 1 : 0) / n;
        const double b = lo + (hi - lo) * (k < n ? k + 1 : n) / n;
        best = fmin(best, golden_exact(vf, x, uv, a, b));
    }
    return best;
}

/* The distance from x to the foot of P(t) in the basin of uv: the descent
 * from uv (foot_descent, which cannot leave that basin across a fold as
 * Newton can), HUGE_VAL where it finds no critical point. */
static double basin_distance(const verifier *vf, const double x[3], const double uv[2],
                             double t)
{
    double p[3], foot[3], fuv[2] = {uv[0], uv[1]};
    int local_min = 0;
    curve_point(vf, t, p);
    return foot_descent(vf, p, fuv, foot, &local_min) ? dist3(x, foot) : HUGE_VAL;
}

/* The brute-force distance from x to the exact projection curve over t in
 * [lo, hi], for the samples the searches above do not clear (orthogonal):
 * basin_distance at DENSE_T + 1 even t, the DENSE_MINIMA smallest local
 * minima refined by golden section between their neighbours. Where S
 * folds (linkrods.step surface 11, its v lines reversing within 1e-3 of
 * v) the foot moves by ~1e3 eps_D for a change of t that the 32-point
 * scans step over, and Newton from the sample's (u, v) lands on the other
 * sheet; the descent stays on the sample's. A foot found so is an exact
 * critical point of |S - P(t)| (foot_newton's or critical_at's test), so
 * the distance is never under-estimated: only the search is denser. */
static double dense_nearest_foot(verifier *vf, const double x[3], const double uv[2],
                                 double lo, double hi)
{
    double best = HUGE_VAL;
    int at[DENSE_MINIMA];
    double val[DENSE_MINIMA];
    int kept = 0;
    double prev2 = HUGE_VAL, prev = basin_distance(vf, x, uv, lo);
    for (int k = 1; k <= DENSE_T + 1; ++k) {
        const double cur = k <= DENSE_T ? basin_distance(vf, x, uv, lo + (hi - lo) * k / DENSE_T)
                                        : HUGE_VAL;
        best = fmin(best, prev);
        /* prev (at k - 1) a local minimum: keep the smallest few */
        if (prev < HUGE_VAL && prev <= prev2 && prev <= cur) {
            int slot = kept < DENSE_MINIMA ? kept++ : -1;
            for (int i = 0; slot < 0 && i < kept; ++i)
                if (val[i] > prev)
                    slot = i;
            if (slot >= 0)
                at[slot] = k - 1, val[slot] = prev;
        }
        prev2 = prev, prev = cur;
    }
    for (int i = 0; i < kept; ++i) {
        double a = lo + (hi - lo) * (at[i] > 0 ? at[i] - 1 : 0) / DENSE_T;
        double b = lo + (hi - lo) * (at[i] < DENSE_T ? at[i] + 1 : DENSE_T) / DENSE_T;
        const double g = 0.5 * (sqrt(5.0) - 1.0);
        for (int it = 0; it < GOLDEN_ITER && b > a; ++it) {
            const double c = b - g * (b - a), d = a + g * (b - a);
            if (basin_distance(vf, x, uv, c) <= basin_distance(vf, x, uv, d))
                b = d;
            else
                a = c;
        }
        best = fmin(best, basin_distance(vf, x, uv, 0.5 * (a + b)));
    }
    return best;
}

/* The t range searched for a sample of a piece over `range`: the range
 * widened by half its length on each side, within the curve's domain. */
static void search_range(const verifier *vf, const double range[2], double *lo, double *hi)
{
    const double pad = fmax(0.5 * (range[1] - range[0]), 1e-6 * (vf->t1 - vf->t0));
    *lo = fmax(vf->t0, range[0] - pad);
    *hi = fmin(vf->t1, range[1] + pad);
}

/* A sample X with pcurve point uv: on S, with a normal n there (unit),
 * not grazing. Returns 0 (and counts why) when it is not checked further. */
static int sample_frame(verifier *vf, const double x[3], const double uv[2],
                        const double range[2], double n[3])
{
    const pc_sweep_input *in = vf->in;
    pc_sweep_report *rep = vf->rep;
    double f[9];
    if (projcurve_surface_eval(NULL, in->surface, uv[0], uv[1], 1, f) != PROJCURVE_OK) {
        ++rep->accessor_failures;
        return 0;
    }
    const double off = dist3(x, f);
    rep->worst_off_surface = fmax(rep->worst_off_surface, off / in->eps_d);
    if (!(off <= ON_SURFACE_REL * in->size)) {
        ++rep->off_surface;
        if (isnan(rep->wrong_t))
            rep->wrong_t = range[0], rep->wrong_gap = off, rep->wrong_lambda = NAN;
        return 0;
    }
    cross3(f + 3, f + 6, n);
    const double nn = norm3(n);
    if (!(nn > 1e-12 * norm3(f + 3) * norm3(f + 6))) {
        ++rep->pole_samples; /* a collapsed edge: no normal to check against */
        return 0;
    }
    for (int c = 0; c < 3; ++c)
        n[c] /= nn;
    if (!in->orthogonal && fabs(dot3(vf->dir_unit, n)) < sin(PC_VERIFY_GRAZING_DEG * PI / 180.0)) {
        ++rep->grazing_samples;
        return 0;
    }
    return 1;
}

/* t*: the curve parameter whose ray (directional, in front) or normal line
 * at X (orthogonal) passes nearest X, searched over the piece's range
 * widened by half, then over the whole domain. Directional: fails (and
 * counts why) unless that ray passes within eps_D of X. Orthogonal: the gap
 * is not the criterion (the normal turns along S, so the gap grows with the
 * distance to the curve); the exact foot of t* is checked next. */
static int find_t_star(verifier *vf, const double x[3], const double axis[3],
                       const double range[2], double *t)
{
    const pc_sweep_input *in = vf->in;
    pc_sweep_report *rep = vf->rep;
    const double gap_tol = in->eps_d * (1.0 + 1e-6) + ROUND_REL * in->size;
    double lo, hi;
    search_range(vf, range, &lo, &hi);
    const int front = !in->orthogonal;
    int behind_only = 0;
    *t = range[0];
    double gap = best_t(vf, x, axis, lo, hi, T_SCAN, front, in->eps_d, gap_tol, t, &behind_only);
    if (!(gap <= gap_tol) && vf->scans < MAX_SCANS) {
        ++vf->scans;
        gap = best_t(vf, x, axis, vf->t0, vf->t1, T_GLOBAL_SCAN, front, in->eps_d, gap_tol, t,
                     &behind_only);
    }
    if (in->orthogonal)
        return 1;
    if (gap < HUGE_VAL)
        rep->worst_residual = fmax(rep->worst_residual, gap / in->eps_d);
    if (gap <= gap_tol)
        return 1;
    if (behind_only) {
        ++rep->behind;
        int unused = 0; /* for the report: the t whose ray, behind, meets X */
        best_t(vf, x, axis, vf->t0, vf->t1, T_GLOBAL_SCAN, 0, 0.0, gap_tol, t, &unused);
    } else {
        ++rep->off_projection;
    }
    note_wrong(vf, x, axis, *t);
    return 0;
}

/* The checks of one sample X of a piece over the t range `range`, with
 * pcurve point uv. */
static void check_sample(verifier *vf, const double x[3], const double uv[2],
                         const double range[2])
{
    const pc_sweep_input *in = vf->in;
    pc_sweep_report *rep = vf->rep;
    ++rep->samples;
    double n[3], t;
    if (!sample_frame(vf, x, uv, range, n))
        return;
    const double *axis = in->orthogonal ? n : vf->dir_unit;
    if (!find_t_star(vf, x, axis, range, &t))
        return;
    /* The exact point of t* bounds X's distance to the exact projection
     * curve from above; where that bound is not enough, the distance itself
     * is found: the nearest exact point over t around t*, and over the
     * piece's own t range (widened as for t*). The second search is needed
     * where S folds onto itself (the v lines of linkrods.step surface 11
     * reverse within 1e-3 of v, the normal flipping by ~178 deg): there the
     * normal line of a sample 1e-7 from the exact foot of P(t) misses P(t)
     * by ~1e3 eps_D, the nearest normal line names a t* far from t, and
     * the window around t* does not reach t (curve 0: 27 of 2637 samples
     * failed so, up to 19.8 eps_D, all within 1e-4 eps_D of the exact foot
     * of a t of their piece by a pattern search; test_ortho_fold_real). */
    const double bound = HAUSDORFF_SLACK * in->eps_d + ROUND_REL * in->size;
    double err = exact_distance(vf, x, uv, t);
    if (!(err <= bound) && vf->scans < MAX_SCANS) {
        ++vf->scans;
        const double w = fmax(range[1] - range[0], 1e-9 * (vf->t1 - vf->t0));
        err = fmin(err, nearest_exact(vf, x, uv, fmax(vf->t0, t - w), fmin(vf->t1, t + w),
                                      T_EXACT_SCAN));
        double lo, hi;
        search_range(vf, range, &lo, &hi);
        if (!(err <= bound) && vf->scans < MAX_SCANS) {
            ++vf->scans;
            err = fmin(err, nearest_exact(vf, x, uv, lo, hi, T_EXACT_SCAN));
        }
    }
    if (in->orthogonal && !(err <= bound) && vf->dense_scans < MAX_DENSE_SCANS) {
        ++vf->dense_scans;
        double lo, hi;
        search_range(vf, range, &lo, &hi);
        err = fmin(err, dense_nearest_foot(vf, x, uv, lo, hi));
    }
    if (err == HUGE_VAL) {
        ++rep->off_projection; /* no exact point near X for any t near t* */
        note_wrong(vf, x, axis, t);
        return;
    }
    rep->worst_exact = fmax(rep->worst_exact, err / in->eps_d);
    if (!(err <= bound)) {
        ++rep->far_from_exact;
        note_wrong(vf, x, axis, t);
    }
}

/* Distance from y to the piece polylines, refined on the nearest piece by
 * golden section over s around its nearest segment. */
static double segment_distance(const double a[3], const double b[3], const double y[3])
{
    double ab[3], ay[3];
    sub3(b, a, ab);
    sub3(y, a, ay);
    const double l2 = dot3(ab, ab);
    double s = l2 > 0.0 ? dot3(ay, ab) / l2 : 0.0;
    s = fmin(fmax(s, 0.0), 1.0);
    double q[3];
    for (int c = 0; c < 3; ++c)
        q[c] = a[c] + s * ab[c];
    return dist3(q, y);
}

static double piece_distance_at(const piece *pc, double s, const double y[3])
{
    double x[3];
    pc_test_piece_point(pc->degree, pc->ctrl, pc->weights, s, x);
    return dist3(x, y);
}

static double cover_distance(const verifier *vf, const double y[3])
{
    double best = HUGE_VAL;
    size_t best_piece = 0;
    int best_seg = 0;
    for (size_t k = 0; k < vf->n_pieces; ++k) {
        const double *poly = vf->pieces[k].poly;
        for (int i = 0; i < COVER_INTERVALS; ++i) {
            const double d = segment_distance(poly + 3 * i, poly + 3 * (i + 1), y);
            if (d < best)
                best = d, best_piece = k, best_seg = i;
        }
    }
    if (vf->n_pieces == 0)
        return best;
    const piece *pc = &vf->pieces[best_piece];
    double a = (double)(best_seg > 0 ? best_seg - 1 : 0) / COVER_INTERVALS;
    double b = (double)(best_seg + 2 < COVER_INTERVALS ? best_seg + 2 : COVER_INTERVALS) /
               COVER_INTERVALS;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int k = 0; k < GOLDEN_ITER; ++k) {
        const double c = b - g * (b - a), d = a + g * (b - a);
        if (piece_distance_at(pc, c, y) <= piece_distance_at(pc, d, y))
            b = d;
        else
            a = c;
    }
    return fmin(best, piece_distance_at(pc, 0.5 * (a + b), y));
}

static void note_missed(verifier *vf, double t, double d)
{
    pc_sweep_report *rep = vf->rep;
    ++rep->missed;
    if (isnan(rep->missed_t))
        rep->missed_t = t;
    rep->worst_missed = fmax(rep->worst_missed, d / vf->in->eps_d);
}

/* 1 when the curve at t runs along Dir to eps_D: the rays of the
 * neighbouring samples t - dt and t + dt (clamped to the domain) are the
 * ray of t to eps_D (P moved along it, |(P(t +- dt) - P(t)) x Dir| <=
 * eps_D), so each ray hit there is the hit of the whole stretch: the
 * curve's image is a point of S. */
static int runs_along_dir(const verifier *vf, double t, double dt, const double p[3])
{
    for (int side = -1; side <= 1; side += 2) {
        double q[3], w[3], c[3];
        curve_point(vf, t + side * dt, q);
        sub3(q, p, w);
        cross3(w, vf->dir_unit, c);
        if (!(norm3(c) <= vf->in->eps_d))
            return 0;
    }
    return 1;
}

static void complete_directional(verifier *vf, double t, double dt, const double p[3])
{
    const pc_sweep_input *in = vf->in;
    pc_oracle_hit hits[MAX_HITS];
    const size_t n = pc_oracle_line_hits(in->mesh, p, vf->dir_unit, 1, hits, MAX_HITS);
    const double tol = HAUSDORFF_SLACK * in->eps_d + ROUND_REL * in->size;
    for (size_t k = 0; k < n && k < MAX_HITS; ++k) {
        if (hits[k].lambda < in->lambda_min)
            continue;
        if (!(hits[k].cos_dir >= sin(PC_VERIFY_GRAZING_DEG * PI / 180.0))) {
            ++vf->rep->grazing_points;
            continue;
        }
        ++vf->rep->oracle_points;
        double h[3];
        projcurve_surface_eval(NULL, in->surface, hits[k].u, hits[k].v, 0, h);
        const double d = cover_distance(vf, h);
        if (d <= tol)
            continue;
        if (runs_along_dir(vf, t, dt, p))
            ++vf->rep->point_image_points;
        else
            note_missed(vf, t, d);
    }
}

static double grid_d2(const pc_oracle_mesh *m, int i, int j, const double p[3])
{
    const double *x = m->points + 3 * ((size_t)j * (size_t)(m->cells_u + 1) + (size_t)i);
    double w[3];
    sub3(x, p, w);
    return dot3(w, w);
}

static void complete_orthogonal(verifier *vf, double t, const double p[3])
{
    const pc_sweep_input *in = vf->in;
    const pc_oracle_mesh *m = in->mesh;
    const double tol = HAUSDORFF_SLACK * in->eps_d + ROUND_REL * in->size;
    double feet[2 * MAX_FEET];
    int n_feet = 0;
    for (int j = 1; j < m->cells_v && n_feet < MAX_FEET; ++j) {
        for (int i = 1; i < m->cells_u && n_feet < MAX_FEET; ++i) {
            const double d = grid_d2(m, i, j, p);
            int is_min = 1;
            for (int dj = -1; dj <= 1 && is_min; ++dj)
                for (int di = -1; di <= 1 && is_min; ++di)
                    if ((di || dj) && grid_d2(m, i + di, j + dj, p) < d)
                        is_min = 0;
            if (!is_min)
                continue;
            double uv[2] = {m->us[i], m->vs[j]}, foot[3];
            int local_min = 0;
            if (!foot_newton(vf, p, uv, foot, &local_min) || !local_min)
                continue;
            int seen = 0;
            for (int k = 0; k < n_feet && !seen; ++k)
                seen = fabs(feet[2 * k] - uv[0]) <= 1e-7 * (m->domain[1] - m->domain[0]) &&
                       fabs(feet[2 * k + 1] - uv[1]) <= 1e-7 * (m->domain[3] - m->domain[2]);
            if (seen)
                continue;
            feet[2 * n_feet] = uv[0], feet[2 * n_feet + 1] = uv[1];
            ++n_feet;
            ++vf->rep->oracle_points;
            const double dc = cover_distance(vf, foot);
            if (!(dc <= tol))
                note_missed(vf, t, dc);
        }
    }
}

/* Reads and samples every piece of branch b (up to the work bound). */
static void sample_branch(verifier *vf, const projcurve_result *r, size_t b, size_t n_pieces,
                          size_t stride)
{
    pc_sweep_report *rep = vf->rep;
    for (size_t k = 0; k < n_pieces; ++k) {
        if (k % stride != 0) {
            ++rep->pieces_skipped;
            continue;
        }
        piece *pc = &vf->pieces[vf->n_pieces];
        double uv_range[4], uvc[2 * PROJCURVE_MAX_PCURVE_POINTS];
        int uv_degree = 0;
        if (projcurve_result_piece(NULL, r, b, k, &pc->degree, pc->ctrl, pc->weights, pc->range,
                                   uv_range) != PROJCURVE_OK ||
            projcurve_result_piece_pcurve(NULL, r, b, k, &uv_degree, uvc) != PROJCURVE_OK) {
            ++rep->accessor_failures;
            continue;
        }
        ++vf->n_pieces;
        for (int i = 0; i <= COVER_INTERVALS; ++i)
            pc_test_piece_point(pc->degree, pc->ctrl, pc->weights, (double)i / COVER_INTERVALS,
                                pc->poly + 3 * i);
        for (int i = 0; i <= PIECE_INTERVALS; ++i) {
            const double s = (double)i / PIECE_INTERVALS;
            double x[3], uv[2];
            pc_test_piece_point(pc->degree, pc->ctrl, pc->weights, s, x);
            bezier_uv(uv_degree, uvc, s, uv);
            /* A piece end lies on a knot line, where S may be only C0 (a
             * crease: every knot of a faceted surface): its normal and its
             * foot are those of the patch the piece lies in, whose side one
             * ulp towards the other end is (the surface evaluator takes
             * one side at the line, maybe the other patch's). */
            if (i == 0 || i == PIECE_INTERVALS) {
                const int other = i == 0 ? 1 : 0;
                uv[0] = nextafter(uv[0], uv_range[2 * other]);
                uv[1] = nextafter(uv[1], uv_range[2 * other + 1]);
            }
            check_sample(vf, x, uv, pc->range);
        }
    }
}

void pc_sweep_verify(const pc_sweep_input *in, const projcurve_result *r,
                      pc_sweep_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->wrong_t = rep->missed_t = rep->wrong_gap = rep->wrong_lambda = NAN;
    verifier vf = {in, rep, 0.0, 0.0, {0, 0, 0}, NULL, 0, 0, 0, 0};
    if (projcurve_curve_domain(NULL, in->curve, &vf.t0, &vf.t1) != PROJCURVE_OK) {
        ++rep->accessor_failures;
        return;
    }
    const double dn = norm3(in->dir);
    for (int c = 0; c < 3; ++c)
        vf.dir_unit[c] = dn > 0.0 ? in->dir[c] / dn : 0.0;
    rep->branches = projcurve_result_branch_count(r);
    size_t total = 0;
    for (size_t b = 0; b < rep->branches; ++b) {
        size_t n_pieces = 0;
        projcurve_branch_end end = PROJCURVE_END_CURVE_END;
        if (projcurve_result_branch_info(NULL, r, b, NULL, NULL, &end, NULL, &n_pieces) !=
            PROJCURVE_OK) {
            ++rep->accessor_failures;
            continue;
        }
        total += n_pieces;
        rep->zero_piece_branches += n_pieces == 0;
        rep->failed_ends += end == PROJCURVE_END_FAILED;
    }
    rep->pieces = total;
    /* The work bound: every stride-th piece when there are more. */
    const size_t budget = in->max_piece_samples / (PIECE_INTERVALS + 1);
    const size_t stride = total > budget && budget > 0 ? (total + budget - 1) / budget : 1;
    vf.pieces = malloc(sizeof *vf.pieces * (total / stride + rep->branches + 1));
    if (vf.pieces == NULL) {
        ++rep->accessor_failures;
        return;
    }
    for (size_t b = 0; b < rep->branches; ++b) {
        size_t n_pieces = 0;
        if (projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces) ==
            PROJCURVE_OK)
            sample_branch(&vf, r, b, n_pieces, stride);
    }
    /* Completeness only against every piece: with some skipped, a hit
     * between sampled pieces would be reported missed wrongly. */
    if (rep->pieces_skipped == 0) {
        const int n = in->completeness_samples;
        for (int k = 0; k < n; ++k) {
            const double t = vf.t0 + (vf.t1 - vf.t0) * (k + 0.5) / n;
            double p[3];
            curve_point(&vf, t, p);
            if (in->orthogonal)
                complete_orthogonal(&vf, t, p);
            else
                complete_directional(&vf, t, (vf.t1 - vf.t0) / n, p);
        }
    }
    free(vf.pieces);
}

void pc_sweep_surface_eval(void *user, double u, double v, int n_deriv, double out[9])
{
    if (projcurve_surface_eval(NULL, user, u, v, n_deriv, out) != PROJCURVE_OK)
        for (int k = 0; k < 9; ++k)
            out[k] = NAN;
}

int pc_sweep_mesh_cells(size_t spans)
{
    const size_t cells = 8 * spans;
    return cells < 48 ? 48 : (cells > 256 ? 256 : (int)cells);
}
