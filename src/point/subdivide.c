/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier patch subdivision walk and the culling tests used by point
 * projection.
 */
#include "point/subdivide.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bezier/net.h"
#include "common/error.h"

/* Depth-first: a split pops one net and pushes four for 2 levels of depth
 * (or two for 1), so the stack never holds more than 3 * depth / 2 + 1
 * nets; 2 more are scratch for the split. */
#define PC_SUBDIV_STACK (3 * PC_SUBDIV_MAX_DEPTH / 2 + 1)
#define PC_SUBDIV_SCRATCH 2

projcurve_status pc_subdiv_work_init(projcurve_context *ctx, pc_subdiv_work *w, int p, int q)
{
    w->p = p;
    w->q = q;
    w->net_len = 4 * ((size_t)p + 1) * ((size_t)q + 1);
    w->n_slots = PC_SUBDIV_STACK + PC_SUBDIV_SCRATCH;
    /* + 3/4 net for the Cartesian points of the current sub-patch. */
    const size_t n_doubles = (w->n_slots + 1) * w->net_len;
    w->mem = n_doubles <= PC_SUBDIV_LOCAL ? w->local : malloc(n_doubles * sizeof(double));
    if (w->mem == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for patch subdivision");
    return PROJCURVE_OK;
}

void pc_subdiv_work_free(pc_subdiv_work *w)
{
    if (w->mem != w->local)
        free(w->mem);
    w->mem = NULL;
}

#if defined(__GNUC__)
#define SPLIT_INLINE inline __attribute__((always_inline))
#else
#define SPLIT_INLINE inline
#endif

/* de Casteljau at 1/2 of `count` homogeneous points spaced `stride`
 * doubles apart, into lo and hi (same spacing). */
static SPLIT_INLINE void split_line_n(const double *src, size_t count, size_t stride,
                                      double *lo, double *hi)
{
    double tmp[PC_MAX_ORDER][4];
    for (size_t i = 0; i < count; ++i)
        memcpy(tmp[i], src + i * stride, 4 * sizeof(double));
    const size_t last = count - 1;
    for (size_t r = 0; r <= last; ++r) {
        memcpy(lo + r * stride, tmp[0], 4 * sizeof(double));
        memcpy(hi + (last - r) * stride, tmp[last - r], 4 * sizeof(double));
        for (size_t i = 0; i + r < last; ++i)
            for (int m = 0; m < 4; ++m)
                tmp[i][m] = 0.5 * (tmp[i][m] + tmp[i + 1][m]);
    }
}

/* The usual degrees get a constant count, for which the compiler unrolls
 * the triangle and keeps it in registers. */
static void split_line(const double *src, size_t count, size_t stride, double *lo, double *hi)
{
    switch (count) {
    case 2: split_line_n(src, 2, stride, lo, hi); break;
    case 3: split_line_n(src, 3, stride, lo, hi); break;
    case 4: split_line_n(src, 4, stride, lo, hi); break;
    case 6: split_line_n(src, 6, stride, lo, hi); break;
    default: split_line_n(src, count, stride, lo, hi); break;
    }
}

/* Cartesian points and box of a net whose weights are all 1 (the
 * sub-patches of a polynomial patch: halving keeps the weights 1 exactly):
 * the same values as pc_bezier_net_cartesian, without its per-point test. */
static void cartesian_polynomial(const double *cw, size_t n, double *xyz, double box[6])
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < 3; ++k) {
            const double x = cw[4 * i + k];
            xyz[3 * i + k] = x;
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
    for (int k = 0; k < 3; ++k) {
        box[k] = lo[k];
        box[k + 3] = hi[k];
    }
}

static void split_u(const double *net, int p, int q, double *left, double *right)
{
    const size_t row = 4 * ((size_t)p + 1);
    for (size_t j = 0; j <= (size_t)q; ++j)
        split_line(net + j * row, (size_t)p + 1, 4, left + j * row, right + j * row);
}

static void split_v(const double *net, int p, int q, double *bottom, double *top)
{
    const size_t row = 4 * ((size_t)p + 1);
    for (size_t i = 0; i <= (size_t)p; ++i)
        split_line(net + 4 * i, (size_t)q + 1, row, bottom + 4 * i, top + 4 * i);
}

