/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The driver of the compact fits (fit.h): per branch, the exact samples,
 * the features, then the pcurve and the 3D curve, each first in the
 * curve's own space (own_space.h), else by adaptive least squares
 * (adaptive.h) over knots at the features.
 */
#include "fit/fit.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "fit/features.h"
#include "fit/joined.h"
#include "fit/own_space.h"

/* The samples are fitted to this fraction of eps_D, and the dense check
 * accepts up to PC_FIT_LIMIT of it: the margin covers what lies between
 * check points (10 per span, where the error profile is smooth) and the
 * rounding of the corrector's points. */
#define PC_FIT_TARGET 0.5
#define PC_FIT_LIMIT 0.8
/* Exact points inside each piece to start from, beyond its ends (exact
 * vertices already): none, the pieces are dense where the projection
 * bends, and the fit adds samples to the spans that hold too few. */
#define PC_FIT_INNER_SAMPLES 0
/* Pieces meet at a crease when their tangents differ by more than this
 * many times eps_T (the refinement keeps smooth joints within eps_T), and
 * at least PC_FIT_CREASE_MIN_DEG. */
#define PC_FIT_CREASE_FACTOR 4.0
#define PC_FIT_CREASE_MIN_DEG 5.0
/* The pole bound of a fit: the poles of the pieces joined (3 per piece for
 * the pcurve, degree per piece for the 3D curve) plus these. The spare
 * poles matter where a few long pieces cover a stretch that the fit, at
 * the same t, must follow more closely: a straight piece ending at a
 * fold, where q(t) behaves as a square root. */
#define PC_FIT_SPARE_POLES 256

/* Features where q is C^k with 2 <= k < the fit's degree ("soft": the
 * jump is in the third derivative or above): with at most this many, they
 * are marked (a knot of multiplicity d - 2 at each of a few knots of P
 * lets the fit follow them exactly: Example 1's 3D curve, 13 poles instead
 * of 45 at 1e-5); with more, the fit is made both ways and the one with
 * fewer poles kept: at each of the hundreds of knots of a long curve the
 * marks can triple the poles at a loose eps_D (real_joinsurf85: 378
 * against Open CASCADE's 113, unmarked 91), and save two thirds at a tight
 * one (real_lens: 82 marked, 221 unmarked). Places below C2 are always
 * marked. */
#define PC_FIT_SOFT_FEATURES_MAX 16
#define PC_FIT_HARD_BELOW 2

/* The clamped knot vector of degree p over [t_lo, t_hi] with a knot of
 * multiplicity p - continuity (at least 1) at every feature marked (above)
 * where that is positive. *out is malloc'd. */
