/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Measured deviation of a projection result from the exact projection,
 * on dense samples, independently of how the result was made.
 *
 * A result is a set of 3D curves (ours: one NURBS curve per branch; Open
 * CASCADE's: the edges it returns). Two one-sided distances are measured:
 *   result_to_exact: the largest distance from a point of the result to the
 *                    exact projection (every result point must lie on it);
 *   exact_to_result: the largest distance from a primary exact point to the
 *                    result (the result must cover the projection).
 * The deviation is the larger of the two: the Hausdorff distance between the
 * result and the (primary) exact projection.
 */
#ifndef PCB_DEVIATION_H
#define PCB_DEVIATION_H

#include <stddef.h>

#include "exact.h"
#include "projcurve.h"

typedef struct pcb_curve_set {
    size_t n_curves;
    /* Parameter range of curve i; returns 0 on success. */
    int (*domain)(void *user, size_t i, double range[2]);
    /* Point of curve i at s; returns 0 on success. */
    int (*eval)(void *user, size_t i, double s, double p[3]);
    void *user;
} pcb_curve_set;

typedef struct pcb_deviation {
    double result_to_exact;
    double exact_to_result;
    double hausdorff;
} pcb_deviation;

/* Samples every curve at samples_per_curve points and measures both
 * distances. An empty result against an empty projection deviates by 0;
 * a missing branch shows as an infinite exact_to_result.
 * Returns 0, or -1 on allocation or evaluation failure. */
int pcb_measure_deviation(const pcb_exact *ex, const pcb_curve_set *result,
                          size_t samples_per_curve, pcb_deviation *out);

/* Our result as a curve set: one NURBS curve per branch. */
typedef struct pcb_result_curves {
    projcurve_curve **curves;
    size_t n;
} pcb_result_curves;

projcurve_status pcb_result_curves_init(projcurve_context *ctx, const projcurve_result *result,
                                        pcb_result_curves *rc);
/* The same with each branch's compact 3D curve
 * (projcurve_result_branch_compact_curve; the joined pieces where it has
 * none); *poles and *degree (may be NULL) get their pole count summed and
 * their largest degree, *pcurve_poles and *pcurve_degree the compact
 * pcurves'. */
projcurve_status pcb_result_compact_curves_init(projcurve_context *ctx,
                                                const projcurve_result *result,
                                                pcb_result_curves *rc, double *poles,
                                                double *degree, double *pcurve_poles,
                                                double *pcurve_degree);
void pcb_result_curves_free(pcb_result_curves *rc);
pcb_curve_set pcb_result_curve_set(pcb_result_curves *rc);

#endif /* PCB_DEVIATION_H */
