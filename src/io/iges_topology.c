/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES topology: trimmed surfaces (144: a base surface, an outer curve on
 * surface 142 or the natural boundary, inner 142s), bounded surfaces (143
 * with 141 boundaries) and untrimmed surfaces (a 128 that bounds no 144 or
 * 143 is a face on its whole domain, as CAD readers take it). The loops
 * are the parameter-space curves (BPTR of 142, PSCPT of 141); each member
 * of a composite 102 is a piece of its own; on an analytic base surface a
 * 144's loops are its 142s' model-space curves (CPTR), and a 143's its
 * 141s' (CRVPT), mapped onto the surface's NURBS instead (iges_face_map.c). All faces of a file make one
 * shape of independent faces: IGES 144 shares no edge records.
 *
 * A face that cannot be built (a surface kind not built, a loop without
 * parameter-space curve, an open loop, a hole outside) is listed on the
 * model with the reason, and the rest of the file still loads.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brep/face.h"
#include "brep/sew.h"
#include "brep/shape.h"
#include "common/error.h"
#include "io/iges.h"

/* Global field 19, the minimum user-intended resolution, when the file
 * does not give one: a fraction of the model's size. */
#define PC_IGES_DEFAULT_RESOLUTION_REL 1e-7
#define PC_IGES_GLOBAL_RESOLUTION_FIELD 19
/* Pieces of a loop may miss each other by this many ON tolerances. */
#define PC_IGES_CLOSE_FACTOR 10.0
#define PC_IGES_MAX_LOOP_PIECES 100000
#define PC_IGES_REASON 160

typedef struct topo {
    pc_iges_file *f;
    projcurve_model *model;
    unsigned char *consumed;
    double resolution;
} topo;

/* Field 19 of the global section (0 when absent or unreadable). Fields are
 * separated by the parameter delimiter; Hollerith strings (nH...) may hold
 * it, so their n characters are skipped whole. */
static double global_resolution(const pc_iges_file *f)
{
    const pc_iges_section *g = &f->sec[1];
    char text[PC_IGES_DATA_COLUMNS * 64 + 1];
    size_t len = 0;
    for (size_t r = 0; r < g->count && len + PC_IGES_DATA_COLUMNS < sizeof text; ++r) {
        memcpy(text + len, g->records[r], PC_IGES_DATA_COLUMNS);
        len += PC_IGES_DATA_COLUMNS;
    }
    text[len] = '\0';
    size_t field = 1, pos = 0;
    while (pos < len && field < PC_IGES_GLOBAL_RESOLUTION_FIELD) {
        size_t digits = pos;
        while (digits < len && text[digits] == ' ')
            ++digits;
        size_t end = digits;
        while (end < len && text[end] >= '0' && text[end] <= '9')
            ++end;
        if (end > digits && end < len && text[end] == 'H')
            pos = end + 1 + (size_t)strtoul(text + digits, NULL, 10);
        while (pos < len && text[pos] != f->param_delim && text[pos] != f->record_delim)
            ++pos;
        if (pos >= len || text[pos] == f->record_delim)
            return 0.0;
        ++pos;
        ++field;
    }
    const double r = strtod(text + pos, NULL);
    return isfinite(r) && r > 0.0 ? r : 0.0;
}

static void mark(const topo *t, long de)
{
    if (de > 0 && de % 2 == 1 && (size_t)(de - 1) / 2 < t->f->n_entries)
        t->consumed[(de - 1) / 2] = 1;
}

static const char *surface_kind_name(int type)
{
    switch (type) {
    case 128: return "bspline";
    case 108: case 190: return "plane";
    case 192: return "cylinder";
    case 194: return "cone";
    case 196: return "sphere";
    case 198: return "torus";
    case 118: return "ruled";
    case 120: return "revolution";
    case 122: return "extrusion";
    case 140: return "offset";
    default: return "other";
    }
}

/* The model surface of the surface entity at DE de: the one place where a
 * file's surface entity becomes the surface of a face. B-spline surfaces
 * (128) are the model surfaces read by iges_read.c; so are the analytic
 * ones it built (their exact NURBS), taken where analytic_ok (a 144, whose
 * boundaries are then mapped from their model-space curves: *analytic is
 * set); any other kind gives its name in *kind and a reason. */
