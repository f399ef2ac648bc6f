/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES entities 100, 102, 110, 124, 126 and 128 as raw splines.
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* 124 entities may point at further 124 entities; longer chains than this
 * are taken as a cycle. */
#define PC_IGES_MAX_TRANSFORM_CHAIN 16
/* Composite curve members must meet to this fraction of their size. */
#define PC_IGES_JOIN_REL_GAP 1e-6
/* Start and end of an arc closer than this fraction of the radius make a
 * full circle (IGES 5.3 s4.3). */
#define PC_IGES_ARC_CLOSED_REL 1e-12

static projcurve_status need(const pc_iges_params *p, size_t required)
{
    if (p->count >= required)
        return PROJCURVE_OK;
    return pc_fail(p->file->ctx, PROJCURVE_ERR_PARSE,
                   "IGES entity %d at DE %zu: %zu parameters, but its counts require %zu",
                   p->type, p->de, p->count - 1, required - 1);
}

static double *alloc_doubles(const pc_iges_file *f, size_t n)
{
    return pc_arena_calloc(f->arena, n ? n : 1, sizeof(double));
}

/* The transformation of the entity at de (identity without field 7), with
 * the chain of 124 entities composed. */
static projcurve_status transform_of(const pc_iges_file *f, size_t de, pc_io_affine *out)
{
    pc_io_affine_identity(out);
    const pc_iges_entry *e = pc_iges_entry_at(f, (long)de, de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    long next = e->transform;
    for (int depth = 0; next != 0; ++depth) {
        if (depth >= PC_IGES_MAX_TRANSFORM_CHAIN)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES entity at DE %zu: more than %d chained transformations (a cycle?)",
                           de, PC_IGES_MAX_TRANSFORM_CHAIN);
        const pc_iges_entry *t = pc_iges_entry_at(f, next, de);
        if (t == NULL)
            return PROJCURVE_ERR_PARSE;
        if (t->type != 124)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES entity at DE %zu: transformation pointer %ld is entity %d, not 124",
                           de, next, t->type);
        pc_iges_params p;
        projcurve_status st = pc_iges_params_of(f, (size_t)next, &p);
        if (st != PROJCURVE_OK)
            return st;
        pc_io_affine m;
        if ((st = need(&p, 13)) != PROJCURVE_OK || (st = pc_iges_reals(&p, 1, 12, m.m)) != PROJCURVE_OK)
            return st;
        /* The matrices found so far act first, the one they point to after. */
        *out = pc_io_affine_compose(&m, out);
        next = t->transform;
    }
    return PROJCURVE_OK;
}

/* Reads a count that must lie in [lo, hi]. */
static projcurve_status count_param(const pc_iges_params *p, size_t i, long lo, long hi,
                                    const char *what, long *out)
{
    projcurve_status st = pc_iges_int(p, i, out);
    if (st != PROJCURVE_OK)
        return st;
    if (*out < lo || *out > hi)
        return pc_fail(p->file->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: %s = %ld is outside [%ld, %ld]", p->type, p->de,
                       what, *out, lo, hi);
    return PROJCURVE_OK;
}

