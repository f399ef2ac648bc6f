/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seed finder of the directional projection ([SY13] s3.1, s3.4): the
 * points of the projection at P(t) are the hits of the ray P(t) + lambda Dir
 * (lambda > 0) with S; the jump criteria compare the ray's hits with the
 * control polygons of the patches against the previous ray's.
 */
#ifndef PC_DIRECTIONAL_LINE_SEEDS_H
#define PC_DIRECTIONAL_LINE_SEEDS_H

#include <stddef.h>

#include "geom/curve_pieces.h"
#include "intersect/intersect.h"
#include "trace/trace.h"

/* A hit of a ray with the control polygon of patch `patch`. */
typedef struct pc_polygon_hit {
    size_t patch;
    pc_vec3 x;
} pc_polygon_hit;

/* A list of polygon hits (one ray's). */
typedef struct pc_polygon_hits {
    pc_polygon_hit *items;
    size_t count, capacity;
} pc_polygon_hits;

typedef struct pc_line_finder {
    pc_seed_finder base;       /* base.state points to this struct */
    const pc_projector *proj;  /* surface, curve and the corrector */
    pc_vec3 dir;               /* unit projection direction */
    pc_hit_list hits;          /* scratch of find() */
    size_t curve_hint;
    /* Jump criteria state ([SY13] s3.4): control-polygon hits of the
     * previous ray L1 and of the current ray L2, and the patches the BVH
     * returned for L2. */
    pc_polygon_hits l1, l2;
    size_t *patches;
    size_t n_patches, cap_patches;
    int patches_incomplete;    /* memory ran out collecting them */
    /* Memory ran out for the polygon hits at least once in this run: the
     * length estimate or a jump decision then differed from the one with
     * memory, so the caller must fail the run with NO_MEMORY. */
    int no_memory;
    int have_l1;
    /* The curve's Bezier segments, for the control boxes of the pieces
     * between two checks (step_skip.c); built by pc_line_finder_bound_curve. */
    pc_curve_pieces pieces;
} pc_line_finder;

/* Sets up the finder (no allocation until used). proj must be directional. */
void pc_line_finder_init(pc_line_finder *f, const pc_projector *proj, pc_vec3 unit_dir);
void pc_line_finder_free(pc_line_finder *f);

/* Gives the finder the bounds of the curve's pieces and with them its
 * step_may_skip (directional; the conical finder sets its own): needed by
 * the jump sweep only. A curve without bounds (callback, weight <= 0)
 * leaves step_may_skip NULL. Statuses: OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_line_finder_bound_curve(projcurve_context *ctx, pc_line_finder *f);

/* step_may_skip for rays along f->dir (eye NULL) or from *eye through the
 * curve (step_skip.c): 1 when the control box of the curve over [ta, tb],
 * swept along the rays (geom/box_reach.h), meets the box of a patch (the
 * surface's BVH) that neither the ray at ta nor the one at tb meets and
 * that no polyline of the trail crosses over [ta, tb] in (u, v). 0 when
 * the curve has no bounds. */
int pc_rays_step_may_skip(const pc_line_finder *f, const pc_vec3 *eye, double ta, double tb,
                          const pc_sweep_trail *trail);

/* The jump criteria of [SY13] s3.4 (jump_detect.c), the finder's
 * may_jump and reset. */
int pc_line_may_jump(pc_seed_finder *self, double t, const pc_seed *active, size_t n_active,
                     double ds);
void pc_line_jump_reset(pc_seed_finder *self);

/* Every control-polygon hit of the ray origin + lambda dir over the patches
 * whose boxes it meets; clears and fills out. Returns 0 (and sets
 * f->no_memory) when memory ran out. Also used by the length estimate. */
int pc_line_polygon_hits(pc_line_finder *f, pc_vec3 origin, pc_polygon_hits *out);

/* The projection's arc length estimated as in [SY13] s3.3 (the curve's
 * polyline projected onto the patches' control polygons); 0 when no
 * sample meets them (length_estimate.c). */
double pc_directional_length_estimate(pc_line_finder *f);

#endif /* PC_DIRECTIONAL_LINE_SEEDS_H */
