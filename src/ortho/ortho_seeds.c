/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_seeds.h"

#include <stdint.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "ortho/collapsed.h"
#include "ortho/ortho_minima.h"
#include "point/point.h"

/* Initial capacity of the foot-point buffer; it grows when a search finds
 * more (the geometry reports the full count). */
#define ORTHO_FOOT_CAPACITY 16

static projcurve_status grow(projcurve_context *ctx, pc_ortho_finder_state *st, size_t need)
{
    /* elements of two doubles: the (u, v) of a foot point */
    void *items = st->uv;
    const projcurve_status grown =
        pc_array_reserve(ctx, &items, &st->capacity, st->capacity, need, 2 * sizeof *st->uv,
                         ORTHO_FOOT_CAPACITY, NULL, "the foot points of a seed search");
    st->uv = items;
    return grown;
}

/* 1 when (u, v) is a collapsed point of the parametrisation (collapsed.h).
 * Such a foot point is no seed: its u (or v) is arbitrary (at the pole of a
 * sphere every u is a foot point of a P on the axis, and the search returns
 * several), q' has no reliable component along it, and the branch through
 * it is the one that reached the edge or the one the next search finds
 * beside it and traces back to the edge. */
static int at_collapsed_point(const projcurve_surface *s, double u, double v)
{
    pc_vec3 sd[3];
    pc_nurbs_surface_eval(&s->nurbs, u, v, 1, NULL, NULL, sd);
    return pc_collapsed_direction(sd[1], sd[2]) != PC_COLLAPSE_NONE;
}

/* Every local foot point of P(t) (projcurve_surface_foot_points), or none
 * where may_jump asked for no search (ortho_seeds.h). */
static projcurve_status ortho_find(pc_seed_finder *self, projcurve_context *ctx, double t,
                                   pc_seed_list *out)
{
    pc_ortho_finder_state *st = self->state;
    out->count = 0;
    const int skip = st->skip_due && t == st->skip_t;
    st->skip_due = 0;
    if (skip)
        return PROJCURVE_OK;
    pc_vec3 p;
    if (pc_curve_eval(st->curve, t, 0, NULL, &p) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g", t);
    projcurve_status status = grow(ctx, st, ORTHO_FOOT_CAPACITY);
    size_t count = 0;
    if (status == PROJCURVE_OK)
        status = pc_surface_foot_points_uv(ctx, st->surface, p, st->budget, st->capacity,
                                           st->uv, &count);
    if (status == PROJCURVE_OK && count > st->capacity) {
        status = grow(ctx, st, count);
        if (status == PROJCURVE_OK)
            status = pc_surface_foot_points_uv(ctx, st->surface, p, st->budget, st->capacity,
                                               st->uv, &count);
        if (count > st->capacity)
            count = st->capacity;
    }
    for (size_t i = 0; status == PROJCURVE_OK && i < count; ++i) {
        const double u = st->uv[2 * i], v = st->uv[2 * i + 1];
        if (!at_collapsed_point(st->surface, u, v) &&
            (st->minima_of == NULL || pc_ortho_is_minimum(st->minima_of, t, u, v)))
            status = pc_seed_list_push(ctx, out, t, u, v);
    }
    return status;
}

static int ortho_may_jump(pc_seed_finder *self, double t, const pc_seed *active,
                          size_t n_active, double ds)
{
    pc_ortho_finder_state *st = self->state;
    (void)active;
    (void)ds;
    int search = 0;
    if (!st->started || n_active != st->last_active || t - st->last_full_t >= st->interval)
        search = 1;
    st->started = 1;
    st->last_active = n_active;
    st->skip_due = !search;
    st->skip_t = t;
    if (search)
        st->last_full_t = t;
    return search;
}

static void ortho_reset(pc_seed_finder *self)
{
    pc_ortho_finder_state *st = self->state;
    st->started = 0;
    st->last_active = 0;
    st->skip_due = 0;
    st->last_full_t = st->curve->t0;
}

void pc_ortho_finder_init(pc_seed_finder *finder, pc_ortho_finder_state *state,
                          const projcurve_surface *surface, const projcurve_curve *curve,
                          const pc_projector *minima_of)
{
    state->surface = surface;
    state->curve = curve;
    state->minima_of = minima_of;
    const int cheap = surface->nurbs.deg_u <= PC_ORTHO_DENSE_CHECKS_DEGREE &&
                      surface->nurbs.deg_v <= PC_ORTHO_DENSE_CHECKS_DEGREE;
    state->interval = (curve->t1 - curve->t0) /
                      (cheap ? PC_ORTHO_DENSE_JUMP_CHECKS : PC_ORTHO_JUMP_CHECKS);
    state->uv = NULL;
    state->capacity = 0;
    state->budget = NULL;
    finder->find = ortho_find;
    finder->may_jump = ortho_may_jump;
    finder->reset = ortho_reset;
    /* a foot point needs no ray: no box of the patches bounds where the
     * foot points of a curve piece lie without the patches' normal cones
     * (docs/tracing.md, "Small patches between two checks") */
    finder->step_may_skip = NULL;
    finder->state = state;
    ortho_reset(finder);
}

void pc_ortho_finder_free(pc_ortho_finder_state *state)
{
    free(state->uv);
    state->uv = NULL;
    state->capacity = 0;
}
