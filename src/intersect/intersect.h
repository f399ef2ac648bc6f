/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Line / surface intersection: every hit of origin + lambda * dir with a
 * NURBS surface. BVH and control-net culling choose candidate patches,
 * Bezier clipping isolates each root, Newton polishes it to full precision
 * (docs/intersection.md).
 */
#ifndef PC_INTERSECT_H
#define PC_INTERSECT_H

#include <stddef.h>

#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* Internal flag (never in the public flags): the hit is a pole, a point
 * where a whole patch edge collapses, so the parameter along that edge is
 * arbitrary (the middle of the patch's edge is reported). */
#define PC_HIT_POLE 0x100u
/* Internal flag: the hit is the least-squares point of a clipping box that
 * could not be resolved (a grazing sliver, the depth bound, a failed
 * Newton), flagged PROJCURVE_HIT_TANGENT for that reason alone. */
#define PC_HIT_STALLED 0x200u

typedef struct pc_hit {
    double u, v, lambda;
    double residual; /* distance of S(u, v) to the line */
    unsigned flags;  /* PROJCURVE_HIT_TANGENT | PROJCURVE_HIT_BOUNDARY | PC_HIT_POLE |
                      * PC_HIT_STALLED */
} pc_hit;

/* A growable list of hits owned by the caller (pc_hit_list_free). Start it
 * zeroed ({0}). It also keeps the scratch memory of the Bezier clipping, so
 * that a caller who reuses one list for many rays pays no allocation per ray
 * once the list has grown. */
typedef struct pc_hit_list {
    pc_hit *items;
    size_t count, capacity;
    double *work;          /* clipping scratch, reused between calls */
    size_t work_capacity;  /* doubles */
    /* Set by pc_hit_list_borrow: items / work are the caller's buffers,
     * never freed or reallocated here (growth moves to the heap). */
    int items_borrowed, work_borrowed;
} pc_hit_list;

/* Starts `list` on caller-owned buffers (e.g. on the stack) of the given
 * capacities, so that a one-off query allocates nothing when they suffice.
 * The buffers must outlive the list; pc_hit_list_free still releases what
 * growth allocated. */
void pc_hit_list_borrow(pc_hit_list *list, pc_hit *items, size_t n_items, double *work,
                        size_t n_work);

void pc_hit_list_free(pc_hit_list *list);

/* Clears `hits` and fills it with every intersection sorted by lambda; with
 * ray_only, only lambda > 0. dir need not be unit length but must be finite
 * and non-zero (the caller validates). Each hit satisfies the line equation
 * to ~1e-12 of the model size, plus the parameters' resolution |Su| ulp(u) +
 * |Sv| ulp(v) where spans are far narrower than their parameters (knot
 * clusters). One hit per point of the line: copies whose lambda agree to
 * 1e-8 of the model's scale (chained) are one, whatever their (u, v) --
 * shared patch edges and corners, poles, the two sides of a closed
 * surface's seam, sheets of a knot cluster folded onto each other. The copy
 * kept is, among exact transversal ones, the one with the smaller u, then
 * v (a seam crossing is reported at u0, or v0), otherwise the nearest the
 * line (docs/intersection.md). Grazing hits are flagged
 * PROJCURVE_HIT_TANGENT (known to ~1e-7 of the model along the line), hits
 * on the domain's edge PROJCURVE_HIT_BOUNDARY.
 * Statuses: OK, NO_MEMORY (OVERFLOW for degrees out of range, which a valid
 * surface never has). The list's scratch is reused: calling again with the
 * same list allocates nothing new. Thread-safe for distinct lists. */
projcurve_status pc_intersect_line(projcurve_context *ctx, const projcurve_surface *s,
                                   pc_vec3 origin, pc_vec3 dir, int ray_only,
                                   pc_hit_list *hits);

/* Hits restricted to the given patches (indices into s->grid.patches), used
 * by jump detection to look only at the patches near a predicted point.
 * An index may repeat. Statuses: as above, and INDEX for an index past the
 * last patch. */
projcurve_status pc_intersect_line_patches(projcurve_context *ctx, const projcurve_surface *s,
                                           const size_t *patch_indices, size_t n_patches,
                                           pc_vec3 origin, pc_vec3 dir, int ray_only,
                                           pc_hit_list *hits);

#endif /* PC_INTERSECT_H */