/* Longest control polygon of the net (Cartesian points xyz) along u
 * (along_v == 0) or v: the 3D extent of the sub-patch that way. */
static double net_extent(const double *xyz, int p, int q, int along_v)
{
    const size_t n_u = (size_t)p + 1;
    const size_t n_lines = along_v ? (size_t)p + 1 : (size_t)q + 1;
    const size_t n_steps = along_v ? (size_t)q : (size_t)p;
    double longest = 0.0;
    for (size_t a = 0; a < n_lines; ++a) {
        double len = 0.0;
        for (size_t k = 0; k < n_steps; ++k) {
            const size_t i0 = along_v ? k * n_u + a : a * n_u + k;
            const size_t i1 = along_v ? (k + 1) * n_u + a : a * n_u + k + 1;
            const double dx = xyz[3 * i1] - xyz[3 * i0], dy = xyz[3 * i1 + 1] - xyz[3 * i0 + 1],
                         dz = xyz[3 * i1 + 2] - xyz[3 * i0 + 2];
            len += sqrt(dx * dx + dy * dy + dz * dz);
        }
        longest = len > longest ? len : longest;
    }
    return longest;
}

/* Which directions a split halves: 1 u only, 2 v only, 3 both. */
static int split_directions(const double *xyz, int p, int q)
{
    const double eu = net_extent(xyz, p, q, 0), ev = net_extent(xyz, p, q, 1);
    if (eu > PC_SUBDIV_ANISOTROPY * ev)
        return 1;
    if (ev > PC_SUBDIV_ANISOTROPY * eu)
        return 2;
    return 3;
}

typedef struct stack_item {
    double u0, u1, v0, v1;
    int depth;
} stack_item;

void pc_subdiv_walk(pc_subdiv_work *w, const pc_bezier_patch *patch, pc_subdiv_fn decide,
                    void *user)
{
    const size_t len = w->net_len, n_pts = len / 4;
    double *slot0 = w->mem;                              /* stack nets */
    double *scratch = w->mem + PC_SUBDIV_STACK * len;    /* 2 half nets of a split */
    double *xyz = w->mem + w->n_slots * len;             /* current Cartesian points */
    stack_item items[PC_SUBDIV_STACK];
    size_t top = 0;
    int polynomial = 1;
    for (size_t i = 0; i < n_pts; ++i)
        polynomial &= patch->cw[4 * i + 3] == 1.0;
    items[top++] = (stack_item){patch->u0, patch->u1, patch->v0, patch->v1, 0};
    while (top > 0) {
        const stack_item it = items[--top];
        /* The patch itself is read where the grid keeps it, with its
         * Cartesian net, box and flatness; sub-patches from their slots. */
        const int root = it.depth == 0;
        double *slot = slot0 + top * len;
        const double *net = root ? patch->cw : slot;
        pc_subpatch sp = {it.u0, it.u1, it.v0, it.v1, it.depth, net, root ? patch->xyz : xyz,
                          {0}, root ? patch->flatness : -1.0};
        if (root)
            memcpy(sp.box, patch->box, sizeof sp.box);
        else if (polynomial)
            cartesian_polynomial(net, n_pts, xyz, sp.box);
        else
            pc_bezier_net_cartesian(net, n_pts, xyz, sp.box);
        const pc_subdiv_action action = decide(user, &sp);
        if (action != PC_SUBDIV_SPLIT || it.depth >= PC_SUBDIV_MAX_DEPTH)
            continue;
        int dirs = split_directions(sp.xyz, w->p, w->q);
        if (dirs == 3 && it.depth + 2 > PC_SUBDIV_MAX_DEPTH)
            continue;
        /* The halves go straight to the slots top, top + 1, ... (the first
         * overwrites the parent, which the first split has consumed by
         * then). */
        double *left = scratch, *right = scratch + len;
        const double um = 0.5 * (it.u0 + it.u1), vm = 0.5 * (it.v0 + it.v1);
        if (dirs == 1) {
            split_u(net, w->p, w->q, left, right);
            memcpy(slot, left, len * sizeof *slot);
            memcpy(slot + len, right, len * sizeof *slot);
            items[top++] = (stack_item){it.u0, um, it.v0, it.v1, it.depth + 1};
            items[top++] = (stack_item){um, it.u1, it.v0, it.v1, it.depth + 1};
        } else if (dirs == 2) {
            split_v(net, w->p, w->q, left, right);
            memcpy(slot, left, len * sizeof *slot);
            memcpy(slot + len, right, len * sizeof *slot);
            items[top++] = (stack_item){it.u0, it.u1, it.v0, vm, it.depth + 1};
            items[top++] = (stack_item){it.u0, it.u1, vm, it.v1, it.depth + 1};
        } else {
            split_u(net, w->p, w->q, left, right);
            split_v(left, w->p, w->q, slot, slot + len);
            split_v(right, w->p, w->q, slot + 2 * len, slot + 3 * len);
            items[top++] = (stack_item){it.u0, um, it.v0, vm, it.depth + 2};
            items[top++] = (stack_item){it.u0, um, vm, it.v1, it.depth + 2};
            items[top++] = (stack_item){um, it.u1, it.v0, vm, it.depth + 2};
            items[top++] = (stack_item){um, it.u1, vm, it.v1, it.depth + 2};
        }
    }
}

