/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Samples of a face's loop pieces (faceproj/loop_samples.h).
 */
#include "faceproj/loop_samples.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"

void pc_loop_samples_free(pc_loop_samples *s)
{
    free(s->pieces);
    s->pieces = NULL;
    s->n_pieces = 0;
    PC_ARRAY_FREE(s);
}

static size_t span_count(const pc_curve2 *c)
{
    size_t n = 0;
    for (size_t k = (size_t)c->degree; k < c->n_ctrl; ++k)
        n += c->knots[k + 1] > c->knots[k];
    return n > 0 ? n : 1;
}

static void add_sample(pc_loop_samples *s, pc_piece_samples *ps, double tau, const double uv[2])
{
    pc_loop_sample *q = &s->items[s->count++];
    q->tau = tau;
    q->uv[0] = uv[0];
    q->uv[1] = uv[1];
    ps->box[0] = fmin(ps->box[0], uv[0]);
    ps->box[1] = fmax(ps->box[1], uv[0]);
    ps->box[2] = fmin(ps->box[2], uv[1]);
    ps->box[3] = fmax(ps->box[3], uv[1]);
    ++ps->count;
}

/* A piece of degree 1 is its control polygon, control point i at knot
 * i + 1 (clamped): those are its samples, exact and without evaluation
 * (real loops have degree-1 pieces of thousands of points). Higher
 * degrees: PC_LOOP_SAMPLES_PER_SPAN a span. */
static projcurve_status sample_piece(projcurve_context *ctx, pc_loop_samples *s,
                                     pc_piece_samples *ps, const pc_curve2 *c)
{
    double t0, t1;
    pc_curve2_domain(c, &t0, &t1);
    const int linear = c->degree == 1;
    size_t n = linear ? c->n_ctrl - 1 : span_count(c) * PC_LOOP_SAMPLES_PER_SPAN;
    if (!linear && s->count + n + 1 > PC_LOOP_MAX_SAMPLES)
        n = PC_LOOP_SAMPLES_PER_SPAN; /* bounded: a coarser guess, Newton still refines */
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, s, s->count + n + 1, 64, "loop samples");
    if (st != PROJCURVE_OK)
        return st;
    ps->first = s->count;
    ps->count = 0;
    ps->box[0] = ps->box[2] = INFINITY;
    ps->box[1] = ps->box[3] = -INFINITY;
    for (size_t i = 0; i <= n; ++i) {
        if (linear) {
            add_sample(s, ps, c->knots[i + 1], c->ctrl + 2 * i);
            continue;
        }
        const double tau = i == n ? t1 : t0 + (t1 - t0) * (double)i / (double)n;
        double uv[2];
        pc_curve2_eval(c, tau, uv);
        add_sample(s, ps, tau, uv);
    }
    return PROJCURVE_OK;
}

