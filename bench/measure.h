/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * One case measured: the whole projection timed (median after warm-up),
 * its shape (branches, pieces, control points, worst joint angle) and its
 * deviation from the exact projection measured on dense samples.
 */
#ifndef PCB_MEASURE_H
#define PCB_MEASURE_H

#include <stddef.h>

#include "cases.h"
#include "deviation.h"
#include "timing.h"

typedef struct pcb_measurement {
    double ms;              /* median ms per projection */
    double branches;
    double pieces;          /* composed pieces, all branches */
    double control_points;  /* of the joined branch curves */
    double points;          /* traced points */
    double max_joint_deg;   /* worst tangent angle between consecutive pieces */
    pcb_deviation deviation;
    double uniform_pieces;  /* equal-t pieces a uniform split needs for eps_D (NaN: not asked) */
    /* The compact forms (src/fit/): poles summed over the branches and
     * the largest degree, of the 3D curves and of the pcurves; the 3D
     * curves' deviation measured like the pieces'; and the time the fits
     * add to the projection (ms, the same run with and without them). */
    double compact_poles, compact_degree, pcurve_poles, pcurve_degree;
    pcb_deviation compact_deviation;
    double fit_ms;
} pcb_measurement;

/* Every field NaN. */
void pcb_measurement_clear(pcb_measurement *m);

/* How densely accuracy is measured. */
typedef struct pcb_sampling {
    size_t exact_samples;      /* curve parameters sampled for the oracle */
    size_t min_per_curve;      /* result samples per branch curve, at least */
    size_t per_piece;          /* and at least this many per composed piece */
} pcb_sampling;

/* Dense for real figures, sparse for quick runs. */
pcb_sampling pcb_sampling_for(int quick);

/* Measures case c; with with_uniform, also the uniform split count.
 * Returns 0, or -1 with a message in status. */
int pcb_measure_case(const pcb_case *c, const pcb_timing *timing, const pcb_sampling *sampling,
                     int with_uniform, pcb_measurement *m, char *status, size_t status_size);

/* Shape figures of a result (branches, pieces, control points, joint angle,
 * points). Returns OK or the failing library status. */
projcurve_status pcb_result_shape(projcurve_context *ctx, const projcurve_result *r,
                                  pcb_measurement *m);

/* Smallest number of equal-t pieces per branch whose (u, v) chords,
 * composed on the surface, stay within eps_d of the exact projection and
 * meet at tangent angles within eps_t_deg (doubling, then bisection;
 * capped). */
double pcb_uniform_pieces(const pcb_exact *ex, const projcurve_result *r, double eps_d,
                          double eps_t_deg);

/* Second-order against RK4 tracing on one case, whole projection with the
 * case's tolerances, timed pair by pair. */
typedef struct pcb_method_pair {
    double second_ms, rk4_ms;
    double rk4_over_second;  /* median of per-run ratios */
    double second_points, rk4_points;
} pcb_method_pair;

int pcb_compare_methods(const pcb_case *c, const pcb_timing *timing, pcb_method_pair *out,
                        char *status, size_t status_size);

#endif /* PCB_MEASURE_H */