double pc_box_distance_sq(const double box[6], pc_vec3 p)
{
    const double pp[3] = {p.x, p.y, p.z};
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double e = pp[k] < box[k] ? box[k] - pp[k] : (pp[k] > box[k + 3] ? pp[k] - box[k + 3] : 0.0);
        d2 += e * e;
    }
    return d2;
}

/* Sign of x.d over every x in the box [lo, hi]: +1 if always > 0, -1 if
 * always < 0, 0 otherwise. */
static int sign_over_box(const double lo[3], const double hi[3], const double d[3])
{
    double mn = 0.0, mx = 0.0;
    for (int k = 0; k < 3; ++k) {
        mn += d[k] >= 0.0 ? d[k] * lo[k] : d[k] * hi[k];
        mx += d[k] >= 0.0 ? d[k] * hi[k] : d[k] * lo[k];
    }
    return mn > 0.0 ? 1 : (mx < 0.0 ? -1 : 0);
}

/* Polynomial patches: can (S - p).S_dir vanish? S_dir is a positive
 * combination of the differences of control points adjacent in that
 * direction (the hodograph), and S - p lies in the box of the control points
 * minus p. If every difference has a dot product of one strict sign with
 * the whole box, so has S_dir. */
static int may_vanish_polynomial(const pc_subpatch *sp, int p, int q, const double lo[3],
                                 const double hi[3], int along_v)
{
    const size_t n_u = (size_t)p + 1;
    const size_t n_lines = along_v ? (size_t)p + 1 : (size_t)q + 1;
    const size_t n_steps = along_v ? (size_t)q : (size_t)p;
    int sign = 2; /* not yet known */
    for (size_t k = 0; k < n_steps; ++k)
        for (size_t a = 0; a < n_lines; ++a) {
            const size_t i0 = along_v ? k * n_u + a : a * n_u + k;
            const size_t i1 = along_v ? (k + 1) * n_u + a : a * n_u + k + 1;
            const double d[3] = {sp->xyz[3 * i1] - sp->xyz[3 * i0],
                                 sp->xyz[3 * i1 + 1] - sp->xyz[3 * i0 + 1],
                                 sp->xyz[3 * i1 + 2] - sp->xyz[3 * i0 + 2]};
            const int s = sign_over_box(lo, hi, d);
            if (s == 0 || (sign != 2 && s != sign))
                return 1;
            sign = s;
        }
    return 0;
}

/* Closed intervals for the rational test. */
typedef struct interval {
    double lo, hi;
} interval;

/* Plain comparisons instead of fmin / fmax: the operands are finite, and
 * the libm calls (NaN semantics) took half the time of the rational test. */
static inline double dmin(double a, double b) { return a < b ? a : b; }
static inline double dmax(double a, double b) { return a > b ? a : b; }

static interval iv_mul(interval a, interval b)
{
    const double c0 = a.lo * b.lo, c1 = a.lo * b.hi, c2 = a.hi * b.lo, c3 = a.hi * b.hi;
    return (interval){dmin(dmin(c0, c1), dmin(c2, c3)), dmax(dmax(c0, c1), dmax(c2, c3))};
}

