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

/* Two grazing hits are one touching point when the surface halfway
 * between them (in parameters) is as close to the line as a hit: a double
 * root is only known to ~sqrt(tolerance) along the line, so copies found
 * from neighbouring boxes or patches can lie well apart, but the surface
 * between them hugs the line. Two separate touching points do not. */
typedef struct graze_context {
    const projcurve_surface *surface;
    const pc_ray_frame *frame;
} graze_context;

static int same_graze(const void *user, const pc_hit *a, const pc_hit *b)
{
    const graze_context *g = user;
    pc_vec3 p;
    pc_nurbs_surface_eval(&g->surface->nurbs, 0.5 * (a->u + b->u), 0.5 * (a->v + b->v), 0, NULL,
                          NULL, &p);
    const pc_vec3 w = vec3_sub(p, g->frame->origin);
    const double off = vec3_norm(vec3_axpy(w, -vec3_dot(w, g->frame->d), g->frame->d));
    return off <= 2.0 * g->frame->tol_residual;
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
