/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Seeds and jump criteria of the conical projection. The seeds are the
 * hits of the ray from P(t) along Dir(t) (started a few corrector
 * tolerances behind P(t), so that a hit at lambda = 0 is not lost to
 * rounding; the tracer judges what lies behind), each polished by the
 * corrector.
 *
 * The jump criteria of [SY13] s3.4 count and compare the hits of the rays
 * with the patches' control polygons. Along a direction they rest on the
 * parallel image of a patch lying within that of its control net's convex
 * hull; from an eye the same holds for the central image (the cone of
 * directions from E) of every patch whose hull does not contain E: a
 * convex set not containing E is seen from E as a convex set of
 * directions. A patch whose hull may contain E (the eye inside its
 * control-net box) is seen in every direction, so its polygon hits say
 * nothing: a ray that meets its box asks for a full search at each check.
 * Patches lying partly behind E are otherwise safe: the rays start at
 * P(t), beyond E, and the polygon hits are taken on those rays only.
 */
#include "conical/conical_seeds.h"

#include "common/error.h"
#include "conical/conical.h"

/* How far behind P(t), in corrector tolerances, the rays of the search
 * start (as the directional seeds). */
#define PC_CONE_SEED_BEHIND 4.0
/* The patch boxes are padded by this fraction of the model size for the
 * eye test (as the polygon hits' box pad). */
#define PC_CONE_EYE_BOX_PAD 1e-9
/* Samples of the curve's polyline for the length estimate. */
#define PC_CONE_ESTIMATE_SAMPLES 64

static int box_contains(const double box[6], pc_vec3 x, double pad)
{
    return x.x >= box[0] - pad && x.x <= box[3] + pad && x.y >= box[1] - pad &&
           x.y <= box[4] + pad && x.z >= box[2] - pad && x.z <= box[5] + pad;
}

static int eye_in_patch_box(const pc_cone_finder *f, size_t patch)
{
    const projcurve_surface *s = f->proj->surface;
    return box_contains(s->grid.patches[patch].box, f->eye, PC_CONE_EYE_BOX_PAD * s->size);
}

static projcurve_status cone_find(pc_seed_finder *self, projcurve_context *ctx, double t,
                                  pc_seed_list *out)
{
    pc_cone_finder *f = self->state;
    const pc_projector *proj = f->proj;
    out->count = 0;
    pc_vec3 p, dir;
    if (!pc_conical_ray(proj, t, &p, &dir))
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK,
                       "curve evaluation failed (or met the eye) at t = %.17g", t);
    const pc_vec3 origin = vec3_axpy(p, -PC_CONE_SEED_BEHIND * proj->newton_tol, dir);
    projcurve_status st = pc_intersect_line(ctx, proj->surface, origin, dir, 1, &f->hits);
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

/* The directional criteria on the ray of t, then the eye test on the
 * patches whose boxes that ray met. */
static int cone_may_jump(pc_seed_finder *self, double t, const pc_seed *active, size_t n_active,
                         double ds)
{
    pc_cone_finder *f = self->state;
    pc_vec3 dir;
    if (!pc_conical_ray(f->proj, t, NULL, &dir)) {
        f->line.have_l1 = 0;
        return 1; /* let the full search report the failure */
    }
    f->line.dir = dir;
    if (pc_line_may_jump(&f->line.base, t, active, n_active, ds))
        return 1;
    if (f->eye_in_some_box)
        for (size_t k = 0; k < f->line.n_patches; ++k)
            if (eye_in_patch_box(f, f->line.patches[k]))
                return 1;
    return 0;
}

static void cone_reset(pc_seed_finder *self)
{
    pc_cone_finder *f = self->state;
    pc_line_jump_reset(&f->line.base);
}

void pc_cone_finder_init(pc_cone_finder *f, const pc_projector *proj, pc_vec3 eye)
{
    *f = (pc_cone_finder){0};
    f->proj = proj;
    f->eye = eye;
    pc_line_finder_init(&f->line, proj, vec3(0.0, 0.0, 1.0));
    const pc_patch_grid *grid = &proj->surface->grid;
    const size_t n = grid->spans_u * grid->spans_v;
    for (size_t k = 0; k < n && !f->eye_in_some_box; ++k)
        f->eye_in_some_box = eye_in_patch_box(f, k);
    f->base.find = cone_find;
    f->base.may_jump = cone_may_jump;
    f->base.reset = cone_reset;
    f->base.state = f;
}

static int cone_step_may_skip(pc_seed_finder *self, double ta, double tb,
                              const pc_sweep_trail *trail)
{
    const pc_cone_finder *f = self->state;
    return pc_rays_step_may_skip(&f->line, &f->eye, ta, tb, trail);
}

projcurve_status pc_cone_finder_bound_curve(projcurve_context *ctx, pc_cone_finder *f)
{
    const projcurve_status st = pc_curve_pieces_build(ctx, f->proj->curve, &f->line.pieces);
    if (st == PROJCURVE_OK && f->line.pieces.bz.n_segments > 0)
        f->base.step_may_skip = cone_step_may_skip;
    return st;
}

void pc_cone_finder_free(pc_cone_finder *f)
{
    pc_hit_list_free(&f->hits);
    pc_line_finder_free(&f->line);
    *f = (pc_cone_finder){0};
}

/* Shortest distance between a hit of one ray and a hit of the next: the
 * step of the polygon-projected polyline along one sheet. */
static double closest_pair(const pc_polygon_hits *a, const pc_polygon_hits *b)
{
    double best = INFINITY;
    for (size_t i = 0; i < a->count; ++i)
        for (size_t k = 0; k < b->count; ++k)
            best = fmin(best, vec3_dist(a->items[i].x, b->items[k].x));
    return best;
}

double pc_conical_length_estimate(pc_cone_finder *f)
{
    const projcurve_curve *c = f->proj->curve;
    pc_line_finder *line = &f->line;
    double total = 0.0;
    line->l1.count = 0;
    for (int i = 0; i <= PC_CONE_ESTIMATE_SAMPLES; ++i) {
        const double t = c->t0 + (c->t1 - c->t0) * (double)i / PC_CONE_ESTIMATE_SAMPLES;
        pc_vec3 p;
        if (!pc_conical_ray(f->proj, t, &p, &line->dir) ||
            !pc_line_polygon_hits(line, p, &line->l2))
            return 0.0;
        if (line->l1.count > 0 && line->l2.count > 0)
            total += closest_pair(&line->l1, &line->l2);
        const pc_polygon_hits tmp = line->l1;
        line->l1 = line->l2;
        line->l2 = tmp;
    }
    line->l1.count = line->l2.count = 0;
    line->have_l1 = 0;
    return total;
}