static interval iv_add(interval a, interval b) { return (interval){a.lo + b.lo, a.hi + b.hi}; }

static interval iv_sq(interval a)
{
    const double l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.lo <= 0.0 && a.hi >= 0.0)
        return (interval){0.0, dmax(l, h)};
    return (interval){dmin(l, h), dmax(l, h)};
}

static void iv_include(interval *r, double x)
{
    r->lo = dmin(r->lo, x);
    r->hi = dmax(r->hi, x);
}

/* Rational patches: with B = A - p w (homogeneous, a polynomial patch),
 * S - p = B / w and (S - p).S_dir = (w (B.B_dir) - w_dir |B|^2) / w^3. The
 * numerator is bounded with interval arithmetic from the boxes of the
 * Bernstein coefficients of B, w and of their hodographs; its width shrinks
 * linearly with the sub-patch, so deep sub-patches away from foot points are
 * discarded (a cone of control point differences would not shrink: for
 * rational nets it must include differences across rows). The boxes of B
 * and w serve both directions: one pass over the net. */
static int may_vanish_rational(const pc_subpatch *sp, int p, int q, pc_vec3 pt)
{
    const size_t n_u = (size_t)p + 1, n = n_u * ((size_t)q + 1);
    const double pp[3] = {pt.x, pt.y, pt.z};
    interval b[3], bd[2][3], w = {INFINITY, -INFINITY}, wd[2];
    for (int k = 0; k < 3; ++k)
        b[k] = bd[0][k] = bd[1][k] = (interval){INFINITY, -INFINITY};
    wd[0] = wd[1] = w;
    for (size_t i = 0; i < n; ++i) {
        const double *h = sp->cw + 4 * i;
        const double bi[3] = {h[0] - pp[0] * h[3], h[1] - pp[1] * h[3], h[2] - pp[2] * h[3]};
        for (int k = 0; k < 3; ++k)
            iv_include(&b[k], bi[k]);
        iv_include(&w, h[3]);
        const size_t col = i % n_u, row = i / n_u;
        for (int dir = 0; dir < 2; ++dir) {
            if (dir ? row == (size_t)q : col == (size_t)p)
                continue;
            const double *h1 = h + 4 * (dir ? n_u : 1); /* next point along dir */
            for (int k = 0; k < 3; ++k)
                iv_include(&bd[dir][k], (h1[k] - pp[k] * h1[3]) - bi[k]);
            iv_include(&wd[dir], h1[3] - h[3]);
        }
    }
    /* The hodograph's degree factor is a positive constant: signs only. */
    interval norm2 = {0.0, 0.0};
    for (int k = 0; k < 3; ++k)
        norm2 = iv_add(norm2, iv_sq(b[k]));
    for (int dir = 0; dir < 2; ++dir) {
        interval dot = {0.0, 0.0};
        for (int k = 0; k < 3; ++k)
            dot = iv_add(dot, iv_mul(b[k], bd[dir][k]));
        const interval first = iv_mul(w, dot), second = iv_mul(wd[dir], norm2);
        const interval num = {first.lo - second.hi, first.hi - second.lo};
        if (num.lo > 0.0 || num.hi < 0.0)
            return 0;
    }
    return 1;
}

int pc_subpatch_may_hold_foot(const pc_subpatch *sp, int p, int q, int rational, pc_vec3 pt)
{
    if (rational)
        return may_vanish_rational(sp, p, q, pt);
    const double lo[3] = {sp->box[0] - pt.x, sp->box[1] - pt.y, sp->box[2] - pt.z};
    const double hi[3] = {sp->box[3] - pt.x, sp->box[4] - pt.y, sp->box[5] - pt.z};
    return may_vanish_polynomial(sp, p, q, lo, hi, 0) && may_vanish_polynomial(sp, p, q, lo, hi, 1);
}

double pc_subpatch_flatness(const pc_subpatch *sp, int p, int q)
{
    return sp->flatness >= 0.0 ? sp->flatness : pc_bezier_net_flatness(sp->xyz, p, q, sp->box);
}
