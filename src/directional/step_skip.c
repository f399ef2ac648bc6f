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
 *
 * A box swept along an oblique Dir is much wider than the thin piece of
 * curve it holds (a chord of a step): on a surface of many small patches
 * the box test alone flags the patches beside the branch at many checks.
 * So a second necessary condition is asked of the same boxes: the
 * separation along the chord's normal across the rays. Along Dir that is
 * n = Dir x (P(tb) - P(ta)), and n.x is constant on every ray; from the
 * eye E, n = (P(ta) - E) x (P(tb) - E) and the value n.(x - E) / m.(x - E)
 * (m: the direction to the chord's middle), constant on every ray from E,
 * projective, so the hull of the cut control points (all of positive
 * depth m.(c - E)) bounds the curve's values and the box's 8 corners (all
 * of positive depth) bound the box's. Disjoint ranges: no ray of the piece
 * meets the box. Where the chord has no normal (a point, or along the
 * ray) or a depth is not positive, only the box test holds.
 */
#include "directional/line_seeds.h"

#include <math.h>

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
    /* The chord's axis: valid when has_axis; the piece's range of values
     * (padded) in piece_range. */
    int has_axis;
    pc_vec3 n, m, d;          /* d: the chord's direction across the rays */
    double piece_range[2];
} skip_walk;

/* The value of x on the axis: n.x along Dir, n.(x - E) / m.(x - E) from
 * the eye (*depth_ok cleared where m.(x - E) is not positive). */
static double axis_value(const skip_walk *w, pc_vec3 x, int *depth_ok)
{
    if (w->eye == NULL)
        return vec3_dot(w->n, x);
    const pc_vec3 r = vec3_sub(x, *w->eye);
    const double depth = vec3_dot(w->m, r);
    if (!(depth > 0.0)) {
        *depth_ok = 0;
        return 0.0;
    }
    return vec3_dot(w->n, r) / depth;
}

typedef struct axis_user {
    const skip_walk *w;
    int *depth_ok;
} axis_user;

static double piece_value(const void *user, pc_vec3 c)
{
    const axis_user *a = user;
    return axis_value(a->w, c, a->depth_ok);
}

/* The value of corner k of box b on the chord's direction d, as
 * axis_value on n (d.x along Dir, d.(x - E) / m.(x - E) from the eye). */
static double along_value(const skip_walk *w, pc_vec3 x)
{
    if (w->eye == NULL)
        return vec3_dot(w->d, x);
    const pc_vec3 r = vec3_sub(x, *w->eye);
    return vec3_dot(w->d, r) / vec3_dot(w->m, r);
}

/* 0 when box b and the piece are separated on the axis, or touch there
 * (within the pad) at a single point of the box's image, a corner: a
 * curve through the corner where a sphere's four patch boxes meet at its
 * pole would else be approached by halvings down to the floor, for hits
 * on a vanishing stretch (the sweep's own bound already leaves out
 * branches shorter than about 2 ds). A touch along a side (the image's
 * corners there spread along the chord: a curve along the edge two
 * patches share) counts as meeting. */
static int axis_meets(const skip_walk *w, const double b[6])
{
    if (!w->has_axis)
        return 1;
    double v[8], lo = INFINITY, hi = -INFINITY, min_depth = INFINITY;
    pc_vec3 x[8];
    int depth_ok = 1;
    for (int k = 0; k < 8; ++k) {
        x[k] = vec3(k & 1 ? b[3] : b[0], k & 2 ? b[4] : b[1], k & 4 ? b[5] : b[2]);
        v[k] = axis_value(w, x[k], &depth_ok);
        lo = fmin(lo, v[k]);
        hi = fmax(hi, v[k]);
        if (w->eye != NULL)
            min_depth = fmin(min_depth, vec3_dot(w->m, vec3_sub(x[k], *w->eye)));
    }
    if (!depth_ok)
        return 1;
    /* the pad in the axis' units: model units along Dir, over the
     * nearest depth from the eye */
    const double pad = w->eye == NULL ? w->pad : w->pad / min_depth;
    const double r0 = w->piece_range[0], r1 = w->piece_range[1];
    if (lo > r1 + pad || hi < r0 - pad)
        return 0; /* separated */
    const int at_lo = r1 <= lo + pad, at_hi = r0 >= hi - pad;
    if (at_lo == at_hi)
        return 1; /* across the box's range (or the box thinner than the pad) */
    /* a touch at one end: the corners there, spread along the chord? */
    const double end = at_lo ? lo : hi;
    double e_lo = INFINITY, e_hi = -INFINITY;
    for (int k = 0; k < 8; ++k)
        if (fabs(v[k] - end) <= pad) {
            const double e = along_value(w, x[k]);
            e_lo = fmin(e_lo, e);
            e_hi = fmax(e_hi, e);
        }
    return e_hi - e_lo > pad;
}

/* Sets the chord's axis of w from the piece's ends, and the piece's range
 * on it; has_axis 0 where there is none. */
static void chord_axis(skip_walk *w, const pc_line_finder *f, double ta, double tb,
                       const pc_vec3 ends[2])
{
    w->has_axis = 0;
    pc_vec3 n;
    if (w->eye == NULL) {
        n = vec3_cross(w->dir, vec3_sub(ends[1], ends[0]));
    } else {
        const pc_vec3 a = vec3_sub(ends[0], *w->eye), b = vec3_sub(ends[1], *w->eye);
        const double la = vec3_norm(a), lb = vec3_norm(b);
        if (!(la > 0.0) || !(lb > 0.0))
            return;
        n = vec3_cross(a, b);
        w->m = vec3_add(vec3_scale(a, 1.0 / la), vec3_scale(b, 1.0 / lb));
        const double lm = vec3_norm(w->m);
        if (!(lm > 0.0))
            return;
        w->m = vec3_scale(w->m, 1.0 / lm);
    }
    const double ln = vec3_norm(n);
    if (!(ln > 0.0) || !isfinite(ln))
        return;
    w->n = vec3_scale(n, 1.0 / ln);
    /* along Dir: Dir x n, unit; from the eye: m x n (m is the depth
     * direction, the along-chord value is d.(x - E) / m.(x - E)) */
    w->d = vec3_cross(w->eye == NULL ? w->dir : w->m, w->n);
    int depth_ok = 1;
    const axis_user user = {w, &depth_ok};
    if (pc_curve_pieces_range(&f->pieces, ta, tb, piece_value, &user, w->piece_range) &&
        depth_ok)
        w->has_axis = 1;
}

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
    const double *box = w->s->bvh.nodes[node].box;
    return reaches(w, w->piece, box) && axis_meets(w, box);
}

static int visit_patch(void *user, size_t patch)
{
    skip_walk *w = user;
    const pc_bezier_patch *bp = &w->s->grid.patches[patch];
    if (!reaches(w, w->piece, bp->box) || reaches(w, w->ends[0], bp->box) ||
        reaches(w, w->ends[1], bp->box) || !axis_meets(w, bp->box))
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
    chord_axis(&w, f, ta, tb, ends);
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
