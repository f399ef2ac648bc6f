/* SPDX-License-Identifier: BSD-3-Clause */
#include "intersect/ray_patch.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "common/error.h"
#include "intersect/bezier_clip.h"
#include "intersect/frame_net.h"

/* |d . n| below this (n the unit normal) makes a hit a grazing one: there
 * the Jacobian of (d1, d2) is ~this small relative to |Su x Sv| and the
 * hit is a fold of the projection ([SY13] s3.4). */
#define PC_HIT_TANGENT_COS 1e-6
/* Subdivision stops at this depth; depth d boxes are about 2^(-d/2) wide. */
#define PC_CLIP_MAX_DEPTH 56
/* A stalled box narrower than this (local parameters) on both sides holds a
 * root where clipping converges only linearly (a tangent, double root) or a
 * curve of roots: it is finished by least squares instead of subdivided. */
#define PC_CLIP_STALL_WIDTH 1e-7
/* Bound on clipping rounds per patch (each round is one clip in s and t);
 * it is reached only when the line lies in the surface along a curve. */
#define PC_CLIP_MAX_ROUNDS 4096
/* A root may lie this far outside its patch (local parameters) before it is
 * rejected: the neighbouring patch then reports it. Accepted roots are
 * clamped into the patch. */
#define PC_PARAM_SLACK 1e-9
/* Where a pole lies on the line, the band of this width (local
 * parameters) along the collapsed edge is left out of the clipping: every
 * box touching the edge holds a root (the pole) and could not be
 * discarded. Points of the band are within ~1e-4 of the patch's size of
 * the pole; the line meets them only if it is the pole's hit itself. */
#define PC_POLE_BAND 1e-4
/* The normal at a pole is taken this far inside the patch. */
#define PC_POLE_NORMAL_OFFSET 1e-6

/* A hit's (u, v) are rounded to doubles. In an ordinary span that moves the
 * local (s, t) by ~1e-16 / (span width), nothing; in a span much narrower
 * than its parameters' magnitude (knot clusters: spans of 1e-8 at v ~ 4)
 * one ulp of v is a sizeable step of t, and S at the reported parameters
 * may lie off the line by |S_t| times that step, beyond the hit tolerance:
 * no double (u, v) does better. Where the rounding moves (s, t) by more
 * than this, the residual recorded is re-evaluated at the reported
 * parameters (the local root itself stays the accepted one). */
#define PC_LOCAL_ROUNDING 1e-13

/* After a failed Newton try on a box, the next waits until the box has
 * shrunk by this factor: a try costs about as much as a clipping round. */
#define PC_NEWTON_RETRY_FACTOR 0.01

static size_t net_points(int deg_u, int deg_v)
{
    return (size_t)(deg_u + 1) * (size_t)(deg_v + 1);
}

size_t pc_ray_patch_work_size(int deg_u, int deg_v)
{
    if (deg_u < 1 || deg_v < 1 || deg_u > PROJCURVE_MAX_DEGREE || deg_v > PROJCURVE_MAX_DEGREE)
        return 0;
    /* The frame net (4 values per point) and one planar net (2 values per
     * point) for each level of the subdivision stack. */
    return net_points(deg_u, deg_v) * (4 + 2 * (PC_CLIP_MAX_DEPTH + 1));
}

typedef struct patch_search {
    const pc_ray_frame *frame;
    const pc_bezier_patch *patch;
    pc_frame_net net;
    pc_hit_list *hits;
    projcurve_context *ctx;
    double zero_tol; /* rounding level of the homogeneous control values */
    double lipschitz; /* of the Jacobian over the patch */
    double jac_max;   /* bound on |J|_F over the patch */
    double sliver_width; /* a stalled box this thin across is one grazing contact */
} patch_search;

