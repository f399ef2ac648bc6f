/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seam segments of a branch for the writers (docs/seams.md, "Writing
 * across seams"): a branch joined across seams has one pcurve in unwrapped
 * (u, v), which leaves the surface's domain beyond each seam. A curve on
 * surface must lie in the domain, so the writers state one per segment
 * between consecutive jumps: the pcurve and the 3D curve split at each
 * jump's t (exact knot insertion to full multiplicity), each pcurve
 * segment shifted back into the domain by the jumps before it (a constant
 * shift of the poles moves a rational B-spline by that constant, exactly).
 */
#ifndef PC_IO_SEAM_SPLIT_H
#define PC_IO_SEAM_SPLIT_H

#include <stddef.h>

#include "nurbs/nurbs.h"
#include "projcurve.h"
#include "trace/result.h"

/* One segment: the pcurve as homogeneous (u w, v w, 0, w) poles inside the
 * domain, and the 3D curve over the same t range (n_ctrl 0 when none was
 * given). Knots and poles are owned (malloc); poly is NULL. */
typedef struct pc_seam_segment {
    pc_nurbs_curve pcurve, curve;
} pc_seam_segment;

/* Splits pcurve (points (u, v, 0), unwrapped) and curve (3D, or NULL) at
 * the jumps' t strictly inside the pcurve's domain (a jump within 1e-12 of
 * the domain's length of a knot is taken at that knot), and shifts pcurve
 * segment k by the sum of the jumps (du, dv) before it. Both curves must
 * have the same domain (to 1e-9 of its length). A pcurve's end that lies outside domain (u0, u1,
 * v0, v1) by rounding (at most 1e-12 of its width) is put on its edge.
 * *out gets n_seams + 1 segments at most (one per jump inside, plus one),
 * *n_out their count; release with pc_seam_segments_free.
 * Statuses: OK, INVALID_ARGUMENT (the domains differ), NO_MEMORY,
 * OVERFLOW. */
projcurve_status pc_seam_split(projcurve_context *ctx, const pc_nurbs_curve *pcurve,
                               const pc_nurbs_curve *curve, const pc_seam_record *seams,
                               size_t n_seams, const double domain[4], pc_seam_segment **out,
                               size_t *n_out);

void pc_seam_segments_free(pc_seam_segment *segments, size_t n);

#endif /* PC_IO_SEAM_SPLIT_H */
