/* SPDX-License-Identifier: BSD-3-Clause */
#include "intersect/bezier_clip.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "common/compiler.h"
#include "projcurve.h"

/* A clip that keeps more than this fraction of a side is no progress
 * (Nishita et al. subdivide when clipping removes less than 20%). */
#define PC_CLIP_PROGRESS_RATIO 0.8
/* Each clipped interval is widened by this fraction of the current box:
 * the crossing of the hull with f = 0 is computed from control values that
 * carry rounding errors of ~1e-16 of the patch size, i.e. ~1e-16 / width
 * of the box in local terms; 1e-6 covers boxes down to ~1e-10. */
#define PC_CLIP_PAD 1e-6

/* Plain minimum and maximum (fmin/fmax are library calls here; no NaN can
 * reach these: control values are finite). */
/* The clipping round is compiled once per common degree pair (constant
 * trip counts let the compiler unroll the short loops, which otherwise
 * cost more than the arithmetic) and once generically. */

static inline double min2(double a, double b) { return a < b ? a : b; }
static inline double max2(double a, double b) { return a > b ? a : b; }

/* Layout of a planar net seen along direction dir: point (k, l) with k along
 * dir (0..K) and l across it (0..L) lives at 2 * (k * step_k + l * step_l). */
typedef struct net_view {
    int K, L;
    size_t step_k, step_l;
} net_view;

static PC_ALWAYS_INLINE net_view view_along(int m, int n, int dir)
{
    net_view v;
    if (dir == 0) {
        v.K = m;
        v.L = n;
        v.step_k = 1;
        v.step_l = (size_t)(m + 1);
    } else {
        v.K = n;
        v.L = m;
        v.step_k = (size_t)(m + 1);
        v.step_l = 1;
    }
    return v;
}

static PC_ALWAYS_INLINE const double *at(const double *net, const net_view *v, int k, int l)
{
    return net + 2 * ((size_t)k * v->step_k + (size_t)l * v->step_l);
}

/* Unit normal n of the functional f = n . Q used to clip along the view's
 * direction: perpendicular to the net's average edge across the direction
 * (f then varies mostly along it). Falls back to the average edge along the
 * direction, then to the X axis, when the net is degenerate. */
static PC_ALWAYS_INLINE void clip_normal(const double *net, const net_view *v, double normal[2])
{
    const double *a0 = at(net, v, 0, 0), *a1 = at(net, v, 0, v->L);
    const double *b0 = at(net, v, v->K, 0), *b1 = at(net, v, v->K, v->L);
    const double across[2] = {a1[0] - a0[0] + b1[0] - b0[0], a1[1] - a0[1] + b1[1] - b0[1]};
    const double along[2] = {b0[0] - a0[0] + b1[0] - a1[0], b0[1] - a0[1] + b1[1] - a1[1]};
    const double len_across = sqrt(across[0] * across[0] + across[1] * across[1]);
    const double len_along = sqrt(along[0] * along[0] + along[1] * along[1]);
    if (len_across > 1e-12 * len_along && len_across > 0.0) {
        normal[0] = -across[1] / len_across;
        normal[1] = across[0] / len_across;
    } else if (len_along > 0.0) {
        normal[0] = along[0] / len_along;
        normal[1] = along[1] / len_along;
    } else {
        normal[0] = 1.0;
        normal[1] = 0.0;
    }
}

/* The interval [*a, *b] of x where the lower convex hull of the points
 * (k / K, y[k]) is <= 0; returns 0 when it is empty. That set is the
 * convex hull of the points with y <= 0 and of the zero crossings of the
 * segments joining them to points with y > 0; only positive points outside
 * [first, last] nonpositive index can extend it. */
static PC_ALWAYS_INLINE int sublevel_interval(const double *y, int K, double *a, double *b)
{
    int first = -1, last = -1;
    for (int k = 0; k <= K; ++k) {
        if (y[k] <= 0.0) {
            if (first < 0)
                first = k;
            last = k;
        }
    }
    if (first < 0)
        return 0;
    const double inv_k = 1.0 / K;
    double lo = first * inv_k, hi = last * inv_k;
    for (int i = 0; i < first; ++i) {
        for (int k = first; k <= last; ++k) {
            if (y[k] <= 0.0) {
                const double x = (i + (k - i) * (y[i] / (y[i] - y[k]))) * inv_k;
                lo = min2(lo, x);
            }
        }
    }
    for (int i = last + 1; i <= K; ++i) {
        for (int k = first; k <= last; ++k) {
            if (y[k] <= 0.0) {
                const double x = (i + (k - i) * (y[i] / (y[i] - y[k]))) * inv_k;
                hi = max2(hi, x);
            }
        }
    }
    *a = lo;
    *b = hi;
    return 1;
}

