/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Chaining face pieces across shared edges (shapeproj/chain.h).
 */
#include "shapeproj/chain.h"

#include <math.h>
#include <stdlib.h>

#include "brep/shape.h"
#include "common/error.h"
#include "geom/curve.h"

typedef struct node {
    size_t part, branch;
    const pc_branch_trim *trim;
    pc_vec3 s_start, s_end, p_start, p_end;
    double t_lo;  /* smallest t of the piece */
    double depth; /* of its first point: along Dir, or the distance */
    size_t next, prev; /* SIZE_MAX: none */
    int done;
    projcurve_branch_start start;
    projcurve_branch_end end;
} node;

#define NONE ((size_t)-1)

static pc_vec3 surface_point(const projcurve_face *f, const double uv[2])
{
    pc_vec3 s;
    pc_nurbs_surface_eval(&f->surface->nurbs, uv[0], uv[1], 0, NULL, NULL, &s);
    return s;
}

static projcurve_status fill_node(projcurve_context *ctx, const pc_face_part *part, size_t b,
                                  const projcurve_curve *curve, const pc_projection_spec *spec,
                                  node *n)
{
    const pc_branch_trim *tr = &part->trims[b];
    n->trim = tr;
    n->s_start = surface_point(part->f, tr->start.uv);
    n->s_end = surface_point(part->f, tr->end.uv);
    projcurve_status st = pc_curve_eval(curve, tr->start.t, 0, NULL, &n->p_start);
    if (st == PROJCURVE_OK)
        st = pc_curve_eval(curve, tr->end.t, 0, NULL, &n->p_end);
    if (st != PROJCURVE_OK)
        return pc_fail(ctx, st, "the curve could not be evaluated while chaining");
    n->t_lo = fmin(tr->start.t, tr->end.t);
    const pc_vec3 d = vec3_sub(n->s_start, n->p_start);
    n->depth = spec->kind == PROJCURVE_PROJECT_DIRECTIONAL ? vec3_dot(d, spec->vec)
                                                          : vec3_norm(d);
    n->next = n->prev = NONE;
    n->done = 0;
    n->start = part->result->branches[b].start;
    n->end = part->result->branches[b].end;
    return PROJCURVE_OK;
}