static projcurve_status read_126(const pc_iges_params *p, pc_io_curve *out)
{
    const pc_iges_file *f = p->file;
    const long max = (long)p->count;
    long k, m;
    projcurve_status st;
    if ((st = count_param(p, 2, 1, PROJCURVE_MAX_DEGREE, "degree M", &m)) != PROJCURVE_OK ||
        (st = count_param(p, 1, m, max, "upper index K", &k)) != PROJCURVE_OK)
        return st;
    const size_t n = (size_t)k + 1, nk = (size_t)(k + m) + 2;
    const size_t base = 7;
    if ((st = need(p, base + nk + 4 * n + 2)) != PROJCURVE_OK)
        return st;
    out->degree = (int)m;
    out->n_ctrl = n;
    out->knots = alloc_doubles(f, nk);
    out->weights = alloc_doubles(f, n);
    out->ctrl = alloc_doubles(f, 3 * n);
    if (out->knots == NULL || out->weights == NULL || out->ctrl == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES entity 126");
    if ((st = pc_iges_reals(p, base, nk, out->knots)) != PROJCURVE_OK ||
        (st = pc_iges_reals(p, base + nk, n, out->weights)) != PROJCURVE_OK ||
        (st = pc_iges_reals(p, base + nk + n, 3 * n, out->ctrl)) != PROJCURVE_OK)
        return st;
    double v[2];
    if ((st = pc_iges_reals(p, base + nk + 4 * n, 2, v)) != PROJCURVE_OK)
        return st;
    /* V0, V1 may select a part of the knot domain: cut it out exactly. */
    double t0 = out->knots[m], t1 = out->knots[n];
    for (size_t i = 0; i + 1 < nk; ++i)
        if (!(out->knots[i] <= out->knots[i + 1]))
            return PROJCURVE_OK; /* creation reports the bad knots with their index */
    const double a = v[0] > t0 ? v[0] : t0, b = v[1] < t1 ? v[1] : t1;
    if (a < b && (a > t0 || b < t1))
        return pc_io_curve_restrict(f->ctx, f->arena, out, a, b, out);
    return PROJCURVE_OK;
}

static projcurve_status read_110(const pc_iges_params *p, pc_io_curve *out,
                                 const char **skip_reason)
{
    const pc_iges_entry *e = pc_iges_entry_at(p->file, (long)p->de, p->de);
    if (e != NULL && e->form != 0) {
        *skip_reason = "unbounded line (form 1 or 2)";
        return PROJCURVE_OK;
    }
    double x[6];
    projcurve_status st = pc_iges_reals(p, 1, 6, x);
    if (st != PROJCURVE_OK)
        return st;
    return pc_io_line_curve(p->file->ctx, p->file->arena, x, x + 3, out);
}

static projcurve_status read_100(const pc_iges_params *p, pc_io_curve *out,
                                 const char **skip_reason)
{
    double x[7];
    projcurve_status st = pc_iges_reals(p, 1, 7, x);
    if (st != PROJCURVE_OK)
        return st;
    const double centre[3] = {x[1], x[2], x[0]};
    const double dxs = x[3] - x[1], dys = x[4] - x[2], dxe = x[5] - x[1], dye = x[6] - x[2];
    const double r = hypot(dxs, dys);
    if (!(r > 0.0) || !isfinite(r)) {
        *skip_reason = "arc of zero radius";
        return PROJCURVE_OK;
    }
    const double a0 = atan2(dys, dxs);
    double a1 = atan2(dye, dxe);
    if (hypot(x[5] - x[3], x[6] - x[4]) <= PC_IGES_ARC_CLOSED_REL * r)
        a1 = a0 + 2.0 * M_PI;
    while (a1 <= a0)
        a1 += 2.0 * M_PI;
    const double ex[3] = {1.0, 0.0, 0.0}, ey[3] = {0.0, 1.0, 0.0};
    return pc_io_arc_curve(p->file->ctx, p->file->arena, centre, ex, ey, r, a0, a1, out);
}

/* A curve entity in its own coordinates, its transformation then applied. */
static projcurve_status simple_curve(const pc_iges_file *f, size_t de, pc_io_curve *out,
                                     const char **skip_reason)
{
    pc_iges_params p;
    projcurve_status st = pc_iges_params_of(f, de, &p);
    if (st != PROJCURVE_OK)
        return st;
    *skip_reason = NULL;
    switch (p.type) {
    case 126: st = read_126(&p, out); break;
    case 110: st = read_110(&p, out, skip_reason); break;
    case 100: st = read_100(&p, out, skip_reason); break;
    default: *skip_reason = "a component of unsupported type"; return PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK || *skip_reason != NULL)
        return st;
    pc_io_affine t;
    if ((st = transform_of(f, de, &t)) != PROJCURVE_OK)
        return st;
    pc_io_affine_points(&t, out->ctrl, out->n_ctrl);
    return PROJCURVE_OK;
}

static double max_abs_coordinate(const pc_io_curve *parts, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < 3 * parts[i].n_ctrl; ++k)
            m = fmax(m, fabs(parts[i].ctrl[k]));
    return m;
}