/* The interval [*lo, *hi] of x where the convex hull of the points
 * (k / K, lo_f[k]) and (k / K, hi_f[k]) meets f = 0, i.e. where its lower
 * chain is <= 0 and its upper chain >= 0 (hi_f holds -max, so that both are
 * sublevel sets). Returns 0 when it does not meet it. */
static PC_ALWAYS_INLINE int hull_zero_interval(const double *lo_f, const double *neg_hi_f, int K, double *lo,
                              double *hi)
{
    double a1, b1, a2, b2;
    if (!sublevel_interval(lo_f, K, &a1, &b1) || !sublevel_interval(neg_hi_f, K, &a2, &b2))
        return 0;
    *lo = max2(a1, a2);
    *hi = min2(b1, b2);
    return *lo <= *hi;
}

/* Interval of the view's direction (local to the box, in [0, 1]) that may
 * hold a zero, from the functional across the net and its perpendicular.
 * Returns 0 when there is none. */
static PC_ALWAYS_INLINE int clip_interval(const double *net, const net_view *v, double zero_tol, double *lo,
                         double *hi)
{
    double normal[2];
    clip_normal(net, v, normal);
    double lo1[PROJCURVE_MAX_DEGREE + 1], hi1[PROJCURVE_MAX_DEGREE + 1];
    double lo2[PROJCURVE_MAX_DEGREE + 1], hi2[PROJCURVE_MAX_DEGREE + 1]; /* hi: -max */
    for (int k = 0; k <= v->K; ++k) {
        lo1[k] = lo2[k] = INFINITY;
        hi1[k] = hi2[k] = INFINITY; /* minus the maximum */
        for (int l = 0; l <= v->L; ++l) {
            const double *q = at(net, v, k, l);
            const double f1 = normal[0] * q[0] + normal[1] * q[1];
            const double f2 = normal[1] * q[0] - normal[0] * q[1];
            lo1[k] = min2(lo1[k], f1);
            hi1[k] = min2(hi1[k], -f1);
            lo2[k] = min2(lo2[k], f2);
            hi2[k] = min2(hi2[k], -f2);
        }
        lo1[k] -= zero_tol;
        hi1[k] -= zero_tol;
        lo2[k] -= zero_tol;
        hi2[k] -= zero_tol;
    }
    double a1, b1, a2, b2;
    if (!hull_zero_interval(lo1, hi1, v->K, &a1, &b1) ||
        !hull_zero_interval(lo2, hi2, v->K, &a2, &b2))
        return 0;
    const double a = max2(a1, a2), b = min2(b1, b2);
    if (a > b + 2.0 * PC_CLIP_PAD)
        return 0;
    *lo = max2(0.0, min2(a, b) - PC_CLIP_PAD);
    *hi = min2(1.0, max2(a, b) + PC_CLIP_PAD);
    return 1;
}

/* De Casteljau on the K + 1 planar points p[0], p[stride], ...: keeps the
 * piece over [0, x] (keep_lower) or [x, 1] in place. */
static PC_ALWAYS_INLINE void casteljau_keep(double *p, size_t stride, int K, double x, int keep_lower)
{
    const double y = 1.0 - x;
    for (int r = 1; r <= K; ++r) {
        if (keep_lower) {
            for (int i = K; i >= r; --i) {
                double *a = p + (size_t)(i - 1) * stride, *b = p + (size_t)i * stride;
                b[0] = y * a[0] + x * b[0];
                b[1] = y * a[1] + x * b[1];
            }
        } else {
            for (int i = 0; i <= K - r; ++i) {
                double *a = p + (size_t)i * stride, *b = p + (size_t)(i + 1) * stride;
                a[0] = y * a[0] + x * b[0];
                a[1] = y * a[1] + x * b[1];
            }
        }
    }
}

/* Restricts the net to [lo, hi] (local) along the view's direction. */
static PC_ALWAYS_INLINE void restrict_net(double *net, const net_view *v, double lo, double hi)
{
    const size_t stride = 2 * v->step_k;
    for (int l = 0; l <= v->L; ++l) {
        double *row = net + 2 * (size_t)l * v->step_l;
        if (hi < 1.0)
            casteljau_keep(row, stride, v->K, hi, 1);
        if (lo > 0.0 && hi > 0.0)
            casteljau_keep(row, stride, v->K, lo / hi, 0);
    }
}