static projcurve_status feature_knots(projcurve_context *ctx, const pc_fit_branch *fb,
                                      const pc_fit_features *f, int p, int mark_below,
                                      double **out, size_t *n_out)
{
    double *k = malloc((2 * (size_t)(p + 1) + f->count * (size_t)p) * sizeof *k);
    if (k == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
    size_t n = 0;
    for (int i = 0; i <= p; ++i)
        k[n++] = fb->t_lo;
    for (size_t j = 0; j < f->count; ++j) {
        if (f->items[j].continuity >= mark_below)
            continue;
        const int mult = p - (f->items[j].continuity < 0 ? 0 : f->items[j].continuity);
        for (int i = 0; i < mult; ++i)
            k[n++] = f->items[j].t;
    }
    for (int i = 0; i <= p; ++i)
        k[n++] = fb->t_hi;
    *out = k;
    *n_out = n;
    return PROJCURVE_OK;
}

/* The curve's own space is kept outright up to this many poles: exact to
 * rounding (a circle stays its 9 poles). Beyond, the adaptive fit is tried
 * too and kept when it needs fewer: a curve lying on S with hundreds of
 * poles projects onto itself, and eps_D may need far fewer. */
#define PC_FIT_OWN_SPACE_KEEP 32

/* The adaptive fit over the feature knots, marking the places below
 * mark_below. */
static projcurve_status adaptive_with(projcurve_context *ctx, pc_fit_branch *fb,
                                      const pc_fit_features *f, pc_fit_samples *data,
                                      const pc_fit_goal *goal, int mark_below,
                                      pc_fit_curve *out, int *ok)
{
    double *knots = NULL;
    size_t n_knots = 0;
    projcurve_status st = feature_knots(ctx, fb, f, goal->degree, mark_below, &knots, &n_knots);
    if (st == PROJCURVE_OK)
        st = pc_fit_adaptive(ctx, fb, goal, knots, n_knots, NULL, data, out, ok);
    free(knots);
    return st;
}

/* The poles of the knot vector feature_knots makes (p + 1 + the
 * multiplicities of the places marked). */
static size_t feature_poles(const pc_fit_features *f, int p, int mark_below)
{
    size_t n = (size_t)p + 1;
    for (size_t j = 0; j < f->count; ++j)
        if (f->items[j].continuity < mark_below)
            n += (size_t)(p - (f->items[j].continuity < 0 ? 0 : f->items[j].continuity));
    return n;
}

/* The adaptive fit, with the soft features marked and, when they are
 * many, also without (PC_FIT_SOFT_FEATURES_MAX): the fewer poles win.
 * With many, the unmarked fit runs first, bound by the poles the marked
 * one starts from (a knot at each feature): where it needs fewer (a loose
 * eps_D) the marked one cannot win and is not run, where run first it
 * checked every one of its many starting spans for nothing
 * (real_joinsurf85 at its case eps_D: 3,000 of the fit's 3,050 exact
 * points); where it needs more it stops there, before its checks, and
 * the marked one is made as before. */
static projcurve_status adaptive_best(projcurve_context *ctx, pc_fit_branch *fb,
                                      const pc_fit_features *f, pc_fit_samples *data,
                                      pc_fit_goal goal, pc_fit_curve *out, int *ok)
{
    size_t soft = 0;
    for (size_t j = 0; j < f->count; ++j)
        soft += f->items[j].continuity >= PC_FIT_HARD_BELOW && f->items[j].continuity < goal.degree;
    if (soft <= PC_FIT_SOFT_FEATURES_MAX)
        return adaptive_with(ctx, fb, f, data, &goal, goal.degree, out, ok);
    pc_fit_goal first = goal;
    const size_t marked_start = feature_poles(f, goal.degree, goal.degree);
    first.max_poles = marked_start < goal.max_poles ? marked_start : goal.max_poles;
    projcurve_status st = adaptive_with(ctx, fb, f, data, &first, PC_FIT_HARD_BELOW, out, ok);
    if (st != PROJCURVE_OK)
        return st;
    if (*ok)
        goal.max_poles = out->spline.n_poles - 1;
    pc_fit_curve other = {0};
    int other_ok = 0;
    if (goal.max_poles >= (size_t)goal.degree + 1 && goal.max_poles >= marked_start)
        st = adaptive_with(ctx, fb, f, data, &goal, goal.degree, &other, &other_ok);
    if (st == PROJCURVE_OK && other_ok) {
        pc_fit_curve_free(out);
        *out = other;
        *ok = 1;
    } else {
        pc_fit_curve_free(&other);
    }
    return st;
}

/* One compact form: the curve's own space or the adaptive fit (above). */
static projcurve_status fit_one(projcurve_context *ctx, pc_fit_branch *fb,
                                const pc_fit_features *f, pc_fit_samples *data, int dim,
                                int degree, size_t max_poles, double eps_d, pc_fit_curve *out,
                                int *ok)
{
    const double target = PC_FIT_TARGET * eps_d, limit = PC_FIT_LIMIT * eps_d;
    const int own_max = dim == 2 ? PROJCURVE_MAX_DEGREE : degree;
    pc_fit_curve own = {0};
    int own_ok = 0;
    projcurve_status st = pc_fit_own_space(ctx, fb, dim, own_max, target, limit, data, &own,
                                           &own_ok);
    if (st != PROJCURVE_OK)
        return st;
    if (own_ok)
        max_poles = own.spline.n_poles - 1;
    if (own_ok && (own.spline.n_poles <= PC_FIT_OWN_SPACE_KEEP || max_poles < (size_t)degree + 1)) {
        *out = own;
        *ok = 1;
        return PROJCURVE_OK;
    }
    const pc_fit_goal goal = {degree, dim, target, limit, max_poles, 1};
    st = adaptive_best(ctx, fb, f, data, goal, out, ok);
    if (st == PROJCURVE_OK && !*ok && own_ok) {
        *out = own;
        *ok = 1;
    } else {
        pc_fit_curve_free(&own);
    }
    return st;
}

/* Moves c's spline into dst (c is left empty). */
static void keep(pc_bspline *dst, pc_fit_curve *c)
{
    pc_bspline_free(dst);
    *dst = c->spline;
    c->spline = (pc_bspline){0};
}

/* The pcurve and the 3D curve of one branch. */
static projcurve_status fit_branch(projcurve_context *ctx, pc_fit_branch *fb,
                                   const pc_params *p, pc_branch *b)
{
    const double eps_d = p->tol_distance;
    const size_t np = b->n_pieces;
    pc_fit_features f = {NULL, 0, 0};
    pc_fit_samples data = {NULL, 0, 0, 0, 0};
    pc_fit_curve pcurve = {0}, curve = {0};
    int complete = 0, have_pcurve = 0, have_curve = 0;
    const double crease =
        fmax(PC_FIT_CREASE_MIN_DEG, PC_FIT_CREASE_FACTOR * p->tol_angle_deg);
    projcurve_status st = pc_fit_features_find(ctx, fb, crease, &f);
    if (st == PROJCURVE_OK)
        st = pc_fit_samples_from_pieces(ctx, fb, PC_FIT_INNER_SAMPLES, &data, &complete);
    if (st == PROJCURVE_OK && complete)
        st = fit_one(ctx, fb, &f, &data, 2, PC_FIT_PCURVE_DEGREE,
                     3 * np + 1 + PC_FIT_SPARE_POLES, eps_d, &pcurve, &have_pcurve);
    if (st == PROJCURVE_OK && complete) {
        const int d = (int)p->curve_degree;
        st = fit_one(ctx, fb, &f, &data, 3, d, np * (size_t)d + 1 + PC_FIT_SPARE_POLES, eps_d,
                     &curve, &have_curve);
    }
    b->compact = have_pcurve ? PC_COMPACT_FITTED : PC_COMPACT_JOINED;
    if (st == PROJCURVE_OK && !have_pcurve)
        st = pc_fit_joined_pcurve(ctx, fb, &pcurve);
    if (st == PROJCURVE_OK)
        keep(&b->compact_pcurve, &pcurve);
    b->compact_pcurve_error = have_pcurve ? pcurve.error : -1.0;
    if (st == PROJCURVE_OK && have_curve)
        keep(&b->compact_curve, &curve);
    b->compact_curve_error = have_curve ? curve.error : -1.0;
    if (st != PROJCURVE_OK)
        b->compact = PC_COMPACT_NONE;
    pc_fit_curve_free(&pcurve);
    pc_fit_curve_free(&curve);
    pc_fit_samples_free(&data);
    pc_fit_features_free(&f);
    return st;
}

projcurve_status pc_fit_result(projcurve_context *ctx, const pc_projector *proj,
                               const pc_params *p, projcurve_result *r)
{
    if (r->point_dim != 3)
        return PROJCURVE_OK;
    projcurve_status st = PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < r->n_branches; ++i) {
        pc_fit_branch fb;
        if (!pc_fit_branch_init(&fb, proj, &r->branches[i], p->budget))
            continue;
        fb.progress = (double)i / (double)r->n_branches;
        st = fit_branch(ctx, &fb, p, &r->branches[i]);
    }
    if (st == PROJCURVE_OK)
        st = pc_budget_fail(p->budget, ctx);
    return st;
}

projcurve_status pc_fit_stage(projcurve_context *ctx, const pc_projector *proj,
                              const pc_params *p, projcurve_result *r, projcurve_status st)
{
    if (!p->compose || !pc_status_keeps_result(st))
        return st;
    pc_budget_stage(p->budget, PC_FIT_STAGE_FROM, 1.0);
    if (!p->compact)
        return st;
    const projcurve_status fs = pc_fit_result(ctx, proj, p, r);
    return fs == PROJCURVE_ERR_NO_MEMORY || (fs != PROJCURVE_OK && st == PROJCURVE_OK) ? fs : st;
}
