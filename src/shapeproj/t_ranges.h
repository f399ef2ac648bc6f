/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The curve parameter ranges over which a projection can reach a face.
 *
 * A face's 3D box holds its whole untrimmed surface (the control-net box,
 * brep/face.h), so every hit of the untrimmed projection lies in it: at a
 * parameter t where no point of the swept curve (P(t) swept along +Dir, or
 * the ray from the eye E through P(t) beyond P(t)) meets the box, there is
 * no hit at all. The curve is cut into its Bezier segments, each split in
 * halves by de Casteljau down to PC_T_RANGE_DEPTH levels (2^depth pieces
 * per segment); a piece lies in the convex hull of its control points, so
 * when the piece's control box swept (face_select.h: the same exact box
 * tests) misses the face box, no t of the piece has a hit. The ranges are
 * the union of the pieces whose sweep meets the box (conservative: never a
 * hit lost). The test is exact for a piece's box (face_select.h).
 *
 * A face with no range is not projected (shape_project.c): its untrimmed
 * projection has no point. A face whose ranges have a short hull is
 * projected over the curve restricted to it (reach_curve.h: else a small
 * face is missed between two checks of the sweep); otherwise over the whole
 * curve: the tracer's steps are fractions of the curve's domain and of the
 * projection's length estimated over it (trace/), so the part of the curve
 * over a range would be traced more finely than the whole curve is there,
 * which costs more than the parameters without hits save (the sweep over
 * them is cheap). Ranges closer than PC_T_RANGE_MERGE_GAP of the domain
 * are merged (a merged gap only adds t with no hit).
 *
 * Unrestricted (one range, the whole domain): a callback curve (no control
 * points to bound it), a rational curve with a weight <= 0 (no convex hull
 * property), and the orthogonal projection (a foot point needs no ray).
 */
#ifndef PC_SHAPEPROJ_T_RANGES_H
#define PC_SHAPEPROJ_T_RANGES_H

#include "faceproj/surface_projection.h"

/* Levels of halving of each Bezier segment. */
#define PC_T_RANGE_DEPTH 5

/* Ranges whose gap is below this fraction of the curve's domain are merged. */
#define PC_T_RANGE_MERGE_GAP (1.0 / 64.0)

/* The control boxes of the curve's pieces: per Bezier segment, a complete
 * binary tree of 2^(depth + 1) - 1 boxes in heap order (node k's halves
 * 2k + 1, 2k + 2). n_segments 0: the curve is not bounded (unrestricted). */
typedef struct pc_curve_boxes {
    size_t n_segments;
    double t0, t1;   /* the curve's domain */
    double *breaks;  /* n_segments + 1 */
    double *boxes;   /* 6 per node */
} pc_curve_boxes;

/* The boxes of curve for the projection kind (none for orthogonal and the
 * unbounded curves above). Statuses: OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_curve_boxes_build(projcurve_context *ctx, const projcurve_curve *curve,
                                      const pc_projection_spec *spec, pc_curve_boxes *out);
void pc_curve_boxes_free(pc_curve_boxes *cb);

typedef struct pc_t_range {
    double a, b;
} pc_t_range;

typedef struct pc_t_ranges {
    pc_t_range *items;
    size_t count, capacity;
} pc_t_ranges;

/* The padding of the face box, in model units, for a projection with
 * parameters p onto a model of size `size`: 1000 times the precision of
 * the exact points (pc_params_precision), as the seam joining distance. A
 * hit's t is solved to that precision, so its P(t) may lie that far from
 * where the sweep enters the box. */
double pc_t_range_pad(const pc_params *p, double size);

/* The ranges (increasing, disjoint) where the projection spec of the
 * curve boxed by cb can reach face_box grown by pad on every side, in *out
 * (emptied first): none when it cannot, the whole domain when cb bounds
 * nothing. Statuses: OK, NO_MEMORY. */
projcurve_status pc_t_ranges_find(projcurve_context *ctx, const pc_curve_boxes *cb,
                                  const pc_projection_spec *spec, const double face_box[6],
                                  double pad, pc_t_ranges *out);

#endif /* PC_SHAPEPROJ_T_RANGES_H */
