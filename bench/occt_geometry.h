/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The exact NURBS data of our surfaces and curves as plain arrays, so that
 * the Open CASCADE comparison builds the very same geometry
 * (Geom_BSplineSurface / Geom_BSplineCurve) instead of re-reading files.
 */
#ifndef PCB_OCCT_GEOMETRY_H
#define PCB_OCCT_GEOMETRY_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pcb_nurbs_data {
    int deg_u, deg_v;          /* curves: deg_u only */
    size_t n_u, n_v;           /* control points (curves: n_v = 1), u fastest */
    double *knots_u, *knots_v; /* clamped, n + deg + 1 each (curves: knots_v NULL) */
    double *ctrl;              /* 3 * n_u * n_v Cartesian points */
    double *weights;           /* n_u * n_v */
    int rational;
} pcb_nurbs_data;

#ifdef __cplusplus
extern "C" {
#endif

/* Returns 0, or -1 (no memory, or a callback curve). */
int pcb_surface_data(const projcurve_surface *s, pcb_nurbs_data *out);
int pcb_curve_data(const projcurve_curve *c, pcb_nurbs_data *out);
void pcb_nurbs_data_free(pcb_nurbs_data *d);

#ifdef __cplusplus
}
#endif

#endif /* PCB_OCCT_GEOMETRY_H */