static size_t edge_uses(const projcurve_shape *shape, long id)
{
    size_t lo = 0, hi = shape ? shape->n_edges : 0;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (shape->edges[mid].id < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < (shape ? shape->n_edges : 0) && shape->edges[lo].id == id
               ? shape->edges[lo].n_uses
               : 0;
}

/* The continuation of node a: the nearest start on the same edge within
 * tol; or, on a closed curve, the piece of the same face that starts the
 * curve where a ends it (closed: the curve's ends meet within tol). */
static size_t find_next(const node *nodes, size_t n, size_t a, double tol, int closed)
{
    const pc_trim_end *e = &nodes[a].trim->end;
    const int wraps = closed && nodes[a].end == PROJCURVE_END_CURVE_END;
    if (!wraps && (!e->on_loop || e->edge < 0))
        return NONE;
    size_t best = NONE;
    double best_d = INFINITY;
    for (size_t b = 0; b < n; ++b) {
        const pc_trim_end *s = &nodes[b].trim->start;
        /* b == a: a piece closing on itself (a closed curve projected
         * whole, across a seam edge or at the curve's ends) */
        if (nodes[b].prev != NONE)
            continue;
        if (wraps ? nodes[b].start != PROJCURVE_START_CURVE_START || nodes[b].part != nodes[a].part
                  : !s->on_loop || s->edge != e->edge)
            continue;
        const double d = vec3_dist(nodes[a].s_end, nodes[b].s_start);
        if (d <= tol && vec3_dist(nodes[a].p_end, nodes[b].p_start) <= tol && d < best_d) {
            best = b;
            best_d = d;
        }
    }
    return best;
}

static int node_before(const node *x, const node *y)
{
    if (x->t_lo != y->t_lo)
        return x->t_lo < y->t_lo;
    if (x->depth != y->depth)
        return x->depth < y->depth;
    if (x->part != y->part)
        return x->part < y->part;
    return x->branch < y->branch;
}

typedef struct chain_sort {
    const node *nodes;
    size_t head;
} chain_sort;

static int by_head(const void *a, const void *b)
{
    const chain_sort *x = a, *y = b;
    const node *p = &x->nodes[x->head], *q = &y->nodes[y->head];
    return node_before(p, q) ? -1 : (node_before(q, p) ? 1 : 0);
}

/* Emits the chain from head into r (refs and one curve). */
static void emit_chain(projcurve_shape_result *r, node *nodes, size_t head)
{
    pc_connected *c = &r->curves[r->n_curves++];
    c->first = r->n_refs;
    c->count = 0;
    c->closed = 0;
    /* bounded: each node is emitted once (done) */
    for (size_t k = head; k != NONE && !nodes[k].done; k = nodes[k].next) {
        nodes[k].done = 1;
        r->refs[r->n_refs++] = (pc_piece_ref){nodes[k].part, nodes[k].branch};
        ++c->count;
        if (nodes[k].next == head)
            c->closed = 1;
    }
}

/* An end with no continuation is a gap when its edge lies between two
 * faces of which one is missing (a single use in a closed shape), or when
 * an end of the other kind waits on the same edge within
 * PC_CHAIN_GAP_FACTOR chaining tolerances (the faces do not meet within
 * the tolerance). Elsewhere it is the end of the projection on that edge:
 * a free border, or a silhouette edge beyond which Dir grazes the next
 * face. */
#define PC_CHAIN_GAP_FACTOR 1000.0

static int is_gap(const node *nodes, size_t n, size_t a, int at_end,
                  const projcurve_shape *shape, double tol)
{
    const pc_trim_end *e = at_end ? &nodes[a].trim->end : &nodes[a].trim->start;
    if (shape == NULL || !e->on_loop || e->edge < 0)
        return 0;
    const size_t uses = edge_uses(shape, e->edge);
    if (uses <= 1)
        return shape->kind == PROJCURVE_SHAPE_SOLID || shape->kind == PROJCURVE_SHAPE_CLOSED_SHELL;
    const pc_vec3 x = at_end ? nodes[a].s_end : nodes[a].s_start;
    for (size_t b = 0; b < n; ++b) {
        const pc_trim_end *o = at_end ? &nodes[b].trim->start : &nodes[b].trim->end;
        const size_t link = at_end ? nodes[b].prev : nodes[b].next;
        if (b == a || link != NONE || !o->on_loop || o->edge != e->edge)
            continue;
        const pc_vec3 y = at_end ? nodes[b].s_start : nodes[b].s_end;
        if (vec3_dist(x, y) <= PC_CHAIN_GAP_FACTOR * tol)
            return 1;
    }
    return 0;
}

static projcurve_status link_and_emit(projcurve_context *ctx, projcurve_shape_result *r,
                                      node *nodes, size_t n, const projcurve_shape *shape,
                                      int closed)
{
    for (size_t a = 0; a < n; ++a) {
        const size_t b = find_next(nodes, n, a, r->chain_tol, closed);
        if (b != NONE) {
            nodes[a].next = b;
            nodes[b].prev = a;
        }
    }
    for (size_t a = 0; a < n; ++a) {
        r->open_ends += nodes[a].next == NONE && is_gap(nodes, n, a, 1, shape, r->chain_tol);
        r->open_ends += nodes[a].prev == NONE && is_gap(nodes, n, a, 0, shape, r->chain_tol);
    }
    chain_sort *heads = malloc((n + 1) * sizeof *heads);
    r->refs = malloc((n + 1) * sizeof *r->refs);
    r->curves = malloc((n + 1) * sizeof *r->curves);
    if (heads == NULL || r->refs == NULL || r->curves == NULL) {
        free(heads);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory chaining face pieces");
    }
    size_t n_heads = 0;
    for (size_t a = 0; a < n; ++a)
        if (nodes[a].prev == NONE)
            heads[n_heads++] = (chain_sort){nodes, a};
    /* closed loops: no head; start each at its first node in the order */
    for (size_t a = 0; a < n; ++a) {
        if (nodes[a].prev == NONE)
            continue;
        size_t k = a, first = a;
        int has_head = 0;
        for (size_t steps = 0; steps < n && k != NONE; ++steps, k = nodes[k].prev)
            if (nodes[k].prev == NONE)
                has_head = 1;
        if (has_head)
            continue;
        k = nodes[a].next;
        for (size_t steps = 0; steps < n && k != a && k != NONE; ++steps, k = nodes[k].next)
            if (node_before(&nodes[k], &nodes[first]))
                first = k;
        if (first == a)
            heads[n_heads++] = (chain_sort){nodes, a};
    }
    qsort(heads, n_heads, sizeof *heads, by_head);
    for (size_t i = 0; i < n_heads; ++i)
        emit_chain(r, nodes, heads[i].head);
    free(heads);
    return PROJCURVE_OK;
}

projcurve_status pc_chain_pieces(projcurve_context *ctx, projcurve_shape_result *r,
                                 const projcurve_shape *shape, const projcurve_curve *curve,
                                 const pc_projection_spec *spec)
{
    size_t n = 0;
    for (size_t i = 0; i < r->n_parts; ++i)
        n += r->parts[i].result ? r->parts[i].result->n_branches : 0;
    node *nodes = malloc((n + 1) * sizeof *nodes);
    if (nodes == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory chaining face pieces");
    size_t m = 0;
    projcurve_status st = PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < r->n_parts; ++i)
        for (size_t b = 0; st == PROJCURVE_OK && r->parts[i].result &&
                           b < r->parts[i].result->n_branches;
             ++b) {
            nodes[m].part = i;
            nodes[m].branch = b;
            st = fill_node(ctx, &r->parts[i], b, curve, spec, &nodes[m]);
            ++m;
        }
    int closed = 0;
    if (st == PROJCURVE_OK) {
        pc_vec3 e0, e1;
        st = pc_curve_eval(curve, curve->t0, 0, NULL, &e0);
        if (st == PROJCURVE_OK)
            st = pc_curve_eval(curve, curve->t1, 0, NULL, &e1);
        if (st != PROJCURVE_OK)
            st = pc_fail(ctx, st, "the curve could not be evaluated while chaining");
        closed = st == PROJCURVE_OK && vec3_dist(e0, e1) <= r->chain_tol;
    }
    if (st == PROJCURVE_OK)
        st = link_and_emit(ctx, r, nodes, n, shape, closed);
    free(nodes);
    return st;
}
