/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Line / surface intersection: the BVH picks the patches whose control-net
 * boxes meet the line, each is clipped in the line's frame (ray_patch.c),
 * and the hits are sorted, merged and flagged (hit_list.c).
 */
#include "intersect/intersect.h"

#include <math.h>

#include "common/error.h"
#include "intersect/ray_patch.h"

/* The BVH's box test is widened by this fraction of the model size, so that
 * a line grazing a patch whose box is tight is not lost to rounding. */
#define PC_BVH_PAD_REL 1e-9

typedef struct line_query {
    projcurve_context *ctx;
    const projcurve_surface *surface;
    const pc_ray_frame *frame;
    pc_hit_list *hits;
    projcurve_status status;
} line_query;

/* The magnitude of the coordinates involved: where the model is and how
 * far the origin is from it (rounding in the frame's distances grows with
 * both). */
static double query_magnitude(const projcurve_surface *s, pc_vec3 origin)
{
    const pc_vec3 center = vec3(0.5 * (s->box[0] + s->box[3]), 0.5 * (s->box[1] + s->box[4]),
                                0.5 * (s->box[2] + s->box[5]));
    return vec3_norm(center) + vec3_dist(origin, center);
}

static projcurve_status prepare(projcurve_context *ctx, const projcurve_surface *s,
                                pc_vec3 origin, pc_vec3 dir, int ray_only, pc_hit_list *hits,
                                pc_ray_frame *frame)
{
    hits->count = 0;
    const size_t work = pc_ray_patch_work_size(s->nurbs.deg_u, s->nurbs.deg_v);
    if (work == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "surface degrees (%d, %d) out of range",
                       s->nurbs.deg_u, s->nurbs.deg_v);
    const projcurve_status st = pc_hit_list_reserve_work(ctx, hits, work);
    if (st != PROJCURVE_OK)
        return st;
    pc_ray_frame_init(frame, origin, dir, s->size, query_magnitude(s, origin), ray_only);
    return PROJCURVE_OK;
}

/* Two grazing hits are one touching point when the surface comes as close
 * to the line between them as a hit: a double root is only known to
 * ~sqrt(tolerance) along the line, so copies found from neighbouring boxes
 * or patches, or from the two sides of a closed surface's seam, can lie well
 * apart, but the surface between them hugs the line. Two separate touching
 * points do not. "Between" is tried in parameters (the midpoint of the two
 * (u, v)) and in space (the foot on S, near either hit, of the line's point
 * halfway between them: across a seam the parameters' midpoint is on the
 * other side of the surface). */
#define PC_GRAZE_FOOT_ITER 8

typedef struct graze_context {
    const projcurve_surface *surface;
    const pc_ray_frame *frame;
} graze_context;

static double distance_to_line(const graze_context *g, pc_vec3 p)
{
    const pc_vec3 w = vec3_sub(p, g->frame->origin);
    return vec3_norm(vec3_axpy(w, -vec3_dot(w, g->frame->d), g->frame->d));
}

/* Distance from m to S near (u, v): Gauss-Newton on |S - m|^2, in the
 * domain. The start is a grazing hit ~sqrt(tolerance) from the foot. */
static double distance_near(const pc_nurbs_surface *s, pc_vec3 m, double u, double v)
{
    pc_vec3 f[3];
    for (int it = 0; it < PC_GRAZE_FOOT_ITER; ++it) {
        pc_nurbs_surface_eval(s, u, v, 1, NULL, NULL, f);
        const pc_vec3 r = vec3_sub(m, f[0]);
        const double a = vec3_dot(f[1], f[1]), b = vec3_dot(f[1], f[2]), c = vec3_dot(f[2], f[2]);
        const double rhs[2] = {vec3_dot(f[1], r), vec3_dot(f[2], r)};
        double step[2];
        if (!mat2_solve(a, b, b, c, rhs, step))
            break;
        u = fmin(fmax(u + step[0], s->domain[0]), s->domain[1]);
        v = fmin(fmax(v + step[1], s->domain[2]), s->domain[3]);
    }
    pc_nurbs_surface_eval(s, u, v, 0, NULL, NULL, f);
    return vec3_dist(m, f[0]);
}

static int same_graze(const void *user, const pc_hit *a, const pc_hit *b)
{
    const graze_context *g = user;
    const pc_nurbs_surface *s = &g->surface->nurbs;
    const double near = 2.0 * g->frame->tol_residual;
    pc_vec3 p;
    pc_nurbs_surface_eval(s, 0.5 * (a->u + b->u), 0.5 * (a->v + b->v), 0, NULL, NULL, &p);
    if (distance_to_line(g, p) <= near)
        return 1;
    const double lambda = 0.5 * (a->lambda + b->lambda) / g->frame->inv_dir_norm;
    const pc_vec3 m = vec3_axpy(g->frame->origin, lambda, g->frame->d);
    return distance_near(s, m, a->u, a->v) <= near || distance_near(s, m, b->u, b->v) <= near;
}

static void finish(const projcurve_surface *s, const pc_ray_frame *frame, pc_vec3 dir,
                   pc_hit_list *hits)
{
    const graze_context g = {s, frame};
    const pc_graze_test graze = {same_graze, &g};
    pc_hit_list_finish(hits, s->nurbs.domain, pc_vec3_length_robust(dir),
                       s->size + query_magnitude(s, frame->origin), frame->tol_residual, &graze);
}

static int visit_patch(void *user, size_t patch_index)
{
    line_query *q = user;
    q->status = pc_ray_patch_hits(q->ctx, q->frame, &q->surface->grid.patches[patch_index],
                                  q->hits->work, q->hits);
    return q->status != PROJCURVE_OK;
}

projcurve_status pc_intersect_line(projcurve_context *ctx, const projcurve_surface *s,
                                   pc_vec3 origin, pc_vec3 dir, int ray_only,
                                   pc_hit_list *hits)
{
    pc_ray_frame frame;
    projcurve_status st = prepare(ctx, s, origin, dir, ray_only, hits, &frame);
    if (st != PROJCURVE_OK)
        return st;
    line_query q = {ctx, s, &frame, hits, PROJCURVE_OK};
    pc_bvh_query_line(&s->bvh, origin, dir, ray_only ? 0.0 : -INFINITY, INFINITY,
                      PC_BVH_PAD_REL * s->size, visit_patch, &q);
    if (q.status != PROJCURVE_OK) {
        hits->count = 0;
        return q.status;
    }
    finish(s, &frame, dir, hits);
    return PROJCURVE_OK;
}

projcurve_status pc_intersect_line_patches(projcurve_context *ctx, const projcurve_surface *s,
                                           const size_t *patch_indices, size_t n_patches,
                                           pc_vec3 origin, pc_vec3 dir, int ray_only,
                                           pc_hit_list *hits)
{
    pc_ray_frame frame;
    projcurve_status st = prepare(ctx, s, origin, dir, ray_only, hits, &frame);
    if (st != PROJCURVE_OK)
        return st;
    const size_t n_grid = s->grid.spans_u * s->grid.spans_v;
    for (size_t k = 0; k < n_patches; ++k) {
        if (patch_indices[k] >= n_grid) {
            hits->count = 0;
            return pc_fail(ctx, PROJCURVE_ERR_INDEX, "patch index %zu past the %zu patches",
                           patch_indices[k], n_grid);
        }
        st = pc_ray_patch_hits(ctx, &frame, &s->grid.patches[patch_indices[k]], hits->work, hits);
        if (st != PROJCURVE_OK) {
            hits->count = 0;
            return st;
        }
    }
    finish(s, &frame, dir, hits);
    return PROJCURVE_OK;
}
