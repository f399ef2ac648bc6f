/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The precision a projection can reach: its coordinates are doubles, so
 * S(u, v) - P(t) is known only to a few ulps of the largest coordinate, not
 * to a fraction of the model's size. Far from the origin (a part placed at
 * 1e6 in an assembly) the relative tolerances of the options fall below that
 * rounding; the projectors floor theirs by it, so that translated geometry
 * gives the translated result.
 */
#ifndef PC_TRACE_PRECISION_H
#define PC_TRACE_PRECISION_H

#include "geom/curve.h"
#include "geom/surface.h"

/* The ulps of the largest coordinate a tolerance on S - P never goes below:
 * an evaluation of S or P rounds to a few ulps (the sums of a de Boor or
 * basis-function evaluation of degree up to ~10), their difference adds
 * both. */
#define PC_ROUNDING_ULPS 16.0

/* PC_ROUNDING_ULPS ulps of the largest |coordinate| of the surface's
 * control net and of the curve (17 samples: a factor of two in the
 * magnitude does not matter here), in model units. */
double pc_pair_rounding(const projcurve_surface *surface, const projcurve_curve *curve);

#endif /* PC_TRACE_PRECISION_H */