/* Clips one direction: returns -1 (empty), 1 (progress) or 0 (no progress). */
static PC_ALWAYS_INLINE int clip_direction(double *net, int m, int n, int dir, double zero_tol, double box[4])
{
    double *side = box + 2 * dir;
    const double width = side[1] - side[0];
    const net_view v = view_along(m, n, dir);
    double lo, hi;
    if (!clip_interval(net, &v, zero_tol, &lo, &hi))
        return -1;
    if (width < PC_CLIP_WIDTH_TOL)
        return 0; /* converged side: only the emptiness test matters */
    if (lo > 0.0 || hi < 1.0) {
        restrict_net(net, &v, lo, hi);
        const double s0 = side[0];
        side[0] = s0 + lo * width;
        side[1] = s0 + hi * width;
    }
    return hi - lo <= PC_CLIP_PROGRESS_RATIO;
}

static PC_ALWAYS_INLINE pc_clip_outcome clip_step(double *net, int m, int n, double zero_tol,
                                                  double box[4])
{
    const int ds = clip_direction(net, m, n, 0, zero_tol, box);
    if (ds < 0)
        return PC_CLIP_EMPTY;
    const int dt = clip_direction(net, m, n, 1, zero_tol, box);
    if (dt < 0)
        return PC_CLIP_EMPTY;
    if (box[1] - box[0] < PC_CLIP_WIDTH_TOL && box[3] - box[2] < PC_CLIP_WIDTH_TOL)
        return PC_CLIP_CONVERGED;
    return (ds || dt) ? PC_CLIP_PROGRESS : PC_CLIP_STALLED;
}

pc_clip_outcome pc_bezier_clip_step(double *net, int m, int n, double zero_tol, double box[4])
{
    if (m == 3 && n == 3)
        return clip_step(net, 3, 3, zero_tol, box);
    if (m == 2 && n == 2)
        return clip_step(net, 2, 2, zero_tol, box);
    return clip_step(net, m, n, zero_tol, box);
}

int pc_bezier_clip_is_sliver(const double *net, int m, int n, double width)
{
    const size_t row = (size_t)(m + 1), np = row * (size_t)(n + 1);
    const double *p00 = net, *p10 = net + 2 * (size_t)m;
    const double *p01 = net + 2 * (size_t)n * row, *p11 = p01 + 2 * (size_t)m;
    const double a[2] = {p10[0] - p00[0] + p11[0] - p01[0], p10[1] - p00[1] + p11[1] - p01[1]};
    const double b[2] = {p01[0] - p00[0] + p11[0] - p10[0], p01[1] - p00[1] + p11[1] - p10[1]};
    const double la = a[0] * a[0] + a[1] * a[1], lb = b[0] * b[0] + b[1] * b[1];
    const double *e = la >= lb ? a : b;
    const double len = sqrt(la >= lb ? la : lb);
    if (!(len > 0.0))
        return 0;
    const double normal[2] = {-e[1] / len, e[0] / len};
    double lo = INFINITY, hi = -INFINITY;
    for (size_t k = 0; k < np; ++k) {
        const double f = normal[0] * net[2 * k] + normal[1] * net[2 * k + 1];
        lo = min2(lo, f);
        hi = max2(hi, f);
    }
    return hi - lo <= width && lo <= width && hi >= -width;
}

void pc_bezier_clip_restrict(double *net, int m, int n, const double box[4])
{
    const net_view vs = view_along(m, n, 0), vt = view_along(m, n, 1);
    if (box[0] > 0.0 || box[1] < 1.0)
        restrict_net(net, &vs, box[0], box[1]);
    if (box[2] > 0.0 || box[3] < 1.0)
        restrict_net(net, &vt, box[2], box[3]);
}

void pc_bezier_clip_split(double *net, double *other_net, int m, int n, int dir, double box[4],
                          double other_box[4])
{
    const size_t n_values = 2 * (size_t)(m + 1) * (size_t)(n + 1);
    memcpy(other_net, net, n_values * sizeof *net);
    memcpy(other_box, box, 4 * sizeof *box);
    const net_view v = view_along(m, n, dir);
    restrict_net(net, &v, 0.0, 0.5);
    restrict_net(other_net, &v, 0.5, 1.0);
    const double mid = 0.5 * (box[2 * dir] + box[2 * dir + 1]);
    box[2 * dir + 1] = mid;
    other_box[2 * dir] = mid;
}