static projcurve_status read_102(const pc_iges_file *f, size_t de, pc_io_curve *out,
                                 const char **skip_reason)
{
    pc_iges_params p;
    projcurve_status st = pc_iges_params_of(f, de, &p);
    long n;
    if (st != PROJCURVE_OK ||
        (st = count_param(&p, 1, 1, (long)p.count, "number of curves N", &n)) != PROJCURVE_OK ||
        (st = need(&p, 2 + (size_t)n)) != PROJCURVE_OK)
        return st;
    pc_io_curve *parts = pc_arena_calloc(f->arena, (size_t)n, sizeof *parts);
    if (parts == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES entity 102");
    for (size_t i = 0; i < (size_t)n; ++i) {
        long member;
        if ((st = pc_iges_int(&p, 2 + i, &member)) != PROJCURVE_OK)
            return st;
        const pc_iges_entry *e = pc_iges_entry_at(f, member, de);
        if (e == NULL)
            return PROJCURVE_ERR_PARSE;
        if (e->type == 102) {
            *skip_reason = "a composite curve inside a composite curve";
            return PROJCURVE_OK;
        }
        if ((st = simple_curve(f, (size_t)member, &parts[i], skip_reason)) != PROJCURVE_OK ||
            *skip_reason != NULL)
            return st;
    }
    const double gap_tol = PC_IGES_JOIN_REL_GAP * (1.0 + max_abs_coordinate(parts, (size_t)n));
    st = pc_io_curve_join(f->ctx, f->arena, parts, (size_t)n, gap_tol, out);
    if (st == PROJCURVE_ERR_INVALID_ARGUMENT || st == PROJCURVE_ERR_UNSUPPORTED) {
        *skip_reason = st == PROJCURVE_ERR_INVALID_ARGUMENT
                           ? "its curves do not connect end to start"
                           : "its curves have too many knots to join";
        return PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK)
        return st;
    pc_io_affine t;
    if ((st = transform_of(f, de, &t)) != PROJCURVE_OK)
        return st;
    pc_io_affine_points(&t, out->ctrl, out->n_ctrl);
    return PROJCURVE_OK;
}

projcurve_status pc_iges_curve(const pc_iges_file *f, size_t de, pc_io_curve *out,
                               const char **skip_reason)
{
    *skip_reason = NULL;
    const pc_iges_entry *e = pc_iges_entry_at(f, (long)de, de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    if (e->type == 102)
        return read_102(f, de, out, skip_reason);
    return simple_curve(f, de, out, skip_reason);
}

projcurve_status pc_iges_surface(const pc_iges_file *f, size_t de, pc_io_surface *out)
{
    pc_iges_params p;
    projcurve_status st = pc_iges_params_of(f, de, &p);
    if (st != PROJCURVE_OK)
        return st;
    const long max = (long)p.count;
    long k1, k2, m1, m2;
    if ((st = count_param(&p, 3, 1, PROJCURVE_MAX_DEGREE, "degree M1", &m1)) != PROJCURVE_OK ||
        (st = count_param(&p, 4, 1, PROJCURVE_MAX_DEGREE, "degree M2", &m2)) != PROJCURVE_OK ||
        (st = count_param(&p, 1, m1, max, "upper index K1", &k1)) != PROJCURVE_OK ||
        (st = count_param(&p, 2, m2, max, "upper index K2", &k2)) != PROJCURVE_OK)
        return st;
    const size_t n_u = (size_t)k1 + 1, n_v = (size_t)k2 + 1;
    const size_t nk_u = (size_t)(k1 + m1) + 2, nk_v = (size_t)(k2 + m2) + 2;
    /* n_u, n_v < p.count (a file length), so the product cannot overflow. */
    const size_t n = n_u * n_v, base = 10;
    if ((st = need(&p, base + nk_u + nk_v + 4 * n + 4)) != PROJCURVE_OK)
        return st;
    out->deg_u = (int)m1;
    out->deg_v = (int)m2;
    out->n_u = n_u;
    out->n_v = n_v;
    out->knots_u = alloc_doubles(f, nk_u);
    out->knots_v = alloc_doubles(f, nk_v);
    out->weights = alloc_doubles(f, n);
    out->ctrl = alloc_doubles(f, 3 * n);
    if (out->knots_u == NULL || out->knots_v == NULL || out->weights == NULL || out->ctrl == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES entity 128");
    if ((st = pc_iges_reals(&p, base, nk_u, out->knots_u)) != PROJCURVE_OK ||
        (st = pc_iges_reals(&p, base + nk_u, nk_v, out->knots_v)) != PROJCURVE_OK ||
        (st = pc_iges_reals(&p, base + nk_u + nk_v, n, out->weights)) != PROJCURVE_OK ||
        (st = pc_iges_reals(&p, base + nk_u + nk_v + n, 3 * n, out->ctrl)) != PROJCURVE_OK)
        return st;
    /* U0, U1, V0, V1 may select a part of the knot domain (writers extend
     * surfaces a little beyond their use): cut it out exactly. */
    double dom[4];
    if ((st = pc_iges_reals(&p, base + nk_u + nk_v + 4 * n, 4, dom)) != PROJCURVE_OK ||
        (st = pc_io_surface_restrict(f->ctx, f->arena, out, dom[0], dom[1], dom[2], dom[3],
                                     out)) != PROJCURVE_OK)
        return st;
    pc_io_affine t;
    if ((st = transform_of(f, de, &t)) != PROJCURVE_OK)
        return st;
    pc_io_affine_points(&t, out->ctrl, out->n_u * out->n_v);
    return PROJCURVE_OK;
}

projcurve_status pc_iges_transform(const pc_iges_file *f, size_t de, pc_io_affine *out)
{
    return transform_of(f, de, out);
}
