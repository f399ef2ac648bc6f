/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/adaptive.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/budget.h"
#include "common/error.h"
#include "fit/lsq.h"

/* Spans cut per round: at least in two, at most in this many. */
#define PC_FIT_MAX_SPLIT 8
/* Samples per pole a fit uses at most: beyond, every k-th (straight
 * pieces at a tight eps_D give tens of thousands of piece ends for a few
 * hundred poles; the check, not the samples, decides). */
#define PC_FIT_SAMPLES_PER_POLE 16
/* Samples each span needs before a fit: at least this many, and together
 * twice the poles (least squares, not interpolation). */
#define PC_FIT_MIN_PER_SPAN 4
/* Neighbouring spans differ in width by at most about this factor. */
#define PC_FIT_GRADE 4.0
/* A span narrower than this fraction of the branch is not cut: the curve
 * parameter's rounding. */
#define PC_FIT_MIN_SPAN_REL 1e-10

/* The check points of one span [a, b], PC_FIT_CHECK_PER_SPAN samples of
 * the check cache from `first`: a span the fit has not cut keeps them, so
 * a later check measures the new spline there without new exact points. */
typedef struct check_block {
    double a, b;
    size_t first;
} check_block;

/* Working state of one fit. */
typedef struct fit_state {
    projcurve_context *ctx;
    pc_fit_branch *fb;
    const pc_fit_goal *goal;
    const double *weights;
    pc_fit_samples *data;
    double *knots;    /* n_knots, malloc'd */
    size_t n_knots, n_poles;
    double *poles;    /* n_poles * dim */
    double *brk;      /* distinct knot values of the domain, n_brk */
    size_t n_brk;
    double *err;      /* worst distance per span (n_brk - 1) */
    pc_fit_samples cache; /* check points, in blocks (never sorted) */
    check_block *blocks;
    size_t n_blocks, cap_blocks;
    pc_lsq_rows rows; /* the basis at the fitted samples, for the solve and the error pass */
} fit_state;

static pc_lsq_space space_of(const fit_state *f)
{
    const pc_lsq_space sp = {f->goal->degree, f->n_poles, f->knots, f->weights};
    return sp;
}

/* The distance of the spline from sample x at x's t; for a pcurve S at
 * it, evaluated when `exact`, else to first order, |Su du + Sv dv| with
 * (du, dv) its offset from q(t): the error of that is of the order of
 * |S''| |dq|^2, far below eps_D where the fit is near, and knots are only
 * placed by it (the check, which accepts, evaluates S). */