static projcurve_status face_surface(const topo *t, long de, size_t from_de, int analytic_ok,
                                     const projcurve_surface **out, const char **kind,
                                     int *analytic, char reason[PC_IGES_REASON])
{
    *out = NULL;
    *analytic = 0;
    *kind = "other";
    const pc_iges_entry *e = pc_iges_entry_at(t->f, de, from_de);
    if (e == NULL) {
        snprintf(reason, PC_IGES_REASON, "its surface DE %ld is not an entity", de);
        return PROJCURVE_OK;
    }
    *kind = surface_kind_name(e->type);
    const long index = t->f->surface_of[(de - 1) / 2];
    *analytic = e->type != 128;
    if (index < 0 || (*analytic && !analytic_ok)) {
        snprintf(reason, PC_IGES_REASON, "surface kind %s (IGES %d at DE %ld) not built", *kind,
                 e->type, de);
        return PROJCURVE_OK;
    }
    *out = t->model->surfaces[index];
    return PROJCURVE_OK;
}

/* The pieces read so far for one face, in the read's arena. */
typedef struct pieces {
    pc_piece_input *items;
    size_t count, capacity;
    pc_loop_input *loops;
    size_t n_loops, cap_loops;
} pieces;

static int push_piece(const topo *t, pieces *p, const pc_io_curve *c, long edge, int sense)
{
    if (p->count == p->capacity) {
        const size_t fresh = p->capacity ? 2 * p->capacity : 16;
        pc_piece_input *items = pc_arena_calloc(t->f->arena, fresh, sizeof *items);
        if (items == NULL)
            return 0;
        if (p->count)
            memcpy(items, p->items, p->count * sizeof *items);
        p->items = items;
        p->capacity = fresh;
    }
    double *uv = pc_arena_calloc(t->f->arena, 2 * c->n_ctrl, sizeof *uv);
    if (uv == NULL)
        return 0;
    for (size_t i = 0; i < c->n_ctrl; ++i)
        uv[2 * i] = c->ctrl[3 * i], uv[2 * i + 1] = c->ctrl[3 * i + 1];
    p->items[p->count++] = (pc_piece_input){.degree = c->degree, .n_ctrl = c->n_ctrl,
                                            .ctrl = uv, .weights = c->weights,
                                            .knots = c->knots, .edge = edge, .sense = sense,
                                            .edge_sense = 1};
    return 1;
}

/* Where a face's boundaries come from model-space curves (a 144 on an
 * analytic surface, iges_face_map.c): the surface and the face's
 * tolerances. */
typedef struct face_map {
    const projcurve_surface *surface;
    double tol_model, tol_uv;
} face_map;

/* The (u, v) a loop's last piece ends at, or NULL at a loop's start. */
static const double *last_end(const pieces *p, size_t first)
{
    if (p->count <= first)
        return NULL;
    const pc_piece_input *q = &p->items[p->count - 1];
    return q->ctrl + 2 * (q->n_ctrl - 1);
}

/* Appends the pieces of the parameter-space curve at DE de (a 102's
 * members one by one, or one curve); with a map, of the model-space curve
 * at de, each inverted onto the map's surface. */
