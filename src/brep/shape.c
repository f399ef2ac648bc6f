/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/shape.h"

#include <stdlib.h>
#include <string.h>

#include "common/error.h"

void pc_shape_free(projcurve_shape *shape)
{
    if (shape == NULL)
        return;
    free(shape->faces);
    free(shape->face_index);
    free(shape->boxes);
    free(shape->edges);
    free(shape->uses);
    pc_face_bvh_free(&shape->bvh);
    free(shape);
}

typedef struct keyed_use {
    long edge;
    pc_edge_use use;
} keyed_use;

static int by_edge(const void *a, const void *b)
{
    const keyed_use *x = a, *y = b;
    if (x->edge != y->edge)
        return x->edge < y->edge ? -1 : 1;
    if (x->use.face != y->use.face)
        return x->use.face < y->use.face ? -1 : 1;
    if (x->use.loop != y->use.loop)
        return x->use.loop < y->use.loop ? -1 : 1;
    return x->use.piece < y->use.piece ? -1 : (x->use.piece > y->use.piece);
}

static projcurve_status group_edges(projcurve_context *ctx, projcurve_shape *s)
{
    size_t n = 0;
    for (size_t f = 0; f < s->n_faces; ++f)
        for (size_t l = 0; l < s->faces[f]->n_loops; ++l)
            for (size_t k = 0; k < s->faces[f]->loops[l].n_pieces; ++k)
                n += s->faces[f]->loops[l].pieces[k].edge >= 0;
    keyed_use *all = malloc((n + 1) * sizeof *all);
    s->uses = malloc((n + 1) * sizeof *s->uses);
    s->edges = malloc((n + 1) * sizeof *s->edges);
    if (all == NULL || s->uses == NULL || s->edges == NULL) {
        free(all);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a shape");
    }
    size_t m = 0;
    for (size_t f = 0; f < s->n_faces; ++f)
        for (size_t l = 0; l < s->faces[f]->n_loops; ++l)
            for (size_t k = 0; k < s->faces[f]->loops[l].n_pieces; ++k) {
                const pc_face_piece *p = &s->faces[f]->loops[l].pieces[k];
                if (p->edge < 0)
                    continue;
                all[m].edge = p->edge;
                all[m].use = (pc_edge_use){.face = f, .loop = l, .piece = k,
                                           .sense = p->sense * p->edge_sense};
                ++m;
            }
    qsort(all, m, sizeof *all, by_edge);
    for (size_t i = 0; i < m; ++i) {
        s->uses[i] = all[i].use;
        if (i == 0 || all[i].edge != all[i - 1].edge)
            s->edges[s->n_edges++] = (pc_shape_edge){.id = all[i].edge, .first_use = i};
        ++s->edges[s->n_edges - 1].n_uses;
    }
    s->n_uses = m;
    free(all);
    return PROJCURVE_OK;
}

projcurve_status pc_shape_build(projcurve_context *ctx, projcurve_shape_kind kind, long id,
                                const projcurve_face *const *faces, const size_t *index, size_t n,
                                projcurve_shape **out)
{
    projcurve_shape *s = calloc(1, sizeof *s);
    if (s == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a shape");
    s->kind = kind;
    s->id = id;
    s->faces = malloc((n + 1) * sizeof *s->faces);
    s->face_index = malloc((n + 1) * sizeof *s->face_index);
    s->boxes = malloc((6 * n + 1) * sizeof *s->boxes);
    projcurve_status st = PROJCURVE_OK;
    if (s->faces == NULL || s->face_index == NULL || s->boxes == NULL)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a shape");
    for (size_t i = 0; st == PROJCURVE_OK && i < n; ++i) {
        s->faces[i] = faces[i];
        s->face_index[i] = index[i];
        memcpy(s->boxes + 6 * i, faces[i]->box, 6 * sizeof *s->boxes);
    }
    if (st == PROJCURVE_OK) {
        s->n_faces = n;
        st = group_edges(ctx, s);
    }
    if (st == PROJCURVE_OK)
        st = pc_face_bvh_build(ctx, &s->bvh, s->boxes, n);
    if (st != PROJCURVE_OK) {
        pc_shape_free(s);
        return st;
    }
    *out = s;
    return PROJCURVE_OK;
}
