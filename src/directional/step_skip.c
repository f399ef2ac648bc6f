/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Whether a step of the jump sweep may jump over a patch, for the ray
 * projections (directional, conical): the finder's step_may_skip
 * (trace/trace.h, the rule in docs/tracing.md).
 *
 * The curve over [ta, tb] lies in the convex hull of its cut control
 * points (geom/curve_pieces.h), so every ray of that stretch lies in that
 * box swept along Dir (or coned from the eye) (geom/box_reach.h): a patch
 * whose control-net box (which holds the patch) that sweep misses has no
 * hit over [ta, tb]. One whose box it meets may; unless the ray at ta or
 * at tb meets its box too (then a check's ray is at the patch: the
 * sweep's criteria and searches see it as they see any patch), or a
 * traced branch crosses it over [ta, tb] (its hits are on that branch),
 * the step may jump over it. The test is conservative (boxes), exact for
 * the boxes; it costs one BVH walk pruned by the same sweep.
 */
#include "directional/line_seeds.h"

#include "bezier/bvh.h"
#include "geom/box_reach.h"

/* Patch boxes are padded by this fraction of the model size (as the
 * polygon hits' boxes, line_seeds.c), so that a ray grazing a box is
 * counted as meeting it. */
#define PC_SKIP_BOX_PAD 1e-9

typedef struct skip_walk {
    const projcurve_surface *s;
    const pc_vec3 *eye;       /* NULL: along dir */
    pc_vec3 dir;
    double pad;
    double piece[6];          /* the curve's box over [ta, tb] */
    double ends[2][6];        /* the points at ta and tb, as boxes */
    const pc_sweep_trail *trail;
    int skip;
} skip_walk;

/* 1 when the rays from box `from` meet box b padded. */
static int reaches(const skip_walk *w, const double from[6], const double b[6])
{
    double padded[6];
    for (int i = 0; i < 3; ++i) {
        padded[i] = b[i] - w->pad;
        padded[i + 3] = b[i + 3] + w->pad;
    }
    return w->eye != NULL ? pc_cone_box_meets(from, *w->eye, padded)
                          : pc_swept_box_meets(from, w->dir, padded);
}

static int enter_node(void *user, size_t node)
{
    const skip_walk *w = user;
    return reaches(w, w->piece, w->s->bvh.nodes[node].box);
}

static int visit_patch(void *user, size_t patch)
{
    skip_walk *w = user;
    const pc_bezier_patch *bp = &w->s->grid.patches[patch];
    if (!reaches(w, w->piece, bp->box) || reaches(w, w->ends[0], bp->box) ||
        reaches(w, w->ends[1], bp->box))
        return 0;
    const double uv[4] = {bp->u0, bp->u1, bp->v0, bp->v1};
    if (w->trail != NULL && w->trail->crosses(w->trail, uv))
        return 0;
    w->skip = 1;
    return 1; /* one is enough: stop the walk */
}

static void point_box(pc_vec3 p, double box[6])
{
    box[0] = box[3] = p.x;
    box[1] = box[4] = p.y;
    box[2] = box[5] = p.z;
}

int pc_rays_step_may_skip(const pc_line_finder *f, const pc_vec3 *eye, double ta, double tb,
                          const pc_sweep_trail *trail)
{
    skip_walk w = {0};
    pc_vec3 ends[2];
    if (!pc_curve_pieces_box(&f->pieces, ta, tb, w.piece, ends))
        return 0;
    w.s = f->proj->surface;
    w.eye = eye;
    w.dir = f->dir;
    w.pad = PC_SKIP_BOX_PAD * w.s->size;
    w.trail = trail;
    point_box(ends[0], w.ends[0]);
    point_box(ends[1], w.ends[1]);
    pc_bvh_query_nodes(&w.s->bvh, enter_node, visit_patch, &w);
    return w.skip;
}

static int line_step_may_skip(pc_seed_finder *self, double ta, double tb,
                              const pc_sweep_trail *trail)
{
    return pc_rays_step_may_skip(self->state, NULL, ta, tb, trail);
}

projcurve_status pc_line_finder_bound_curve(projcurve_context *ctx, pc_line_finder *f)
{
    const projcurve_status st = pc_curve_pieces_build(ctx, f->proj->curve, &f->pieces);
    if (st == PROJCURVE_OK && f->pieces.bz.n_segments > 0)
        f->base.step_may_skip = line_step_may_skip;
    return st;
}
