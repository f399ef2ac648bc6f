/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS data export for the Open CASCADE comparison (see occt_geometry.h).
 * Surfaces are read from the handle's internal storage (homogeneous control
 * points), curves through the public accessors.
 */
#include "occt_geometry.h"

#include <stdlib.h>
#include <string.h>

#include "geom/curve.h"
#include "geom/surface.h"

void pcb_nurbs_data_free(pcb_nurbs_data *d)
{
    free(d->knots_u);
    free(d->knots_v);
    free(d->ctrl);
    free(d->weights);
    memset(d, 0, sizeof *d);
}

int pcb_surface_data(const projcurve_surface *s, pcb_nurbs_data *out)
{
    const pc_nurbs_surface *n = &s->nurbs;
    memset(out, 0, sizeof *out);
    const size_t count = n->n_u * n->n_v;
    const size_t nku = n->n_u + (size_t)n->deg_u + 1, nkv = n->n_v + (size_t)n->deg_v + 1;
    out->deg_u = n->deg_u;
    out->deg_v = n->deg_v;
    out->n_u = n->n_u;
    out->n_v = n->n_v;
    out->rational = n->rational;
    out->knots_u = malloc(nku * sizeof *out->knots_u);
    out->knots_v = malloc(nkv * sizeof *out->knots_v);
    out->ctrl = malloc(3 * count * sizeof *out->ctrl);
    out->weights = malloc(count * sizeof *out->weights);
    if (!out->knots_u || !out->knots_v || !out->ctrl || !out->weights) {
        pcb_nurbs_data_free(out);
        return -1;
    }
    memcpy(out->knots_u, n->knots_u, nku * sizeof *out->knots_u);
    memcpy(out->knots_v, n->knots_v, nkv * sizeof *out->knots_v);
    for (size_t i = 0; i < count; ++i) {
        const double *h = &n->cw[4 * i];
        out->weights[i] = h[3];
        for (int k = 0; k < 3; ++k)
            out->ctrl[3 * i + (size_t)k] = h[k] / h[3];
    }
    return 0;
}

int pcb_curve_data(const projcurve_curve *c, pcb_nurbs_data *out)
{
    memset(out, 0, sizeof *out);
    int degree = 0, rational = 0;
    size_t n_ctrl = 0, n_knots = 0;
    if (projcurve_curve_nurbs_info(NULL, c, &degree, &n_ctrl, &n_knots, &rational) !=
        PROJCURVE_OK)
        return -1;
    out->deg_u = degree;
    out->n_u = n_ctrl;
    out->n_v = 1;
    out->rational = rational;
    out->knots_u = malloc(n_knots * sizeof *out->knots_u);
    out->ctrl = malloc(3 * n_ctrl * sizeof *out->ctrl);
    out->weights = malloc(n_ctrl * sizeof *out->weights);
    if (!out->knots_u || !out->ctrl || !out->weights ||
        projcurve_curve_nurbs_data(NULL, c, out->ctrl, out->weights, out->knots_u) !=
            PROJCURVE_OK) {
        pcb_nurbs_data_free(out);
        return -1;
    }
    return 0;
}
