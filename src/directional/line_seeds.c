/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Seeds of the directional projection: the hits of the ray P(t) + lambda Dir
 * with S ([SY13] s3.1 steps 1-3: candidate patches by their control
 * polygons' boxes, line/surface intersection, lambda > 0), each polished by
 * the tracing corrector so that it satisfies exactly the equations traced.
 */
#include "directional/line_seeds.h"

#include <stdlib.h>

#include "bezier/bvh.h"
#include "common/array.h"
#include "common/error.h"
#include "directional/control_polygon.h"

/* How far behind P(t), in corrector tolerances, the rays of the search
 * start. */
#define PC_SEED_BEHIND 4.0
/* Smallest capacity of the finder's arrays (candidate patches, polygon hits). */
#define PC_LINE_LIST_MIN_CAPACITY 16

static projcurve_status line_find(pc_seed_finder *self, projcurve_context *ctx, double t,
                                  pc_seed_list *out)
{
    pc_line_finder *f = self->state;
    const pc_projector *proj = f->proj;
    out->count = 0;
    pc_vec3 p;
    projcurve_status st = pc_curve_eval(proj->curve, t, 0, &f->curve_hint, &p);
    if (st != PROJCURVE_OK)
        return pc_fail(ctx, st, "curve evaluation failed at t = %.17g", t);
    /* lambda = 0 counts (a curve lying on S is its own projection): the
     * ray starts PC_SEED_BEHIND corrector tolerances behind P(t), so that
     * the rounding of a hit at lambda = 0 does not decide whether it is
     * found; the tracer judges what lies behind (pc_trace_behind) */
    const pc_vec3 origin = vec3_axpy(p, -PC_SEED_BEHIND * proj->newton_tol, f->dir);
    st = pc_intersect_line(ctx, proj->surface, origin, f->dir, 1, &f->hits);
    if (st != PROJCURVE_OK)
        return st;
    for (size_t k = 0; k < f->hits.count; ++k) {
        double uv[2] = {f->hits.items[k].u, f->hits.items[k].v};
        if (!proj->correct(proj, t, uv, NULL)) {
            uv[0] = f->hits.items[k].u; /* a grazing hit: keep it as found */
            uv[1] = f->hits.items[k].v;
        }
        st = pc_seed_list_push(ctx, out, t, uv[0], uv[1]);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

void pc_line_finder_init(pc_line_finder *f, const pc_projector *proj, pc_vec3 unit_dir)
{
    *f = (pc_line_finder){0};
    f->proj = proj;
    f->dir = unit_dir;
    f->base.find = line_find;
    f->base.may_jump = pc_line_may_jump;
    f->base.reset = pc_line_jump_reset;
    f->base.state = f;
}

void pc_line_finder_free(pc_line_finder *f)
{
    pc_hit_list_free(&f->hits);
    PC_ARRAY_FREE(&f->l1);
    PC_ARRAY_FREE(&f->l2);
    free(f->patches);
    pc_curve_pieces_free(&f->pieces);
    *f = (pc_line_finder){0};
}

/* BVH visitor: collects candidate patch indices. */
static int collect_patch(void *user, size_t patch_index)
{
    pc_line_finder *f = user;
    void *items = f->patches;
    const projcurve_status st =
        pc_array_reserve(NULL, &items, &f->cap_patches, f->n_patches, f->n_patches + 1,
                         sizeof *f->patches, PC_LINE_LIST_MIN_CAPACITY, NULL, "candidate patches");
    f->patches = items;
    if (st != PROJCURVE_OK) {
        f->patches_incomplete = 1;
        return 1; /* stop the walk */
    }
    f->patches[f->n_patches++] = patch_index;
    return 0;
}

static int push_polygon_hit(pc_polygon_hits *l, size_t patch, pc_vec3 x)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, NULL, l, l->count + 1, PC_LINE_LIST_MIN_CAPACITY,
                     "control-polygon hits");
    if (st != PROJCURVE_OK)
        return 0;
    l->items[l->count].patch = patch;
    l->items[l->count].x = x;
    l->count++;
    return 1;
}

/* Patch boxes are padded by this fraction of the model size so that a ray
 * grazing a box is not lost. */
#define PC_POLYGON_BOX_PAD 1e-9
/* Most control-polygon hits of one ray with one patch that are kept. */
#define PC_MAX_POLYGON_HITS 32

int pc_line_polygon_hits(pc_line_finder *f, pc_vec3 origin, pc_polygon_hits *out)
{
    const projcurve_surface *s = f->proj->surface;
    out->count = 0;
    f->n_patches = 0;
    f->patches_incomplete = 0;
    const double pad = PC_POLYGON_BOX_PAD * s->size;
    pc_bvh_query_line(&s->bvh, origin, f->dir, 0.0, INFINITY, pad, collect_patch, f);
    if (f->patches_incomplete) {
        f->no_memory = 1;
        return 0;
    }
    for (size_t k = 0; k < f->n_patches; ++k) {
        pc_vec3 x[PC_MAX_POLYGON_HITS];
        const size_t idx = f->patches[k];
        size_t n = pc_control_polygon_ray_hits(&s->grid.patches[idx], origin, f->dir, x,
                                               PC_MAX_POLYGON_HITS);
        if (n > PC_MAX_POLYGON_HITS)
            n = PC_MAX_POLYGON_HITS;
        for (size_t i = 0; i < n; ++i)
            if (!push_polygon_hit(out, idx, x[i])) {
                f->no_memory = 1;
                return 0;
            }
    }
    return 1;
}