static double distance_of(const fit_state *f, const pc_fit_sample *x, const double c[3], int exact)
{
    double y[3] = {c[0], c[1], c[2]};
    if (f->goal->dim == 2 && exact) {
        pc_fit_surface_point(f->fb, c, y);
    } else if (f->goal->dim == 2) {
        const double du = c[0] - x->uv[0], dv = c[1] - x->uv[1];
        for (int k = 0; k < 3; ++k)
            y[k] = x->x[k] + x->su[k] * du + x->sv[k] * dv;
    }
    const double d[3] = {y[0] - x->x[0], y[1] - x->x[1], y[2] - x->x[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static double distance(fit_state *f, const pc_fit_sample *x, size_t *hint, int exact)
{
    const pc_lsq_space sp = space_of(f);
    double c[3];
    pc_lsq_eval(&sp, f->goal->dim, f->poles, x->t, hint, c);
    return distance_of(f, x, c, exact);
}

/* The span (index into brk) holding t. */
static size_t span_of(const fit_state *f, double t)
{
    size_t lo = 0, hi = f->n_brk - 1; /* answer in [lo, hi) */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (f->brk[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static projcurve_status rebuild_breaks(fit_state *f)
{
    const int p = f->goal->degree;
    f->n_poles = f->n_knots - (size_t)p - 1;
    free(f->brk);
    free(f->err);
    free(f->poles);
    f->brk = malloc((f->n_poles + 1) * sizeof *f->brk);
    f->err = malloc((f->n_poles + 1) * sizeof *f->err);
    f->poles = malloc(f->n_poles * (size_t)f->goal->dim * sizeof *f->poles);
    if (f->brk == NULL || f->err == NULL || f->poles == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
    f->n_brk = 0;
    for (size_t k = (size_t)p; k <= f->n_poles; ++k)
        if (f->n_brk == 0 || f->knots[k] > f->brk[f->n_brk - 1])
            f->brk[f->n_brk++] = f->knots[k];
    return PROJCURVE_OK;
}

/* Adds exact samples to the spans that hold too few for a fit. Returns OK
 * with *ok 0 when an exact point could not be had. */
static projcurve_status fill_spans(fit_state *f, int *ok)
{
    const size_t spans = f->n_brk - 1;
    size_t need = (2 * f->n_poles + spans - 1) / spans;
    need = need < PC_FIT_MIN_PER_SPAN ? PC_FIT_MIN_PER_SPAN : need;
    size_t i = 0;
    projcurve_status st = PROJCURVE_OK;
    const size_t n_data = f->data->count; /* the samples added go at the end */
    for (size_t j = 0; st == PROJCURVE_OK && j < spans; ++j) {
        const double a = f->brk[j], b = f->brk[j + 1];
        size_t have = 0;
        while (i < n_data && f->data->items[i].t < b) {
            have += f->data->items[i].t > a;
            ++i;
        }
        for (size_t k = have; st == PROJCURVE_OK && k < need; ++k) {
            pc_fit_sample x;
            if (!pc_fit_exact(f->fb, a + (b - a) * (double)(k - have + 1) /
                                         (double)(need - have + 1), &x)) {
                *ok = 0;
                return PROJCURVE_OK;
            }
            st = pc_fit_samples_push(f->ctx, f->data, &x);
        }
    }
    pc_fit_samples_sort(f->data);
    return st;
}

/* Index of a sample at exactly t, or (size_t)-1. */
static size_t sample_at(const pc_fit_samples *s, double t)
{
    size_t lo = 0, hi = s->count;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (s->items[mid].t < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < s->count && s->items[lo].t == t ? lo : (size_t)-1;
}

/* The stride through the samples of a fit and an error pass. */
static size_t sample_stride(const fit_state *f)
{
    const size_t most = PC_FIT_SAMPLES_PER_POLE * f->n_poles;
    return f->data->count > most ? f->data->count / most : 1;
}

static const double *sample_coords(const fit_state *f, const pc_fit_sample *x)
{
    return f->goal->dim == 2 ? x->uv : x->x;
}

/* The least-squares poles, the ends (and the poles at C0 knots, which the
 * curve passes through) held at their exact points. */
static projcurve_status solve(fit_state *f)
{
    const int p = f->goal->degree;
    const size_t dim = (size_t)f->goal->dim;
    size_t n_fixed = 0;
    size_t *idx = malloc(f->n_brk * sizeof *idx);
    double *val = malloc(f->n_brk * dim * sizeof *val);
    if (idx == NULL || val == NULL) {
        free(idx);
        free(val);
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
    }
    size_t k = (size_t)p + 1; /* knot index of the first interior knot */
    for (size_t j = 0; j < f->n_brk; ++j) {
        size_t pole = (size_t)-1;
        const double t = f->brk[j];
        if (j == 0) {
            pole = 0;
        } else if (j + 1 == f->n_brk) {
            pole = f->n_poles - 1;
        } else {
            size_t mult = 0;
            while (k + mult < f->n_poles && f->knots[k + mult] == t)
                ++mult;
            if (mult == (size_t)p)
                pole = k - 1;
            k += mult;
        }
        const size_t at = pole == (size_t)-1 ? pole : sample_at(f->data, t);
        if (at != (size_t)-1) {
            idx[n_fixed] = pole;
            memcpy(val + n_fixed * dim, sample_coords(f, &f->data->items[at]), dim * sizeof *val);
            ++n_fixed;
        }
    }
    const pc_lsq_space sp = space_of(f);
    const pc_fit_sample *d0 = f->data->items;
    const size_t stride = sample_stride(f);
    /* the rows of every sample the error pass measures (one past the
     * fitted ones when the stride does not divide the count) */
    projcurve_status st =
        pc_lsq_rows_fill(f->ctx, &sp, &d0->t, PC_FIT_SAMPLE_STRIDE * stride,
                         (f->data->count + stride - 1) / stride, &f->rows);
    if (st == PROJCURVE_OK) /* SINGULAR is the fit's to handle, not the caller's message */
        st = pc_lsq_fit_rows(NULL, &sp, f->goal->dim, &f->rows, sample_coords(f, d0),
                             PC_FIT_SAMPLE_STRIDE * stride, f->data->count / stride, idx, val,
                             n_fixed, f->poles);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        pc_fail(f->ctx, st, "out of memory for a fit of %zu poles", f->n_poles);
    free(idx);
    free(val);
    if (st == PROJCURVE_OK && f->goal->dim == 2) { /* q stays in the domain (convex hull) */
        const double *dom = f->fb->surface->domain;
        for (size_t i = 0; i < f->n_poles; ++i) {
            double *q = f->poles + 2 * i;
            q[0] = q[0] < dom[0] ? dom[0] : (q[0] > dom[1] ? dom[1] : q[0]);
            q[1] = q[1] < dom[2] ? dom[2] : (q[1] > dom[3] ? dom[3] : q[1]);
        }
    }
    return st;
}

/* The worst sample distance per span into f->err; returns the largest. */
static double sample_errors(fit_state *f)
{
    for (size_t j = 0; j + 1 < f->n_brk; ++j)
        f->err[j] = 0.0;
    double worst = 0.0;
    const size_t stride = sample_stride(f);
    for (size_t i = 0, k = 0; i < f->data->count; i += stride, ++k) {
        const pc_fit_sample *x = &f->data->items[i];
        double c[3];
        pc_lsq_eval_row(&f->rows, k, f->goal->dim, f->poles, c);
        const double d = distance_of(f, x, c, 0);
        const size_t j = span_of(f, x->t);
        f->err[j] = fmax(f->err[j], d);
        worst = fmax(worst, d);
    }
    return worst;
}

static int block_by_a(const void *x, const void *y)
{
    const double a = ((const check_block *)x)->a, b = ((const check_block *)y)->a;
    return (a > b) - (a < b);
}

/* The cached check points of span [a, b] (first index), or (size_t)-1. */
static size_t cached_block(const fit_state *f, double a, double b)
{
    size_t lo = 0, hi = f->n_blocks;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (f->blocks[mid].a < a)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (; lo < f->n_blocks && f->blocks[lo].a == a; ++lo)
        if (f->blocks[lo].b == b)
            return f->blocks[lo].first;
    return (size_t)-1;
}

/* Exact check points of span [a, b] into the cache; the block's first
 * index, or (size_t)-1 with *ok 0 when an exact point is missing. */
static projcurve_status new_block(fit_state *f, double a, double b, size_t *first, int *ok)
{
    *first = f->cache.count;
    projcurve_status st = PROJCURVE_OK;
    for (int i = 0; st == PROJCURVE_OK && i < PC_FIT_CHECK_PER_SPAN; ++i) {
        pc_fit_sample x;
        if (!pc_fit_exact(f->fb, a + (b - a) * (i + 0.5) / PC_FIT_CHECK_PER_SPAN, &x)) {
            *ok = 0;
            return PROJCURVE_OK;
        }
        st = pc_fit_samples_push(f->ctx, &f->cache, &x);
    }
    if (st == PROJCURVE_OK) {
        void *blocks = f->blocks;
        st = pc_array_reserve(f->ctx, &blocks, &f->cap_blocks, f->n_blocks, f->n_blocks + 1,
                              sizeof *f->blocks, 64, NULL, "fit check blocks");
        f->blocks = blocks;
    }
    if (st == PROJCURVE_OK)
        f->blocks[f->n_blocks++] = (check_block){a, b, *first};
    return st;
}

/* First sample index with t > a, and the count of those with t < b. */
static size_t samples_inside(const pc_fit_samples *s, double a, double b, size_t *count)
{
    size_t lo = 0, hi = s->count;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (s->items[mid].t <= a)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t end = lo;
    while (end < s->count && s->items[end].t < b)
        ++end;
    *count = end - lo;
    return lo;
}

/* The dense check: errors per span into f->err; the check points beyond
 * the target join the samples. A span checked before (not cut since)
 * reuses its exact points, and one that holds PC_FIT_CHECK_PER_SPAN
 * samples or more (the check points of an earlier fit of the branch) is
 * checked at those. *ok 0 when an exact point is missing. */
static projcurve_status check(fit_state *f, double *worst, int *ok)
{
    *worst = 0.0;
    projcurve_status st = PROJCURVE_OK;
    size_t hint = 0;
    if (f->n_blocks > 1)
        qsort(f->blocks, f->n_blocks, sizeof *f->blocks, block_by_a);
    const size_t n_sorted = f->n_blocks;
    for (size_t j = 0; st == PROJCURVE_OK && j + 1 < f->n_brk; ++j) {
        f->err[j] = 0.0;
        const double a = f->brk[j], b = f->brk[j + 1];
        size_t inside = 0;
        const size_t from = samples_inside(f->data, a, b, &inside);
        if (inside >= PC_FIT_CHECK_PER_SPAN) {
            /* at least PC_FIT_CHECK_PER_SPAN of them, evenly spread */
            const size_t step = inside / PC_FIT_CHECK_PER_SPAN;
            for (size_t i = from; i < from + inside; i += step) {
                const double d = distance(f, &f->data->items[i], &hint, 1);
                f->err[j] = fmax(f->err[j], d);
                *worst = fmax(*worst, d);
            }
            continue;
        }
        const size_t n_now = f->n_blocks;
        f->n_blocks = n_sorted; /* the search sees the sorted part only */
        size_t first = cached_block(f, a, b);
        f->n_blocks = n_now;
        const int fresh = first == (size_t)-1;
        if (fresh)
            st = new_block(f, a, b, &first, ok);
        if (st != PROJCURVE_OK || !*ok)
            return st;
        for (int i = 0; st == PROJCURVE_OK && i < PC_FIT_CHECK_PER_SPAN; ++i) {
            const pc_fit_sample x = f->cache.items[first + (size_t)i];
            const double d = distance(f, &x, &hint, 1);
            f->err[j] = fmax(f->err[j], d);
            *worst = fmax(*worst, d);
            if (fresh && d > f->goal->target) /* a reused point joined when it was new */
                st = pc_fit_samples_push(f->ctx, f->data, &x);
        }
    }
    pc_fit_samples_sort(f->data);
    return st;
}

/* Cuts every span whose error is above `above`; 0 when a span to cut is
 * too narrow or the poles would pass the goal's bound. */
static projcurve_status cut_spans(fit_state *f, double above, int *ok)
{
    const int p = f->goal->degree;
    const double min_span = PC_FIT_MIN_SPAN_REL * (f->fb->t_hi - f->fb->t_lo);
    size_t extra = 0;
    for (size_t j = 0; j + 1 < f->n_brk; ++j)
        if (f->err[j] > above) {
            if (!(f->brk[j + 1] - f->brk[j] > min_span)) {
                *ok = 0;
                return PROJCURVE_OK;
            }
            int k = (int)ceil(pow(f->err[j] / f->goal->target, 1.0 / (p + 1)));
            k = k < 2 ? 2 : (k > PC_FIT_MAX_SPLIT ? PC_FIT_MAX_SPLIT : k);
            extra += (size_t)(k - 1);
            f->err[j] = -(double)k; /* remembered for the pass below */
        }
    /* Grading: a neighbour of a cut span wider than PC_FIT_GRADE times the
     * new spans is cut in two as well. The poles of a span also shape its
     * neighbours: where a wide span's least-squares line bends the shared
     * poles, the error shows in the short span beside it, which cutting
     * alone cannot cure. Only the spans cut for their error (integer marks)
     * grade their neighbours (-2.5: cut in two, no further grading). */
    for (size_t j = 0; j + 1 < f->n_brk; ++j) {
        if (!(f->err[j] < 0.0) || f->err[j] != floor(f->err[j]))
            continue;
        const double sub = (f->brk[j + 1] - f->brk[j]) / -f->err[j];
        for (int side = -1; side <= 1; side += 2) {
            if ((side < 0 && j == 0) || (side > 0 && j + 2 >= f->n_brk))
                continue;
            const size_t n = side < 0 ? j - 1 : j + 1;
            if (f->err[n] >= 0.0 && f->brk[n + 1] - f->brk[n] > PC_FIT_GRADE * sub) {
                f->err[n] = -2.5;
                extra += 1;
            }
        }
    }
    if (f->n_poles + extra > f->goal->max_poles) {
        *ok = 0;
        return PROJCURVE_OK;
    }
    double *knots = malloc((f->n_knots + extra) * sizeof *knots);
    if (knots == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
    size_t m = 0;
    for (size_t i = 0; i < f->n_knots; ++i) {
        knots[m++] = f->knots[i];
        /* after the last copy of a span's start, that span's new knots */
        if (i + 1 < f->n_knots && f->knots[i + 1] > f->knots[i] && i >= (size_t)p &&
            i < f->n_poles) {
            const size_t j = span_of(f, f->knots[i]);
            if (f->err[j] < 0.0) {
                const int k = (int)-f->err[j];
                const double a = f->brk[j], b = f->brk[j + 1];
                for (int c = 1; c < k; ++c)
                    knots[m++] = a + (b - a) * c / k;
            }
        }
    }
    free(f->knots);
    f->knots = knots;
    f->n_knots = m;
    return rebuild_breaks(f);
}

projcurve_status pc_fit_adaptive(projcurve_context *ctx, pc_fit_branch *fb,
                                 const pc_fit_goal *goal, const double *knots, size_t n_knots,
                                 const double *weights, pc_fit_samples *data,
                                 pc_fit_curve *out, int *ok)
{
    *ok = 0;
    fit_state f = {ctx, fb, goal, weights, data, NULL, n_knots, 0, NULL, NULL, 0, NULL,
                   {NULL, 0, 0, 0, 0}, NULL, 0, 0, {0, 0, NULL, NULL, 0, 0}};
    f.knots = malloc(n_knots * sizeof *f.knots);
    if (f.knots == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
    memcpy(f.knots, knots, n_knots * sizeof *f.knots);
    projcurve_status st = rebuild_breaks(&f);
    int going = 1;
    double worst = INFINITY;
    for (int round = 0; st == PROJCURVE_OK && going && round < PC_FIT_MAX_ROUNDS; ++round) {
        if (f.n_poles > goal->max_poles)
            break;
        /* A round is a unit of the budget too: a fit whose samples and
         * check points exist already (the 3D fit after the pcurve's)
         * makes no exact point, and its solves must stop with the call. */
        if (pc_budget_check(fb->budget, fb->progress) != PROJCURVE_OK)
            break;
        st = fill_spans(&f, &going);
        if (st != PROJCURVE_OK || !going)
            break;
        const projcurve_status solved = solve(&f);
        if (solved == PROJCURVE_ERR_NO_MEMORY) /* a singular system only fails the fit */
            st = solved;
        if (solved != PROJCURVE_OK)
            break;
        if (sample_errors(&f) > goal->target) {
            if (!goal->refine)
                break;
            st = cut_spans(&f, goal->target, &going);
            continue;
        }
        st = check(&f, &worst, &going);
        if (st != PROJCURVE_OK || !going)
            break;
        if (worst <= goal->limit) {
            *ok = 1;
            break;
        }
        if (!goal->refine)
            break;
        st = cut_spans(&f, goal->limit, &going);
    }
    if (st == PROJCURVE_OK && *ok) {
        out->spline.degree = goal->degree;
        out->spline.dim = goal->dim;
        out->spline.n_poles = f.n_poles;
        out->spline.knots = f.knots;
        out->spline.poles = f.poles;
        out->spline.weights = NULL;
        out->error = worst;
        f.knots = f.poles = NULL;
        if (weights != NULL) {
            out->spline.weights = malloc(f.n_poles * sizeof *out->spline.weights);
            if (out->spline.weights == NULL) {
                pc_fit_curve_free(out);
                *ok = 0;
                st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
            } else {
                memcpy(out->spline.weights, weights, f.n_poles * sizeof *out->spline.weights);
            }
        }
    } else {
        *ok = 0;
    }
    free(f.knots);
    free(f.poles);
    free(f.brk);
    free(f.err);
    /* the check points are exact: the next fit of the branch has them */
    for (size_t i = 0; st == PROJCURVE_OK && i < f.cache.count; ++i)
        st = pc_fit_samples_push(ctx, data, &f.cache.items[i]);
    pc_fit_samples_sort(data);
    free(f.blocks);
    pc_fit_samples_free(&f.cache);
    pc_lsq_rows_free(&f.rows);
    return st;
}

void pc_fit_curve_free(pc_fit_curve *c)
{
    pc_bspline_free(&c->spline);
    c->error = 0.0;
}
