/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The standalone STEP read of analytic surfaces: each is built over the box
 * that the faces using it need. Before the topology is read, the points of
 * a face are gathered from its bounds (ADVANCED_FACE -> FACE_BOUND ->
 * EDGE_LOOP -> ORIENTED_EDGE -> EDGE_CURVE -> VERTEX_POINT ->
 * CARTESIAN_POINT, and VERTEX_LOOP / POLY_LOOP), plus points that bound
 * the edge curves between their vertices: PC_STEP_CONIC_SAMPLES points of
 * the whole circle or ellipse, the control points of a B-spline edge (its
 * convex hull holds the curve). A line lies between its vertices.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "io/step_analytic.h"
#include "io/step_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* 32 samples of a circle leave at most 1 - cos(pi / 32) = 0.5 % of the
 * radius between them and the curve: inside the box margin. */
#define PC_STEP_CONIC_SAMPLES 32

typedef struct face_point {
    long surface;
    double p[3];
} face_point;

typedef struct gather {
    pc_step_file *f;
    pc_arena *arena;
    long surface;
    face_point *items;
    size_t count, capacity;
} gather;

static projcurve_status add_point(gather *g, const double p[3])
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, g->f->ctx, g, g->count + 1, 256, "STEP face points");
    if (st != PROJCURVE_OK)
        return st;
    g->items[g->count].surface = g->surface;
    memcpy(g->items[g->count].p, p, sizeof g->items[g->count].p);
    ++g->count;
    return PROJCURVE_OK;
}

static projcurve_status vertex(gather *g, const pc_step_instance *from, const pc_step_node *ref)
{
    pc_step_located v;
    projcurve_status st = pc_step_resolve(g->f, g->arena, from, ref, &v);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(v.node, "VERTEX_POINT"))
        return pc_step_bad(g->f, v.inst, "expected a VERTEX_POINT");
    double p[3];
    if ((st = pc_step_point(g->f, g->arena, v.inst, pc_step_child(v.node, 1), p)) != PROJCURVE_OK)
        return st;
    return add_point(g, p);
}

/* Points bounding the edge's curve between its vertices. */
static projcurve_status edge_geometry(gather *g, const pc_step_instance *from,
                                      const pc_step_node *ref)
{
    pc_step_located c;
    projcurve_status st = pc_step_resolve(g->f, g->arena, from, ref, &c);
    if (st != PROJCURVE_OK)
        return st;
    if (pc_step_is(c.node, "SURFACE_CURVE") || pc_step_is(c.node, "SEAM_CURVE"))
        if ((st = pc_step_resolve(g->f, g->arena, c.inst, pc_step_child(c.node, 1), &c)) != PROJCURVE_OK)
            return st;
    if (pc_step_is(c.node, "LINE") || pc_step_is(c.node, "POLYLINE"))
        return PROJCURVE_OK;
    pc_io_curve k;
    const char *skip = NULL;
    if ((st = pc_step_curve(g->f, g->arena, &c, &k, NULL, &skip)) != PROJCURVE_OK || skip != NULL)
        return st;
    const int conic = pc_step_is(c.node, "CIRCLE") || pc_step_is(c.node, "ELLIPSE");
    if (!conic) {
        for (size_t i = 0; i < k.n_ctrl && st == PROJCURVE_OK; ++i)
            st = add_point(g, k.ctrl + 3 * i);
        return st;
    }
    for (int i = 0; i < PC_STEP_CONIC_SAMPLES && st == PROJCURVE_OK; ++i) {
        double p[3];
        pc_rational_curve_eval(&k, 2.0 * M_PI * i / PC_STEP_CONIC_SAMPLES, p);
        st = add_point(g, p);
    }
    return st;
}

static projcurve_status oriented_edge(gather *g, const pc_step_instance *from,
                                      const pc_step_node *ref)
{
    pc_step_located oe, ec;
    projcurve_status st = pc_step_resolve(g->f, g->arena, from, ref, &oe);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(oe.node, "ORIENTED_EDGE"))
        return pc_step_bad(g->f, oe.inst, "expected an ORIENTED_EDGE in an EDGE_LOOP");
    if ((st = pc_step_resolve(g->f, g->arena, oe.inst, pc_step_child(oe.node, 3), &ec)) != PROJCURVE_OK)
        return st;
    if (!pc_step_is(ec.node, "EDGE_CURVE"))
        return pc_step_bad(g->f, ec.inst, "expected an EDGE_CURVE");
    if ((st = vertex(g, ec.inst, pc_step_child(ec.node, 1))) != PROJCURVE_OK ||
        (st = vertex(g, ec.inst, pc_step_child(ec.node, 2))) != PROJCURVE_OK)
        return st;
    return edge_geometry(g, ec.inst, pc_step_child(ec.node, 3));
}

static projcurve_status loop_points(gather *g, const pc_step_instance *from,
                                    const pc_step_node *ref)
{
    pc_step_located loop;
    projcurve_status st = pc_step_resolve(g->f, g->arena, from, ref, &loop);
    if (st != PROJCURVE_OK)
        return st;
    const pc_step_node *items = pc_step_child(loop.node, 1);
    if (pc_step_is(loop.node, "VERTEX_LOOP"))
        return vertex(g, loop.inst, items);
    const int poly = pc_step_is(loop.node, "POLY_LOOP");
    if ((!poly && !pc_step_is(loop.node, "EDGE_LOOP")) || items == NULL || items->kind != PC_STEP_LIST)
        return pc_step_bad(g->f, loop.inst, "expected an EDGE_LOOP, VERTEX_LOOP or POLY_LOOP");
    for (const pc_step_node *c = items->first; c != NULL && st == PROJCURVE_OK; c = c->next) {
        if (poly) {
            double p[3];
            if ((st = pc_step_point(g->f, g->arena, loop.inst, c, p)) == PROJCURVE_OK)
                st = add_point(g, p);
        } else {
            st = oriented_edge(g, loop.inst, c);
        }
    }
    return st;
}