/* Records a root found in patch-local parameters if it is a hit. */
static projcurve_status record_root_flagged(const patch_search *ps, const pc_frame_root *r,
                                            int forced_tangent, unsigned extra_flags)
{
    const pc_ray_frame *f = ps->frame;
    if (!(r->residual <= f->tol_residual))
        return PROJCURVE_OK;
    if (!(r->s >= -PC_PARAM_SLACK && r->s <= 1.0 + PC_PARAM_SLACK && r->t >= -PC_PARAM_SLACK &&
          r->t <= 1.0 + PC_PARAM_SLACK))
        return PROJCURVE_OK;
    pc_hit hit;
    hit.lambda = r->z * f->inv_dir_norm;
    if (f->ray_only && !(hit.lambda > 0.0))
        return PROJCURVE_OK;
    const pc_bezier_patch *p = ps->patch;
    const double s = fmin(fmax(r->s, 0.0), 1.0), t = fmin(fmax(r->t, 0.0), 1.0);
    hit.u = s >= 1.0 ? p->u1 : p->u0 + s * (p->u1 - p->u0);
    hit.v = t >= 1.0 ? p->v1 : p->v0 + t * (p->v1 - p->v0);
    hit.residual = r->residual;
    const double s_rep = (hit.u - p->u0) / (p->u1 - p->u0), t_rep = (hit.v - p->v0) / (p->v1 - p->v0);
    if (fabs(s_rep - s) > PC_LOCAL_ROUNDING || fabs(t_rep - t) > PC_LOCAL_ROUNDING) {
        pc_frame_root at;
        pc_frame_net_point(&ps->net, s_rep, t_rep, &at);
        hit.residual = fmax(hit.residual, at.residual);
    }
    hit.flags = (forced_tangent || r->cos_dir < PC_HIT_TANGENT_COS) ? PROJCURVE_HIT_TANGENT : 0u;
    hit.flags |= extra_flags;
    return pc_hit_list_push(ps->ctx, ps->hits, hit);
}

static projcurve_status record_root(const patch_search *ps, const pc_frame_root *r, int forced_tangent)
{
    return record_root_flagged(ps, r, forced_tangent, forced_tangent ? PC_HIT_STALLED : 0u);
}

/* The least-squares point of a box that could not be resolved is a tangent
 * hit, unless the line is clearly transversal there: a minimum of the
 * distance that is not a root has J^T (X, Y) = 0 with (X, Y) != 0, so J is
 * singular along (X, Y) and |d . n| ~ 0; and near a double root |d . n| is
 * ~sqrt(tolerance) (1e-6 .. 1e-5). With |d . n| above this bound, far from
 * both, a point on the line to the hit tolerance is a simple root that the
 * box could not certify (Newton's steps in a patch of a span 1e-8 wide stall
 * on rounding noise), and it is reported as one. */
#define PC_LSQ_TRANSVERSAL_COS 1e-3

static projcurve_status record_least_squares(const patch_search *ps, const pc_frame_root *r)
{
    return record_root(ps, r, !(r->cos_dir >= PC_LSQ_TRANSVERSAL_COS));
}

/* A box that clipping shrank below PC_CLIP_WIDTH_TOL: Newton from its
 * centre, which must stay near the box; least squares if Newton fails. */
static projcurve_status finish_converged(const patch_search *ps, const double box[4])
{
    const double cs = 0.5 * (box[0] + box[1]), ct = 0.5 * (box[2] + box[3]);
    const double ws = box[1] - box[0] + PC_PARAM_SLACK, wt = box[3] - box[2] + PC_PARAM_SLACK;
    pc_frame_root r;
    if (pc_frame_net_newton(&ps->net, cs, ct, &r) && fabs(r.s - cs) <= ws &&
        fabs(r.t - ct) <= wt)
        return record_root(ps, &r, 0);
    if (!pc_frame_net_minimize(&ps->net, box, &r))
        return PROJCURVE_OK;
    return record_least_squares(ps, &r);
}

/* Newton from the centre of a box, accepted when its root lies in the box
 * and is provably the only one there: with beta = |J(r)^-1| and L the
 * Jacobian's Lipschitz bound, (X, Y)(x) = (J(r) + E)(x - r) with
 * |E| <= L |x - r| / 2, nonsingular while |x - r| < 2 / (beta L); the box
 * must lie within half that radius (Kantorovich-style uniqueness).
 * Returns 1 when the box is finished (its root recorded). */
static int try_certified_newton(const patch_search *ps, const double box[4], projcurve_status *st)
{
    pc_frame_root r;
    if (!pc_frame_net_newton(&ps->net, 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), &r))
        return 0;
    if (!(r.s >= box[0] - PC_PARAM_SLACK && r.s <= box[1] + PC_PARAM_SLACK &&
          r.t >= box[2] - PC_PARAM_SLACK && r.t <= box[3] + PC_PARAM_SLACK))
        return 0;
    const double *j = r.jac;
    const double det = j[0] * j[3] - j[1] * j[2];
    const double norm = sqrt(j[0] * j[0] + j[1] * j[1] + j[2] * j[2] + j[3] * j[3]);
    const double ds = fmax(r.s - box[0], box[1] - r.s), dt = fmax(r.t - box[2], box[3] - r.t);
    const double reach = sqrt(ds * ds + dt * dt);
    /* beta <= |J|_F / |det J|. */
    if (!(reach * norm * ps->lipschitz <= fabs(det)))
        return 0;
    *st = record_root(ps, &r, 0);
    return 1;
}

