/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP topology: ADVANCED_FACE (its surface, same_sense, FACE_OUTER_BOUND /
 * FACE_BOUND with their orientation), EDGE_LOOP of ORIENTED_EDGEs, each an
 * EDGE_CURVE between VERTEX_POINTs whose geometry is a SURFACE_CURVE or
 * SEAM_CURVE with PCURVEs (a DEFINITIONAL_REPRESENTATION of a 2D B-spline
 * or LINE), or a bare 3D curve; shapes from MANIFOLD_SOLID_BREP,
 * BREP_WITH_VOIDS, SHELL_BASED_SURFACE_MODEL and the CLOSED_SHELL /
 * OPEN_SHELL no solid or model holds. Edges are shared by EDGE_CURVE id.
 *
 * A loop piece is the face's own PCURVE when the edge has one on the face's
 * surface (step_pcurve.c); otherwise the 3D edge is projected onto the surface point by
 * point with the library's closest-point projection ([Ook]), sampled
 * until the chords' midpoints are within the file's precision of the edge
 * (step_edge_projection.c). A face that cannot be built is listed on the
 * model with the reason; the rest of the file still loads. Placements of
 * assemblies are not applied, as for the geometry (step_read.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brep/shape.h"
#include "common/error.h"
#include "io/step_topology.h"

/* Pieces of a loop may miss each other by this many ON tolerances: files
 * keep edges to their own tolerance, often above the global one. */
#define PC_STEP_CLOSE_FACTOR 100.0

projcurve_status pc_step_give_up(const stopo *t, const char *fmt, long id, const char *what)
{
    if (!t->reason[0])
        snprintf(t->reason, PC_STEP_REASON, fmt, id, what);
    return PROJCURVE_OK;
}

projcurve_status pc_step_fetch(const stopo *t, const pc_step_node *ref, long from, pc_step_located *out)
{
    out->inst = NULL;
    out->node = NULL;
    if (ref == NULL || ref->kind != PC_STEP_REF)
        return pc_step_give_up(t, "#%ld: a reference is missing%s", from, "");
    const pc_step_instance *inst = pc_step_find(t->f, ref->ref);
    if (inst == NULL) {
        char what[48];
        snprintf(what, sizeof what, " #%ld, which is not defined", ref->ref);
        return pc_step_give_up(t, "#%ld refers to%s", from, what);
    }
    pc_step_node *node;
    projcurve_status st = pc_step_parse(t->f, inst, t->arena, &node);
    if (st == PROJCURVE_ERR_PARSE) /* a malformed instance spoils this face only */
        return pc_step_give_up(t, "#%ld: %s", ref->ref, projcurve_context_message(t->f->ctx));
    if (st != PROJCURVE_OK)
        return st;
    out->inst = inst;
    out->node = node;
    return PROJCURVE_OK;
}

static int is_true(const pc_step_node *n)
{
    return !(n && n->kind == PC_STEP_ENUM && n->len == 1 && n->text[0] == 'F');
}

static const char *surface_kind(const pc_step_node *n)
{
    static const char *const names[][2] = {
        {"PLANE", "plane"},           {"CYLINDRICAL_SURFACE", "cylinder"},
        {"CONICAL_SURFACE", "cone"},  {"SPHERICAL_SURFACE", "sphere"},
        {"TOROIDAL_SURFACE", "torus"}, {"SURFACE_OF_REVOLUTION", "revolution"},
        {"SURFACE_OF_LINEAR_EXTRUSION", "extrusion"}, {"OFFSET_SURFACE", "offset"},
        {"DEGENERATE_TOROIDAL_SURFACE", "torus"}};
    for (size_t k = 0; k < sizeof names / sizeof *names; ++k)
        if (pc_step_is(n, names[k][0]) || pc_step_part(n, names[k][0]) != NULL)
            return names[k][1];
    if (pc_step_part(n, "B_SPLINE_SURFACE") != NULL || pc_step_is(n, "B_SPLINE_SURFACE_WITH_KNOTS") ||
        pc_step_is(n, "BEZIER_SURFACE") || pc_step_is(n, "UNIFORM_SURFACE") ||
        pc_step_is(n, "QUASI_UNIFORM_SURFACE"))
        return "bspline";
    return "other";
}

/* The model surface of the surface instance ref: the one place where a
 * file's surface becomes the surface of a face. B-spline surfaces are the
 * model surfaces read by step_read.c, analytic ones those of
 * step_face_points.c with their maps (*maps, NULL when both are the
 * identity); any other kind gives its name in *kind and the reason. */
static projcurve_status face_surface(const stopo *t, const pc_step_node *ref, long from,
                                     const projcurve_surface **out, const char **kind,
                                     const pc_angle_map **maps)
{
    *out = NULL;
    *kind = "other";
    *maps = NULL;
    pc_step_located s;
    projcurve_status st = pc_step_fetch(t, ref, from, &s);
    if (st != PROJCURVE_OK || s.inst == NULL)
        return st;
    *kind = surface_kind(s.node);
    const long index = t->f->surface_of[s.inst - t->f->instances];
    if (index < 0)
        return pc_step_give_up(t, "surface #%ld: surface kind %s not built", s.inst->id, *kind);
    *out = t->model->surfaces[index];
    const pc_angle_map *m = t->f->maps_of + 2 * (s.inst - t->f->instances);
    if (m[0].is_angle || m[1].is_angle)
        *maps = m;
    return PROJCURVE_OK;
}

/* Pieces of the face being read. */
typedef struct pieces {
    pc_piece_input *items;
    size_t count, capacity;
    pc_loop_input *loops;
    size_t n_loops, cap_loops;
    int has_outer;
} pieces;

static pc_piece_input *new_piece(const stopo *t, pieces *p)
{
    if (p->count == p->capacity) {
        const size_t fresh = p->capacity ? 2 * p->capacity : 16;
        pc_piece_input *items = pc_arena_calloc(t->arena, fresh, sizeof *items);
        if (items == NULL)
            return NULL;
        if (p->count)
            memcpy(items, p->items, p->count * sizeof *items);
        p->items = items;
        p->capacity = fresh;
    }
    return &p->items[p->count++];
}

/* The vertices of an EDGE_CURVE as 3D points. */
static projcurve_status vertices(const stopo *t, const pc_step_located *edge, double a[3], double b[3])
{
    for (int k = 0; k < 2; ++k) {
        pc_step_located v;
        projcurve_status st = pc_step_fetch(t, pc_step_child(edge->node, 1 + (size_t)k), edge->inst->id, &v);
        if (st != PROJCURVE_OK || v.inst == NULL)
            return st;
        if (!pc_step_is(v.node, "VERTEX_POINT"))
            return pc_step_give_up(t, "#%ld: an edge vertex is not a VERTEX_POINT%s", v.inst->id, "");
        st = pc_step_point(t->f, t->arena, v.inst, pc_step_child(v.node, 1), k ? b : a);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}





/* One ORIENTED_EDGE of a loop as a piece. */
static projcurve_status edge_piece(const stopo *t, const pc_step_node *ref, long loop_id,
                                   int bound_sense, const projcurve_surface *s, long surface_id,
                                   pieces *p)
{
    pc_step_located oe, edge, geom;
    projcurve_status st = pc_step_fetch(t, ref, loop_id, &oe);
    if (st != PROJCURVE_OK || oe.inst == NULL)
        return st;
    if (!pc_step_is(oe.node, "ORIENTED_EDGE"))
        return pc_step_give_up(t, "#%ld: a loop member is not an ORIENTED_EDGE%s", oe.inst->id, "");
    if ((st = pc_step_fetch(t, pc_step_child(oe.node, 3), oe.inst->id, &edge)) != PROJCURVE_OK || edge.inst == NULL)
        return st;
    if (!pc_step_is(edge.node, "EDGE_CURVE"))
        return pc_step_give_up(t, "#%ld: an oriented edge's element is not an EDGE_CURVE%s", edge.inst->id, "");
    if ((st = pc_step_fetch(t, pc_step_child(edge.node, 3), edge.inst->id, &geom)) != PROJCURVE_OK || geom.inst == NULL)
        return st;
    const int oe_sense = is_true(pc_step_child(oe.node, 4)) ? 1 : -1;
    const int same = is_true(pc_step_child(edge.node, 4)) ? 1 : -1;
    double va[3], vb[3];
    if ((st = vertices(t, &edge, va, vb)) != PROJCURVE_OK || t->reason[0])
        return st;
    pc_piece_input *piece = new_piece(t, p);
    if (piece == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    unsigned flags = 0;
    const int seam = pc_step_is(geom.node, "SEAM_CURVE");
    pc_step_located found[2];
    size_t n_found = 0;
    if (seam || pc_step_is(geom.node, "SURFACE_CURVE"))
        st = pc_step_pcurves_on(t, &geom, surface_id, found, &n_found);
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if (n_found > 0) {
        /* a seam's first pcurve for the edge used forwards, the second backwards */
        const pc_step_located *c = &found[(seam && n_found == 2 && oe_sense < 0) ? 1 : 0];
        st = pc_step_is(c->node, "LINE") ? pc_step_line_piece(t, c, s, same > 0 ? va : vb, same > 0 ? vb : va, piece)
                                         : pc_step_bspline_piece(t, c, piece);
        if (st == PROJCURVE_OK && !t->reason[0] && t->maps != NULL)
            st = pc_step_piece_to_nurbs(t, s, c->inst->id, piece);
        pc_step_located curve3 = {NULL, NULL};
        if (st == PROJCURVE_OK && !t->reason[0])
            st = pc_step_fetch(t, pc_step_child(geom.node, 1), geom.inst->id, &curve3);
        if (st == PROJCURVE_OK && !t->reason[0] && !pc_step_is(c->node, "LINE"))
            st = pc_step_restrict_to_edge(t, s, piece, same > 0 ? va : vb, same > 0 ? vb : va, &curve3);
        if (st == PROJCURVE_OK && !t->reason[0] && curve3.inst != NULL)
            st = pc_step_check_against_curve(t, s, surface_id, edge.inst->id, piece, &curve3);
        flags |= seam ? PC_PIECE_SEAM : 0u;
    } else {
        pc_step_located curve3 = geom;
        if (seam || pc_step_is(geom.node, "SURFACE_CURVE"))
            st = pc_step_fetch(t, pc_step_child(geom.node, 1), geom.inst->id, &curve3);
        if (st == PROJCURVE_OK && curve3.inst != NULL)
            st = pc_step_edge_projection(t, &curve3, s, same > 0 ? va : vb, same > 0 ? vb : va, piece);
    }
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if ((st = pc_step_check_piece(t, s, surface_id, edge.inst->id, piece, same > 0 ? va : vb,
                          same > 0 ? vb : va, &flags)) != PROJCURVE_OK)
        return st;
    piece->edge = edge.inst->id;
    piece->edge_sense = same;
    piece->sense = bound_sense * oe_sense * same;
    piece->flags = flags;
    return PROJCURVE_OK;
}

static int push_loop(const stopo *t, pieces *p, size_t first, int outer)
{
    if (p->n_loops == p->cap_loops) {
        const size_t fresh = p->cap_loops ? 2 * p->cap_loops : 8;
        pc_loop_input *loops = pc_arena_calloc(t->arena, fresh, sizeof *loops);
        if (loops == NULL)
            return 0;
        if (p->n_loops)
            memcpy(loops, p->loops, p->n_loops * sizeof *loops);
        p->loops = loops;
        p->cap_loops = fresh;
    }
    p->loops[p->n_loops++] = (pc_loop_input){.n_pieces = p->count - first, .outer = outer};
    return 1;
}

/* The pieces from first on of a loop on an analytic surface: moved by
 * the turns that join them, poles bridged. */
static projcurve_status analytic_loop(const stopo *t, const projcurve_surface *s, pieces *p,
                                      size_t first)
{
    const size_t n = p->count - first;
    projcurve_status st = pc_step_join_turns(t, p->items + first, n);
    pc_piece_input *out = st == PROJCURVE_OK ? pc_arena_calloc(t->arena, 2 * n, sizeof *out) : NULL;
    if (st != PROJCURVE_OK)
        return st;
    size_t n_out = 0;
    if (out == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    if ((st = pc_step_bridge_poles(t, s, p->items + first, n, out, &n_out)) != PROJCURVE_OK)
        return st;
    p->count = first;
    for (size_t i = 0; i < n_out; ++i) {
        pc_piece_input *piece = new_piece(t, p);
        if (piece == NULL)
            return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
        *piece = out[i];
    }
    return PROJCURVE_OK;
}

/* A FACE_OUTER_BOUND / FACE_BOUND and its EDGE_LOOP. */
static projcurve_status read_bound(const stopo *t, const pc_step_node *ref, long face_id,
                                   const projcurve_surface *s, long surface_id, pieces *p)
{
    pc_step_located bound, loop;
    projcurve_status st = pc_step_fetch(t, ref, face_id, &bound);
    if (st != PROJCURVE_OK || bound.inst == NULL)
        return st;
    const int outer = pc_step_is(bound.node, "FACE_OUTER_BOUND");
    if (!outer && !pc_step_is(bound.node, "FACE_BOUND"))
        return pc_step_give_up(t, "#%ld: a bound is not a FACE_BOUND%s", bound.inst->id, "");
    if ((st = pc_step_fetch(t, pc_step_child(bound.node, 1), bound.inst->id, &loop)) != PROJCURVE_OK ||
        loop.inst == NULL)
        return st;
    if (pc_step_is(loop.node, "VERTEX_LOOP"))
        return PROJCURVE_OK; /* a pole: it bounds nothing in (u, v) (a face of such bounds only
                                has its surface's natural boundary) */
    const pc_step_node *edges = pc_step_child(loop.node, 1);
    if (!pc_step_is(loop.node, "EDGE_LOOP") || edges == NULL || edges->kind != PC_STEP_LIST ||
        edges->first == NULL)
        return pc_step_give_up(t, "#%ld: not an EDGE_LOOP with edges%s", loop.inst->id, "");
    const int sense = is_true(pc_step_child(bound.node, 2)) ? 1 : -1;
    const size_t first = p->count;
    for (const pc_step_node *e = edges->first; e != NULL && st == PROJCURVE_OK && !t->reason[0]; e = e->next)
        st = edge_piece(t, e, loop.inst->id, sense, s, surface_id, p);
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if (sense < 0) /* the bound runs the loop backwards: its edges in reverse order */
        for (size_t i = first, j = p->count - 1; i < j; ++i, --j) {
            const pc_piece_input tmp = p->items[i];
            p->items[i] = p->items[j];
            p->items[j] = tmp;
        }
    if (t->maps != NULL && (st = analytic_loop(t, s, p, first)) != PROJCURVE_OK)
        return st;
    p->has_outer |= outer;
    return push_loop(t, p, first, outer)
               ? PROJCURVE_OK
               : pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
}

/* Marks pieces whose edge appears twice in one loop as seams. */
static void mark_seams(pieces *p)
{
    size_t at = 0;
    for (size_t l = 0; l < p->n_loops; ++l) {
        for (size_t i = at; i < at + p->loops[l].n_pieces; ++i)
            for (size_t j = i + 1; j < at + p->loops[l].n_pieces; ++j)
                if (p->items[i].edge >= 0 && p->items[i].edge == p->items[j].edge) {
                    p->items[i].flags |= PC_PIECE_SEAM;
                    p->items[j].flags |= PC_PIECE_SEAM;
                }
        at += p->loops[l].n_pieces;
    }
}

static projcurve_status read_face(stopo *t, const pc_step_located *face)
{
    char reason[PC_STEP_REASON] = "";
    t->reason = reason;
    const projcurve_surface *s = NULL;
    const char *kind = "other";
    const pc_step_node *sref = pc_step_child(face->node, 2);
    projcurve_status st = face_surface(t, sref, face->inst->id, &s, &kind, &t->maps);
    t->analytic = strcmp(kind, "bspline") != 0;
    pieces p = {0};
    const pc_step_node *bounds = pc_step_child(face->node, 1);
    if (st == PROJCURVE_OK && !reason[0] && (bounds == NULL || bounds->kind != PC_STEP_LIST))
        pc_step_give_up(t, "#%ld: its bounds are not a list%s", face->inst->id, "");
    for (const pc_step_node *b = reason[0] ? NULL : bounds->first; b != NULL && st == PROJCURVE_OK && !reason[0]; b = b->next)
        st = read_bound(t, b, face->inst->id, s, sref->ref, &p);
    if (st != PROJCURVE_OK)
        return st;
    char what[64];
    snprintf(what, sizeof what, "STEP #%ld ADVANCED_FACE", face->inst->id);
    if (reason[0])
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s: %s", what, reason);
    mark_seams(&p);
    size_t at = 0;
    for (size_t l = 0; l < p.n_loops; ++l) {
        p.loops[l].pieces = p.items + at;
        at += p.loops[l].n_pieces;
    }
    const double tol_model = pc_step_precision(t, s);
    const double tol_uv = pc_face_uv_tolerance(s, tol_model);
    const pc_face_params fp = {.tol_uv = tol_uv, .tol_model = tol_model,
                               .close_tol = PC_STEP_CLOSE_FACTOR * tol_uv,
                               .same_sense = is_true(pc_step_child(face->node, 3)) ? 1 : -1,
                               .pick_outer = !p.has_outer, .id = face->inst->id, .kind = kind,
                               .what = what};
    projcurve_context scratch = {.magic = PC_CONTEXT_MAGIC};
    projcurve_face *f = NULL;
    st = pc_face_build(&scratch, s, p.loops, p.n_loops, &fp, &f);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(t->f->ctx, st, "%s", scratch.last_message);
    if (st != PROJCURVE_OK)
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s", scratch.last_message);
    t->face_of[face->inst - t->f->instances] = (long)t->model->n_faces;
    return pc_model_add_face(t->f->ctx, t->model, f);
}

/* 1 when a simple instance is of one of the names (NULL-terminated list),
 * read from its text without parsing it: the passes below look at a few
 * kinds among thousands of points. */
static int named(const pc_step_file *f, const pc_step_instance *inst, const char *const *names)
{
    size_t pos = inst->begin;
    while (pos < inst->end && (f->text[pos] == ' ' || f->text[pos] == '\n' ||
                               f->text[pos] == '\r' || f->text[pos] == '\t'))
        ++pos;
    size_t len = 0;
    while (pos + len < inst->end && (f->text[pos + len] == '_' ||
                                     (f->text[pos + len] >= 'A' && f->text[pos + len] <= 'Z') ||
                                     (f->text[pos + len] >= '0' && f->text[pos + len] <= '9')))
        ++len;
    for (; *names != NULL; ++names)
        if (strlen(*names) == len && strncmp(f->text + pos, *names, len) == 0)
            return 1;
    return 0;
}

static const char *const face_names[] = {"ADVANCED_FACE", "FACE_SURFACE", NULL};
static const char *const shape_names[] = {"MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS",
                                          "SHELL_BASED_SURFACE_MODEL", "CLOSED_SHELL",
                                          "OPEN_SHELL", NULL};
static const char *const precision_names[] = {"UNCERTAINTY_MEASURE_WITH_UNIT", NULL};

/* The largest UNCERTAINTY_MEASURE_WITH_UNIT length (0 if none). */
static double file_precision(const stopo *t, const pc_step_node *node)
{
    if (!pc_step_is(node, "UNCERTAINTY_MEASURE_WITH_UNIT"))
        return t->precision;
    const pc_step_node *m = pc_step_child(node, 0);
    const pc_step_node *v = m && m->kind == PC_STEP_TYPED ? pc_step_child(m, 0) : m;
    if (v && v->kind == PC_STEP_NUMBER && v->number > 0.0 && isfinite(v->number))
        return fmax(t->precision, v->number);
    return t->precision;
}

/* Model face indices of the faces of a shell, appended to idx. */
static projcurve_status shell_faces(stopo *t, const pc_step_node *ref, long from, size_t *idx,
                                    size_t *n, size_t cap, unsigned char *used,
                                    projcurve_shape_kind *kind)
{
    char reason[PC_STEP_REASON] = "";
    t->reason = reason;
    pc_step_located shell;
    projcurve_status st = pc_step_fetch(t, ref, from, &shell);
    if (st != PROJCURVE_OK || shell.inst == NULL)
        return st;
    used[shell.inst - t->f->instances] = 1;
    if (kind != NULL)
        *kind = pc_step_is(shell.node, "CLOSED_SHELL") ? PROJCURVE_SHAPE_CLOSED_SHELL
                                                       : PROJCURVE_SHAPE_OPEN_SHELL;
    const pc_step_node *faces = pc_step_child(shell.node, 1);
    if (faces == NULL || faces->kind != PC_STEP_LIST)
        return PROJCURVE_OK;
    for (const pc_step_node *r = faces->first; r != NULL && *n < cap; r = r->next) {
        const pc_step_instance *fi = r->kind == PC_STEP_REF ? pc_step_find(t->f, r->ref) : NULL;
        const long index = fi ? t->face_of[fi - t->f->instances] : -1;
        if (index >= 0)
            idx[(*n)++] = (size_t)index;
    }
    return PROJCURVE_OK;
}

static projcurve_status add_shape(stopo *t, projcurve_shape_kind kind, long id, size_t *idx,
                                  size_t n)
{
    if (n == 0)
        return PROJCURVE_OK;
    const projcurve_face **faces = malloc(n * sizeof *faces);
    if (faces == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < n; ++i)
        faces[i] = t->model->faces[idx[i]];
    projcurve_shape *shape = NULL;
    projcurve_status st = pc_shape_build(t->f->ctx, kind, id, faces, idx, n, &shape);
    free(faces);
    return st == PROJCURVE_OK ? pc_model_add_shape(t->f->ctx, t->model, shape) : st;
}

/* Solids and surface models first, then the shells none of them holds. */
static projcurve_status read_shapes(stopo *t, size_t *idx, unsigned char *used)
{
    const size_t cap = t->model->n_faces;
    projcurve_status st = PROJCURVE_OK;
    for (int pass = 0; pass < 2 && st == PROJCURVE_OK; ++pass)
        for (size_t i = 0; i < t->f->n_instances && st == PROJCURVE_OK; ++i) {
            const pc_step_instance *inst = &t->f->instances[i];
            pc_step_node *node;
            if (!named(t->f, inst, shape_names))
                continue;
            st = pc_step_parse(t->f, inst, t->arena, &node);
            if (st == PROJCURVE_ERR_PARSE) { /* listed; the other shapes go on */
                st = pc_model_add_skipped(t->f->ctx, t->model, "STEP #%ld (a shape): %s", inst->id,
                                          projcurve_context_message(t->f->ctx));
                pc_arena_release(t->arena);
                continue;
            }
            if (st != PROJCURVE_OK)
                break;
            size_t n = 0;
            projcurve_shape_kind kind = PROJCURVE_SHAPE_SOLID;
            const int solid = pc_step_is(node, "MANIFOLD_SOLID_BREP") || pc_step_is(node, "BREP_WITH_VOIDS");
            const int model = pc_step_is(node, "SHELL_BASED_SURFACE_MODEL");
            const int shell = pc_step_is(node, "CLOSED_SHELL") || pc_step_is(node, "OPEN_SHELL");
            if (pass == 0 && solid) {
                st = shell_faces(t, pc_step_child(node, 1), inst->id, idx, &n, cap, used, NULL);
                const pc_step_node *voids = pc_step_is(node, "BREP_WITH_VOIDS") ? pc_step_child(node, 2) : NULL;
                for (const pc_step_node *v = voids && voids->kind == PC_STEP_LIST ? voids->first : NULL;
                     v != NULL && st == PROJCURVE_OK; v = v->next)
                    st = shell_faces(t, v, inst->id, idx, &n, cap, used, NULL);
            } else if (pass == 0 && model) {
                const pc_step_node *shells = pc_step_child(node, 1);
                for (const pc_step_node *r = shells && shells->kind == PC_STEP_LIST ? shells->first : NULL;
                     r != NULL && st == PROJCURVE_OK; r = r->next) {
                    n = 0;
                    st = shell_faces(t, r, inst->id, idx, &n, cap, used, &kind);
                    if (st == PROJCURVE_OK)
                        st = add_shape(t, kind, r->kind == PC_STEP_REF ? r->ref : -1, idx, n);
                }
                n = 0;
            } else if (pass == 1 && shell && !used[i]) {
                const pc_step_node self = {.kind = PC_STEP_REF, .ref = inst->id};
                st = shell_faces(t, &self, inst->id, idx, &n, cap, used, &kind);
            }
            if (st == PROJCURVE_OK && n > 0)
                st = add_shape(t, kind, inst->id, idx, n);
            pc_arena_release(t->arena);
        }
    return st;
}

projcurve_status pc_step_read_topology(pc_step_file *f, projcurve_model *model)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    char none[1] = "";
    stopo t = {.f = f, .model = model, .arena = &arena, .reason = none};
    t.face_of = malloc((f->n_instances + 1) * sizeof *t.face_of);
    unsigned char *used = calloc(f->n_instances + 1, 1);
    projcurve_status st = PROJCURVE_OK;
    if (t.face_of == NULL || used == NULL)
        st = pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; st == PROJCURVE_OK && i <= f->n_instances; ++i)
        t.face_of[i] = -1;
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        pc_step_node *node;
        if (!named(f, &f->instances[i], precision_names))
            continue;
        st = pc_step_parse(f, &f->instances[i], &arena, &node);
        if (st == PROJCURVE_OK)
            t.precision = file_precision(&t, node);
        pc_arena_release(&arena);
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        pc_step_node *node;
        if (!named(f, &f->instances[i], face_names))
            continue;
        st = pc_step_parse(f, &f->instances[i], &arena, &node);
        if (st == PROJCURVE_ERR_PARSE) /* listed; the other faces go on */
            st = pc_model_add_unbuilt(f->ctx, model, "other", "STEP #%ld (a face): %s",
                                      f->instances[i].id, projcurve_context_message(f->ctx));
        else if (st == PROJCURVE_OK && (pc_step_is(node, "ADVANCED_FACE") || pc_step_is(node, "FACE_SURFACE"))) {
            const pc_step_located face = {&f->instances[i], node};
            st = read_face(&t, &face);
        }
        pc_arena_release(&arena);
    }
    size_t *idx = st == PROJCURVE_OK ? malloc((model->n_faces + 1) * sizeof *idx) : NULL;
    if (st == PROJCURVE_OK && idx == NULL)
        st = pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    if (st == PROJCURVE_OK)
        st = read_shapes(&t, idx, used);
    free(idx);
    free(used);
    free(t.face_of);
    pc_arena_release(&arena);
    return st;
}