projcurve_status pc_loop_samples_build(projcurve_context *ctx, const projcurve_face *face,
                                       pc_loop_samples *out)
{
    pc_loop_samples s = {.face = face};
    size_t n = 0;
    for (size_t l = 0; l < face->n_loops; ++l)
        n += face->loops[l].n_pieces;
    s.pieces = calloc(n + 1, sizeof *s.pieces);
    if (s.pieces == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the loop samples");
    projcurve_status st = PROJCURVE_OK;
    for (size_t l = 0; st == PROJCURVE_OK && l < face->n_loops; ++l)
        for (size_t k = 0; st == PROJCURVE_OK && k < face->loops[l].n_pieces; ++k) {
            pc_piece_samples *ps = &s.pieces[s.n_pieces++];
            ps->loop = l;
            ps->piece = k;
            st = sample_piece(ctx, &s, ps, &face->loops[l].pieces[k].curve);
        }
    if (st != PROJCURVE_OK) {
        pc_loop_samples_free(&s);
        return st;
    }
    *out = s;
    return PROJCURVE_OK;
}

static const pc_curve2 *piece_curve(const pc_loop_samples *s, size_t which)
{
    const pc_piece_samples *ps = &s->pieces[which];
    return &s->face->loops[ps->loop].pieces[ps->piece].curve;
}

void pc_loop_piece_eval(const pc_loop_samples *s, size_t which, double tau, double c[2],
                        double dc[2])
{
    const pc_curve2 *cv = piece_curve(s, which);
    double t0, t1;
    pc_curve2_domain(cv, &t0, &t1);
    /* a step of ~1e-6 of the domain: central differences then carry an
     * error ~1e-12 relative, far below what Newton needs from a guide */
    const double h = 1e-6 * (t1 - t0);
    const double a = fmax(t0, tau - h), b = fmin(t1, tau + h);
    double pa[2], pb[2];
    pc_curve2_eval(cv, tau, c);
    pc_curve2_eval(cv, a, pa);
    pc_curve2_eval(cv, b, pb);
    dc[0] = (pb[0] - pa[0]) / (b - a);
    dc[1] = (pb[1] - pa[1]) / (b - a);
}

/* The local search after the polylines: a few Newton steps on
 * (c - x).c' = 0, clamped to the piece's domain. */
#define PC_NEAREST_ITERATIONS 8

/* Distance from x to the box {u0, u1, v0, v1}. */
static double box_distance(const double box[4], const double x[2])
{
    const double du = fmax(0.0, fmax(box[0] - x[0], x[0] - box[1]));
    const double dv = fmax(0.0, fmax(box[2] - x[1], x[1] - box[3]));
    return hypot(du, dv);
}

double pc_loop_samples_nearest(const pc_loop_samples *s, const double uv[2], size_t *which,
                               double *tau)
{
    /* nearest point of the sampled polylines (exact for degree-1 pieces,
     * whose samples are their control points), then Newton on the piece */
    double best = INFINITY;
    for (size_t i = 0; i < s->n_pieces; ++i) {
        const pc_piece_samples *ps = &s->pieces[i];
        if (box_distance(ps->box, uv) > best)
            continue;
        for (size_t j = 0; j + 1 < ps->count; ++j) {
            const pc_loop_sample *a = &s->items[ps->first + j], *b = a + 1;
            const double e[2] = {b->uv[0] - a->uv[0], b->uv[1] - a->uv[1]};
            const double ee = e[0] * e[0] + e[1] * e[1];
            double f = ee > 0.0 ? ((uv[0] - a->uv[0]) * e[0] + (uv[1] - a->uv[1]) * e[1]) / ee
                                : 0.0;
            f = fmin(1.0, fmax(0.0, f));
            const double d =
                hypot(a->uv[0] + f * e[0] - uv[0], a->uv[1] + f * e[1] - uv[1]);
            if (d < best) {
                best = d;
                *which = i;
                *tau = a->tau + f * (b->tau - a->tau);
            }
        }
        if (ps->count == 1) {
            const pc_loop_sample *a = &s->items[ps->first];
            const double d = hypot(a->uv[0] - uv[0], a->uv[1] - uv[1]);
            if (d < best) {
                best = d;
                *which = i;
                *tau = a->tau;
            }
        }
    }
    if (!isfinite(best))
        return best;
    double t0, t1;
    pc_curve2_domain(piece_curve(s, *which), &t0, &t1);
    for (int it = 0; it < PC_NEAREST_ITERATIONS; ++it) {
        double c[2], dc[2];
        pc_loop_piece_eval(s, *which, *tau, c, dc);
        const double g = (c[0] - uv[0]) * dc[0] + (c[1] - uv[1]) * dc[1];
        const double h = dc[0] * dc[0] + dc[1] * dc[1];
        if (!(h > 0.0))
            break;
        *tau = fmin(t1, fmax(t0, *tau - g / h));
    }
    double c[2], dc[2];
    pc_loop_piece_eval(s, *which, *tau, c, dc);
    return fmin(best, hypot(c[0] - uv[0], c[1] - uv[1]));
}