/* ADVANCED_FACE / FACE_SURFACE('', (bounds), surface, same_sense) */
static projcurve_status face_points(gather *g, const pc_step_instance *inst)
{
    pc_step_node *node = NULL;
    projcurve_status st = pc_step_parse(g->f, inst, g->arena, &node);
    if (st != PROJCURVE_OK)
        return st;
    const pc_step_node *bounds = pc_step_child(node, 1), *surface = pc_step_child(node, 2);
    if (bounds == NULL || bounds->kind != PC_STEP_LIST || surface == NULL ||
        surface->kind != PC_STEP_REF)
        return pc_step_bad(g->f, inst, "a face without its bounds and surface");
    g->surface = surface->ref;
    for (const pc_step_node *b = bounds->first; b != NULL && st == PROJCURVE_OK; b = b->next) {
        pc_step_located fb;
        if ((st = pc_step_resolve(g->f, g->arena, inst, b, &fb)) != PROJCURVE_OK)
            return st;
        if (!pc_step_is(fb.node, "FACE_OUTER_BOUND") && !pc_step_is(fb.node, "FACE_BOUND"))
            return pc_step_bad(g->f, fb.inst, "expected a FACE_OUTER_BOUND or FACE_BOUND");
        st = loop_points(g, fb.inst, pc_step_child(fb.node, 1));
    }
    return st;
}

static int by_surface(const void *a, const void *b)
{
    const long x = ((const face_point *)a)->surface, y = ((const face_point *)b)->surface;
    return (x > y) - (x < y);
}

/* The first point of surface id in the sorted list and their count. */
static size_t points_of(const gather *g, long id, size_t *count)
{
    size_t lo = 0, hi = g->count;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (g->items[mid].surface < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t end = lo;
    while (end < g->count && g->items[end].surface == id)
        ++end;
    *count = end - lo;
    return lo;
}

static projcurve_status read_one(pc_step_file *f, pc_arena *arena, projcurve_model *model,
                                 const gather *g, const pc_step_instance *inst, const char *name)
{
    size_t n = 0;
    const size_t first = points_of(g, inst->id, &n);
    double *pts = pc_arena_calloc(arena, 3 * (n ? n : 1), sizeof(double));
    if (pts == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP surfaces");
    for (size_t i = 0; i < n; ++i)
        memcpy(pts + 3 * i, g->items[first + i].p, 3 * sizeof(double));
    pc_step_analytic a;
    const char *skip = NULL;
    projcurve_status st = pc_step_analytic_surface(f, arena, inst->id, pts, n, &a, &skip);
    char origin[PC_STEP_MAX_NAME + 48];
    snprintf(origin, sizeof origin, "STEP #%ld %s", inst->id, name);
    if (st == PROJCURVE_ERR_PARSE) /* a malformed surface: the rest still loads */
        return pc_model_add_skipped(f->ctx, model, "%s (%s)", origin,
                                    f->ctx ? projcurve_context_message(f->ctx) : "malformed");
    if (st != PROJCURVE_OK)
        return st;
    if (skip == pc_step_refused_reason)
        return pc_model_add_skipped(f->ctx, model, "%s (%s)", origin,
                                    f->ctx ? projcurve_context_message(f->ctx) : skip);
    if (skip != NULL)
        return pc_model_add_skipped(f->ctx, model, "%s (%s)", origin, skip);
    if ((st = pc_model_add_surface_kind(f->ctx, model, &a.nurbs, origin, a.kind)) != PROJCURVE_OK)
        return st;
    /* the faces on it find it, with the maps their pcurves go through */
    const size_t at = (size_t)(inst - f->instances);
    if (f->surface_of != NULL)
        f->surface_of[at] = (long)model->n_surfaces - 1;
    if (f->maps_of != NULL) {
        f->maps_of[2 * at] = a.map_u;
        f->maps_of[2 * at + 1] = a.map_v;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_step_read_analytic(pc_step_file *f, projcurve_model *model)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    gather g = {.f = f, .arena = &arena};
    char name[PC_STEP_MAX_NAME];
    projcurve_status st = PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        const pc_step_instance *inst = &f->instances[i];
        if (pc_step_name(f, inst, name) &&
            (strcmp(name, "ADVANCED_FACE") == 0 || strcmp(name, "FACE_SURFACE") == 0)) {
            st = face_points(&g, inst);
            /* A face whose bounds are malformed bounds its surface by the
             * points read before the fault; it is listed with the reason. */
            if (st == PROJCURVE_ERR_PARSE)
                st = pc_model_add_skipped(f->ctx, model, "STEP #%ld %s (its bounds: %s)", inst->id,
                                          name, f->ctx ? projcurve_context_message(f->ctx) : "malformed");
        }
        pc_arena_release(&arena);
    }
    if (st == PROJCURVE_OK && g.count > 1)
        qsort(g.items, g.count, sizeof *g.items, by_surface);
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        const pc_step_instance *inst = &f->instances[i];
        if (pc_step_name(f, inst, name) && pc_step_is_analytic_surface(name))
            st = read_one(f, &arena, model, &g, inst, name);
        pc_arena_release(&arena);
    }
    PC_ARRAY_FREE(&g);
    pc_arena_release(&arena);
    return st;
}
