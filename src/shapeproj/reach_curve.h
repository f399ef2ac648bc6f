/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The part of the curve that can reach a face, projected in place of the
 * whole curve when it is short.
 *
 * The tracer's steps and its jump sweep's checks are fractions of the
 * projected curve's domain and of its projection's estimated length
 * (trace/branches.c: one check every half arc-length step, 1/128 of the
 * length by default). A face much smaller than the curve's sweep is then
 * crossed between two full searches of the sweep, and its branches, born
 * and gone between them, are not found (linkrods.step, `projcurve-bench
 * shape` "line dir": faces 19 and 24, hit over 6.5e-4 and 4e-4 of the
 * line's domain, were missed at checks 7.8e-3 apart). Projected over the
 * hull of its t ranges (t_ranges.h) alone, a face gets steps relative to
 * what can reach it. The restriction is exact (knot insertion) and keeps
 * the parameter, so branch parameters are those of the whole curve; the
 * ranges hold every hit (padded), so no branch starts or ends at the cut.
 */
#ifndef PC_SHAPEPROJ_REACH_CURVE_H
#define PC_SHAPEPROJ_REACH_CURVE_H

#include "shapeproj/t_ranges.h"

/* The hull of the ranges is used when it is at most this fraction of the
 * curve's domain (a wider hull gains little resolution for the cost of a
 * curve copy). */
#define PC_REACH_CURVE_MAX_SHARE 0.5

/* *out = curve restricted to the hull of ranges (a new curve, released with
 * projcurve_curve_destroy), or NULL when the whole curve is to be projected:
 * no range, a hull wider than PC_REACH_CURVE_MAX_SHARE of the domain, or a
 * callback curve. Statuses: OK, NO_MEMORY, and those of the curve's
 * creation. */
projcurve_status pc_reach_curve(projcurve_context *ctx, const projcurve_curve *curve,
                                const pc_t_ranges *ranges, projcurve_curve **out);

#endif /* PC_SHAPEPROJ_REACH_CURVE_H */