static projcurve_status curve_pieces(const topo *t, long de, size_t from_de, int sense,
                                     const face_map *map, pieces *p, char reason[PC_IGES_REASON])
{
    const pc_iges_entry *e = pc_iges_entry_at(t->f, de, from_de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    size_t n = 1;
    pc_iges_params params;
    if (e->type == 102) {
        projcurve_status st = pc_iges_params_of(t->f, (size_t)de, &params);
        long count = 0;
        if (st == PROJCURVE_OK)
            st = pc_iges_int(&params, 1, &count);
        if (st != PROJCURVE_OK)
            return st;
        if (count < 1 || count > PC_IGES_MAX_LOOP_PIECES || (size_t)count + 2 > params.count)
            return pc_fail(t->f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES entity 102 at DE %ld: %ld curves, but %zu parameters", de, count,
                           params.count);
        n = (size_t)count;
        mark(t, de);
    }
    const size_t first = p->count;
    for (size_t i = 0; i < n; ++i) {
        long member = de;
        if (e->type == 102) {
            projcurve_status st = pc_iges_int(&params, 2 + i, &member);
            if (st != PROJCURVE_OK)
                return st;
            if (pc_iges_entry_at(t->f, member, (size_t)de) == NULL)
                return PROJCURVE_ERR_PARSE;
        }
        pc_io_curve c;
        const char *skip = NULL;
        projcurve_status st = pc_iges_curve(t->f, (size_t)member, &c, &skip);
        if (st != PROJCURVE_OK)
            return st;
        if (skip != NULL) {
            snprintf(reason, PC_IGES_REASON, "its %s curve DE %ld: %s",
                     map ? "model-space" : "parameter", member, skip);
            return PROJCURVE_OK;
        }
        if (map != NULL) {
            pc_io_curve uv;
            st = pc_iges_boundary_by_inversion(t->f, map->surface, &c, map->tol_model,
                                               map->tol_uv, last_end(p, first), &uv, &skip);
            if (st != PROJCURVE_OK)
                return st;
            if (skip != NULL) {
                snprintf(reason, PC_IGES_REASON, "its model-space curve DE %ld: %s", member,
                         skip);
                return PROJCURVE_OK;
            }
            c = uv;
        }
        mark(t, member);
        if (!push_piece(t, p, &c, member, 1))
            return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    }
    if (sense < 0) { /* the loop runs the whole chain backwards */
        for (size_t i = first, j = p->count - 1; i < j; ++i, --j) {
            const pc_piece_input tmp = p->items[i];
            p->items[i] = p->items[j];
            p->items[j] = tmp;
        }
        for (size_t i = first; i < p->count; ++i)
            p->items[i].sense = -1;
    }
    return PROJCURVE_OK;
}

static int push_loop(const topo *t, pieces *p, size_t first, int outer)
{
    if (p->n_loops == p->cap_loops) {
        const size_t fresh = p->cap_loops ? 2 * p->cap_loops : 8;
        pc_loop_input *loops = pc_arena_calloc(t->f->arena, fresh, sizeof *loops);
        if (loops == NULL)
            return 0;
        if (p->n_loops)
            memcpy(loops, p->loops, p->n_loops * sizeof *loops);
        p->loops = loops;
        p->cap_loops = fresh;
    }
    /* pieces are placed once all loops are read: items may move */
    p->loops[p->n_loops++] = (pc_loop_input){.pieces = NULL, .n_pieces = p->count - first,
                                             .outer = outer};
    return 1;
}

/* Marks the curve at DE de (and a 102's members) as read through a face. */
static void mark_curve(const topo *t, long de, size_t from_de)
{
    const pc_iges_entry *c = de != 0 ? pc_iges_entry_at(t->f, de, from_de) : NULL;
    if (c == NULL)
        return;
    mark(t, de);
    pc_iges_params m;
    long n = 0;
    if (c->type == 102 && pc_iges_params_of(t->f, (size_t)de, &m) == PROJCURVE_OK &&
        pc_iges_int(&m, 1, &n) == PROJCURVE_OK)
        for (long i = 0; i < n && (size_t)(2 + i) < m.count; ++i) {
            long member = 0;
            if (pc_iges_int(&m, 2 + (size_t)i, &member) == PROJCURVE_OK)
                mark(t, member);
        }
}

/* A loop from a 142 curve on surface: its BPTR, or with a map its CPTR
 * inverted onto the map's surface. */
static projcurve_status loop_of_142(const topo *t, long de, size_t from_de, int outer,
                                    const face_map *map, pieces *p, char reason[PC_IGES_REASON])
{
    const pc_iges_entry *e = pc_iges_entry_at(t->f, de, from_de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    if (e->type != 142) {
        snprintf(reason, PC_IGES_REASON, "its boundary DE %ld is IGES %d, not a curve on surface", de,
                 e->type);
        return PROJCURVE_OK;
    }
    pc_iges_params params;
    long ptrs[2] = {0, 0}; /* BPTR, CPTR */
    projcurve_status st = pc_iges_params_of(t->f, (size_t)de, &params);
    if (st == PROJCURVE_OK)
        st = pc_iges_ints(&params, 3, 2, ptrs);
    if (st != PROJCURVE_OK)
        return st;
    const long bptr = ptrs[0], cptr = ptrs[1];
    mark(t, de);
    mark_curve(t, cptr, (size_t)de); /* read through the face */
    if (map != NULL) { /* BPTR is in the analytic entity's parameters: CPTR instead */
        mark_curve(t, bptr, (size_t)de);
        if (cptr == 0) {
            snprintf(reason, PC_IGES_REASON,
                     "its curve on surface DE %ld on an analytic surface has no model-space "
                     "curve (CPTR 0) to map onto the surface's NURBS",
                     de);
            return PROJCURVE_OK;
        }
        const size_t first = p->count;
        st = curve_pieces(t, cptr, (size_t)de, 1, map, p, reason);
        if (st != PROJCURVE_OK || reason[0])
            return st;
        return push_loop(t, p, first, outer)
                   ? PROJCURVE_OK
                   : pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    }
    if (bptr == 0) {
        snprintf(reason, PC_IGES_REASON,
                 "its curve on surface DE %ld has no parameter-space curve (BPTR 0)", de);
        return PROJCURVE_OK;
    }
    const size_t first = p->count;
    st = curve_pieces(t, bptr, (size_t)de, 1, NULL, p, reason);
    if (st != PROJCURVE_OK || reason[0])
        return st;
    return push_loop(t, p, first, outer)
               ? PROJCURVE_OK
               : pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
}

/* A face's ON tolerances: the file's resolution (or a fraction of the
 * surface's size) in space, and what it is in (u, v). */
static void face_tolerances(const topo *t, const projcurve_surface *surface, double *tol_model,
                            double *tol_uv)
{
    double box[6];
    projcurve_surface_bounds(NULL, surface, box);
    const double size = hypot(hypot(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
    *tol_model = t->resolution > 0.0 ? t->resolution : PC_IGES_DEFAULT_RESOLUTION_REL * size;
    *tol_uv = pc_face_uv_tolerance(surface, *tol_model);
}

/* Builds the face from the loops read, or lists why it cannot be. */
static projcurve_status finish_face(const topo *t, const projcurve_surface *surface,
                                    const char *kind, pieces *p, size_t de, int type,
                                    const char *reason)
{
    char what[64];
    snprintf(what, sizeof what, "IGES entity %d at DE %zu", type, de);
    if (reason[0]) {
        t->consumed[(de - 1) / 2] = 0; /* also listed as skipped, as before faces were read */
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s: %s", what, reason);
    }
    size_t at = 0;
    for (size_t l = 0; l < p->n_loops; ++l) {
        p->loops[l].pieces = p->items + at;
        at += p->loops[l].n_pieces;
    }
    double tol_model, tol_uv;
    face_tolerances(t, surface, &tol_model, &tol_uv);
    const pc_face_params fp = {.tol_uv = tol_uv, .tol_model = tol_model,
                               .close_tol = PC_IGES_CLOSE_FACTOR * tol_uv, .same_sense = 1,
                               .id = (long)de, .kind = kind, .what = what};
    projcurve_face *face = NULL;
    projcurve_context scratch = {.magic = PC_CONTEXT_MAGIC};
    const projcurve_status st = pc_face_build(&scratch, surface, p->loops, p->n_loops, &fp, &face);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(t->f->ctx, st, "%s", scratch.last_message);
    if (st != PROJCURVE_OK) {
        t->consumed[(de - 1) / 2] = 0;
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s", scratch.last_message);
    }
    return pc_model_add_face(t->f->ctx, t->model, face);
}

/* 144 (PTS, N1, N2, PTO, PTI(1..N2)). */
static projcurve_status read_144(const topo *t, size_t de)
{
    pc_iges_params params;
    long head[4] = {0, 0, 0, 0}; /* PTS, N1, N2, PTO */
    projcurve_status st = pc_iges_params_of(t->f, de, &params);
    if (st == PROJCURVE_OK)
        st = pc_iges_ints(&params, 1, 4, head);
    if (st != PROJCURVE_OK)
        return st;
    const long pts = head[0], n1 = head[1], n2 = head[2], pto = head[3];
    mark(t, (long)de);
    char reason[PC_IGES_REASON] = "";
    const projcurve_surface *surface = NULL;
    const char *kind = "other";
    int analytic = 0;
    if ((st = face_surface(t, pts, de, 1, &surface, &kind, &analytic, reason)) != PROJCURVE_OK)
        return st;
    face_map map = {.surface = surface};
    if (analytic)
        face_tolerances(t, surface, &map.tol_model, &map.tol_uv);
    const face_map *via = analytic ? &map : NULL;
    if (n2 < 0 || (size_t)n2 + 5 > params.count)
        snprintf(reason, PC_IGES_REASON, "%ld inner boundaries, but %zu parameters", n2,
                 params.count - 1);
    pieces p = {0};
    if (!reason[0] && n1 != 0 && pto != 0)
        st = loop_of_142(t, pto, de, 1, via, &p, reason);
    for (long k = 0; st == PROJCURVE_OK && !reason[0] && k < n2; ++k) {
        long pti = 0;
        st = pc_iges_int(&params, 5 + (size_t)k, &pti);
        if (st == PROJCURVE_OK)
            st = loop_of_142(t, pti, de, 0, via, &p, reason);
    }
    if (st == PROJCURVE_ERR_PARSE) { /* a reference to nothing: this face only */
        snprintf(reason, PC_IGES_REASON, "%s", projcurve_context_message(t->f->ctx));
        st = PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK)
        return st;
    return finish_face(t, surface, kind, &p, de, 144, reason);
}

/* The curves of one 141 boundary curve (CRVPT, SENSE, K, PSCPT(1..K)):
 * the PSCPTs, or with a map (an analytic surface, whose parameters are
 * not its NURBS's) CRVPT inverted onto the map's surface. */
static projcurve_status curve_of_141(const topo *t, const pc_iges_params *bp, size_t at,
                                     long bd, long c, const face_map *via, pieces *p,
                                     char reason[PC_IGES_REASON])
{
    long fields[3] = {0, 1, 0}; /* CRVPT, SENSE, K */
    projcurve_status st = pc_iges_ints(bp, at, 3, fields);
    if (st != PROJCURVE_OK)
        return st;
    const long crvpt = fields[0], k = fields[2];
    const int sense = fields[1] == 2 ? -1 : 1;
    if (via != NULL) {
        for (long j = 0; j < k; ++j) {
            long pscpt = 0;
            if (pc_iges_int(bp, at + 3 + (size_t)j, &pscpt) == PROJCURVE_OK)
                mark_curve(t, pscpt, (size_t)bd);
        }
        if (crvpt == 0) {
            snprintf(reason, PC_IGES_REASON,
                     "boundary DE %ld curve %ld on an analytic surface has no model-space "
                     "curve (CRVPT 0) to map onto the surface's NURBS",
                     bd, c);
            return PROJCURVE_OK;
        }
        mark_curve(t, crvpt, (size_t)bd);
        return curve_pieces(t, crvpt, (size_t)bd, sense, via, p, reason);
    }
    mark(t, crvpt);
    if (k < 1) {
        snprintf(reason, PC_IGES_REASON,
                 "boundary DE %ld curve %ld has no parameter-space curve", bd, c);
        return PROJCURVE_OK;
    }
    for (long j = 0; st == PROJCURVE_OK && !reason[0] && j < k; ++j) {
        long pscpt = 0;
        if ((st = pc_iges_int(bp, at + 3 + (size_t)j, &pscpt)) == PROJCURVE_OK)
            st = curve_pieces(t, pscpt, (size_t)bd, sense, NULL, p, reason);
    }
    return st;
}

/* One 141 boundary (TYPE, PREF, SPTR, N, then per curve CRVPT, SENSE, K,
 * PSCPT(1..K)) as a loop of the face of 143 de. */
static projcurve_status loop_of_141(const topo *t, long bd, size_t de, int outer,
                                    const face_map *via, pieces *p, char reason[PC_IGES_REASON])
{
    const pc_iges_entry *e = pc_iges_entry_at(t->f, bd, de);
    if (e == NULL || e->type != 141) {
        snprintf(reason, PC_IGES_REASON, "its boundary DE %ld is not a 141 boundary", bd);
        return PROJCURVE_OK;
    }
    mark(t, bd);
    pc_iges_params bp;
    long n_curves = 0;
    projcurve_status st = pc_iges_params_of(t->f, (size_t)bd, &bp);
    if (st == PROJCURVE_OK)
        st = pc_iges_int(&bp, 4, &n_curves);
    const size_t first = p->count;
    size_t at = 5;
    for (long c = 0; st == PROJCURVE_OK && !reason[0] && c < n_curves; ++c) {
        long k = 0;
        if ((st = pc_iges_int(&bp, at + 2, &k)) == PROJCURVE_OK)
            st = curve_of_141(t, &bp, at, bd, c, via, p, reason);
        at += 3 + (size_t)(k > 0 ? k : 0);
    }
    if (st == PROJCURVE_OK && !reason[0] && !push_loop(t, p, first, outer))
        st = pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    return st;
}

/* 143 (TYPE, SPTR, N, BDPT(1..N)) with 141 boundaries; the first boundary
 * is the outer one. */
static projcurve_status read_143(const topo *t, size_t de)
{
    pc_iges_params params;
    long head[2] = {0, 0}; /* SPTR, N */
    projcurve_status st = pc_iges_params_of(t->f, de, &params);
    if (st == PROJCURVE_OK)
        st = pc_iges_ints(&params, 2, 2, head);
    if (st != PROJCURVE_OK)
        return st;
    const long sptr = head[0], n = head[1];
    mark(t, (long)de);
    char reason[PC_IGES_REASON] = "";
    const projcurve_surface *surface = NULL;
    const char *kind = "other";
    int analytic = 0;
    if ((st = face_surface(t, sptr, de, 1, &surface, &kind, &analytic, reason)) != PROJCURVE_OK)
        return st;
    face_map map = {.surface = surface};
    if (analytic)
        face_tolerances(t, surface, &map.tol_model, &map.tol_uv);
    pieces p = {0};
    for (long b = 0; st == PROJCURVE_OK && !reason[0] && b < n; ++b) {
        long bd = 0;
        if ((st = pc_iges_int(&params, 4 + (size_t)b, &bd)) == PROJCURVE_OK)
            st = loop_of_141(t, bd, de, b == 0, analytic ? &map : NULL, &p, reason);
    }
    if (st == PROJCURVE_ERR_PARSE) {
        snprintf(reason, PC_IGES_REASON, "%s", projcurve_context_message(t->f->ctx));
        st = PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK)
        return st;
    return finish_face(t, surface, kind, &p, de, 143, reason);
}

/* Independent surfaces that bound no 144 / 143 are faces on their whole
 * domain (a physically dependent one is part of something else). */
static projcurve_status natural_faces(const topo *t, const unsigned char *is_base)
{
    for (size_t i = 0; i < t->f->n_entries; ++i) {
        /* an analytic entity alone is not a face: a plane 108's extent is
         * only its display symbol's, as CAD readers take it */
        if (is_base[i] || t->f->surface_of[i] < 0 || t->f->entries[i].subordinate == 1 ||
            t->f->entries[i].type != 128)
            continue;
        pieces p = {0};
        const projcurve_surface *surface = t->model->surfaces[t->f->surface_of[i]];
        projcurve_status st = finish_face(t, surface, surface_kind_name(t->f->entries[i].type),
                                          &p, 2 * i + 1, t->f->entries[i].type, "");
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

static projcurve_status face_set(const topo *t)
{
    projcurve_model *m = t->model;
    if (m->n_faces == 0)
        return PROJCURVE_OK;
    size_t *index = malloc(m->n_faces * sizeof *index);
    if (index == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    for (size_t i = 0; i < m->n_faces; ++i)
        index[i] = i;
    /* edges shared by geometry, within the file's resolution (else the
     * default fraction of the faces' own precision) */
    double tol = t->resolution;
    for (size_t i = 0; tol <= 0.0 && i < m->n_faces; ++i)
        tol = m->faces[i]->tol_model;
    size_t shared = 0;
    double used_tol = tol;
    projcurve_status st = pc_sew_faces(t->f->ctx, m->faces, m->n_faces, tol, &shared, &used_tol);
    projcurve_shape *shape = NULL;
    if (st == PROJCURVE_OK)
        st = pc_shape_build(t->f->ctx, PROJCURVE_SHAPE_FACE_SET, -1,
                            (const projcurve_face *const *)m->faces, index, m->n_faces, &shape);
    free(index);
    if (st != PROJCURVE_OK)
        return st;
    shape->sew_tol = used_tol;
    return pc_model_add_shape(t->f->ctx, m, shape);
}

projcurve_status pc_iges_read_topology(pc_iges_file *f, projcurve_model *model,
                                       unsigned char *consumed)
{
    topo t = {.f = f, .model = model, .consumed = consumed, .resolution = global_resolution(f)};
    unsigned char *is_base = pc_arena_calloc(f->arena, f->n_entries + 1, 1);
    if (is_base == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    projcurve_status st = PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_entries; ++i) {
        const int type = f->entries[i].type;
        if (type != 144 && type != 143)
            continue;
        pc_iges_params params;
        long base = 0;
        if (pc_iges_params_of(f, 2 * i + 1, &params) == PROJCURVE_OK &&
            pc_iges_int(&params, type == 144 ? 1 : 2, &base) == PROJCURVE_OK && base > 0 &&
            base % 2 == 1 && (size_t)(base - 1) / 2 < f->n_entries)
            is_base[(base - 1) / 2] = 1;
        st = type == 144 ? read_144(&t, 2 * i + 1) : read_143(&t, 2 * i + 1);
    }
    if (st == PROJCURVE_OK)
        st = natural_faces(&t, is_base);
    if (st == PROJCURVE_OK)
        st = face_set(&t);
    return st;
}