/* Whether a certified Newton try on a box of this width can succeed at
 * all: it needs reach L <= |det J| / |J|_F <= |J|_F / 2 <= jac_max / 2,
 * with reach up to the box's diagonal. */
static int newton_may_certify(const patch_search *ps, double width)
{
    return 2.0 * 1.4142135623730951 * width * ps->lipschitz <= ps->jac_max;
}

/* A box where clipping stalls at the resolution limit: the least-squares
 * minimum of the distance to the line, a tangent hit if it touches. */
static projcurve_status finish_stalled(const patch_search *ps, const double box[4])
{
    pc_frame_root r;
    if (!pc_frame_net_minimize(&ps->net, box, &r))
        return PROJCURVE_OK;
    return record_least_squares(ps, &r);
}

/* The side to halve: the wider one among those not converged. */
static int split_direction(const double box[4])
{
    return (box[3] - box[2]) > (box[1] - box[0]) ? 1 : 0;
}

/* The hit at a pole on side `side` (as pc_frame_net_poles_on_line) of the
 * patch: reported at the middle of the collapsed edge, flagged PC_HIT_POLE,
 * grazing or not by the normal just inside the patch. */
static projcurve_status record_pole(const patch_search *ps, int side)
{
    static const double mid[4][2] = {{0.5, 0.0}, {0.5, 1.0}, {0.0, 0.5}, {1.0, 0.5}};
    static const double inward[4][2] = {{0.0, 1.0}, {0.0, -1.0}, {1.0, 0.0}, {-1.0, 0.0}};
    pc_frame_root r, inside;
    pc_frame_net_point(&ps->net, mid[side][0], mid[side][1], &r);
    pc_frame_net_point(&ps->net, mid[side][0] + PC_POLE_NORMAL_OFFSET * inward[side][0],
                       mid[side][1] + PC_POLE_NORMAL_OFFSET * inward[side][1], &inside);
    r.cos_dir = inside.cos_dir;
    return record_root_flagged(ps, &r, 0, PC_HIT_POLE);
}

/* The part of the patch the clipping searches: all of it, less a band
 * along each collapsed edge whose pole lies on the line (recorded here). */
static projcurve_status start_box(const patch_search *ps, double box[4], unsigned *poles)
{
    box[0] = box[2] = 0.0;
    box[1] = box[3] = 1.0;
    *poles = pc_frame_net_poles_on_line(&ps->net, ps->frame->tol_residual);
    for (int side = 0; side < 4; ++side) {
        if (!(*poles & (1u << side)))
            continue;
        const projcurve_status st = record_pole(ps, side);
        if (st != PROJCURVE_OK)
            return st;
        /* side 0: t = 0 -> box[2]; 1: t = 1 -> box[3]; 2: s = 0 -> box[0]; 3: s = 1 -> box[1] */
        static const int bound[4] = {2, 3, 0, 1};
        box[bound[side]] += (side % 2 == 0) ? PC_POLE_BAND : -PC_POLE_BAND;
    }
    return PROJCURVE_OK;
}

/* The depth-first search's stack: planar nets in the caller's scratch,
 * boxes and bookkeeping here (entry k has depth >= k, so PC_CLIP_MAX_DEPTH
 * + 1 entries suffice). */
typedef struct clip_stack {
    double *slots;    /* (PC_CLIP_MAX_DEPTH + 1) planar nets */
    size_t slot_size; /* doubles per net */
    double box[PC_CLIP_MAX_DEPTH + 1][4];
    double next_try[PC_CLIP_MAX_DEPTH + 1]; /* width that allows a Newton try */
    int depth[PC_CLIP_MAX_DEPTH + 1];
    int top; /* -1 when empty */
} clip_stack;

static double *top_net(const clip_stack *st) { return st->slots + (size_t)st->top * st->slot_size; }

/* The first entry: the patch's (X, Y) net, less the pole bands. Returns
 * OK with st->top = -1 when nothing is left to search. */
static projcurve_status push_patch(const patch_search *ps, clip_stack *st)
{
    const size_t np = net_points(ps->net.deg_u, ps->net.deg_v);
    for (size_t k = 0; k < np; ++k) {
        st->slots[2 * k] = ps->net.q[4 * k];
        st->slots[2 * k + 1] = ps->net.q[4 * k + 1];
    }
    st->top = 0;
    st->depth[0] = 0;
    st->next_try[0] = 1.0;
    unsigned poles = 0;
    const projcurve_status status = start_box(ps, st->box[0], &poles);
    if (status != PROJCURVE_OK)
        return status;
    if (poles != 0) {
        const double *b = st->box[0];
        if (!(b[0] < b[1] && b[2] < b[3]) ||
            pc_frame_net_is_point(&ps->net, ps->frame->tol_residual)) {
            st->top = -1; /* the whole patch collapses to the pole */
            return PROJCURVE_OK;
        }
        pc_bezier_clip_restrict(st->slots, ps->net.deg_u, ps->net.deg_v, b);
        return PROJCURVE_OK;
    }
    /* A patch flat enough for Newton to be certified on the whole of it
     * (small patches of a fine surface) needs no clipping at all. */
    if (newton_may_certify(ps, 1.0)) {
        projcurve_status found = PROJCURVE_OK;
        if (try_certified_newton(ps, st->box[0], &found)) {
            st->top = -1;
            return found;
        }
        st->next_try[0] = PC_NEWTON_RETRY_FACTOR;
    }
    return PROJCURVE_OK;
}

/* After a round that shrank the top box: a certified Newton try when the
 * box is narrow enough and the last try was long enough ago. */
static projcurve_status after_progress(const patch_search *ps, clip_stack *st)
{
    const double *box = st->box[st->top];
    const double width = fmax(box[1] - box[0], box[3] - box[2]);
    if (!(width <= st->next_try[st->top] && newton_may_certify(ps, width)))
        return PROJCURVE_OK;
    projcurve_status found = PROJCURVE_OK;
    if (try_certified_newton(ps, box, &found))
        --st->top;
    else
        st->next_try[st->top] = width * PC_NEWTON_RETRY_FACTOR;
    return found;
}

/* After a round that did not shrink the top box enough: finish it (tiny,
 * a grazing sliver, or at the depth bound) or halve it, the upper half
 * going on top. */
static projcurve_status after_stall(const patch_search *ps, clip_stack *st)
{
    double *net = top_net(st), *box = st->box[st->top];
    const int m = ps->net.deg_u, n = ps->net.deg_v;
    const int tiny = box[1] - box[0] < PC_CLIP_STALL_WIDTH && box[3] - box[2] < PC_CLIP_STALL_WIDTH;
    if (tiny || st->depth[st->top] >= PC_CLIP_MAX_DEPTH ||
        pc_bezier_clip_is_sliver(net, m, n, ps->sliver_width)) {
        --st->top;
        return finish_stalled(ps, box);
    }
    const int k = st->top;
    pc_bezier_clip_split(net, net + st->slot_size, m, n, split_direction(box), box, st->box[k + 1]);
    st->depth[k + 1] = ++st->depth[k];
    st->next_try[k + 1] = st->next_try[k];
    ++st->top;
    return PROJCURVE_OK;
}

/* Depth-first Bezier clipping over a bounded stack of planar nets. */
static projcurve_status clip_patch(const patch_search *ps, double *slots)
{
    const int m = ps->net.deg_u, n = ps->net.deg_v;
    clip_stack st;
    st.slots = slots;
    st.slot_size = 2 * net_points(m, n);
    projcurve_status status = push_patch(ps, &st);
    for (int round = 0; status == PROJCURVE_OK && st.top >= 0 && round < PC_CLIP_MAX_ROUNDS;
         ++round) {
        double *box = st.box[st.top];
        switch (pc_bezier_clip_step(top_net(&st), m, n, ps->zero_tol, box)) {
        case PC_CLIP_EMPTY:
            --st.top;
            break;
        case PC_CLIP_PROGRESS:
            status = after_progress(ps, &st);
            break;
        case PC_CLIP_CONVERGED:
            --st.top;
            status = finish_converged(ps, box);
            break;
        case PC_CLIP_STALLED:
            status = after_stall(ps, &st);
            break;
        }
    }
    return status;
}

projcurve_status pc_ray_patch_hits(projcurve_context *ctx, const pc_ray_frame *frame,
                                   const pc_bezier_patch *patch, double *work,
                                   pc_hit_list *hits)
{
    patch_search ps;
    ps.frame = frame;
    ps.patch = patch;
    ps.net.deg_u = patch->deg_u;
    ps.net.deg_v = patch->deg_v;
    ps.net.q = work;
    ps.hits = hits;
    ps.ctx = ctx;
    double w_max = 0.0, w_min = 0.0;
    if (!pc_ray_frame_project(frame, patch, work, &w_max, &w_min))
        return PROJCURVE_OK;
    ps.zero_tol = frame->tol_zero * w_max;
    /* Points of the sliver are within the hit tolerance of the line (in the
     * homogeneous values, times the weight), so the whole box is one
     * grazing contact as far as hits can tell. */
    ps.sliver_width = frame->tol_residual * w_min;
    pc_frame_net_jacobian_bounds(&ps.net, &ps.lipschitz, &ps.jac_max);
    return clip_patch(&ps, work + 4 * net_points(patch->deg_u, patch->deg_v));
}
