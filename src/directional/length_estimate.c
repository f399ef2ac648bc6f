/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The estimate of the projection's total arc length of [SY13] s3.3: the
 * curve's polyline projected along Dir onto the control polygons of the
 * Bezier patches (planar triangles, so each sample is a ray/triangle
 * test). The arc-length step is a fraction of it.
 */
#include "directional/line_seeds.h"

/* Samples of the curve's polyline. */
#define PC_ESTIMATE_SAMPLES 64

/* Shortest distance between a hit of one ray and a hit of the next: the
 * step of the polygon-projected polyline along one sheet. */
static double closest_pair(const pc_polygon_hits *a, const pc_polygon_hits *b)
{
    double best = INFINITY;
    for (size_t i = 0; i < a->count; ++i)
        for (size_t k = 0; k < b->count; ++k)
            best = fmin(best, vec3_dist(a->items[i].x, b->items[k].x));
    return best;
}

double pc_directional_length_estimate(pc_line_finder *f)
{
    const projcurve_curve *c = f->proj->curve;
    size_t hint = 0;
    double total = 0.0;
    f->l1.count = 0;
    for (int i = 0; i <= PC_ESTIMATE_SAMPLES; ++i) {
        const double t = c->t0 + (c->t1 - c->t0) * (double)i / PC_ESTIMATE_SAMPLES;
        pc_vec3 p;
        if (pc_curve_eval(c, t, 0, &hint, &p) != PROJCURVE_OK || !pc_line_polygon_hits(f, p, &f->l2))
            return 0.0;
        if (f->l1.count > 0 && f->l2.count > 0)
            total += closest_pair(&f->l1, &f->l2);
        const pc_polygon_hits tmp = f->l1;
        f->l1 = f->l2;
        f->l2 = tmp;
    }
    f->l1.count = f->l2.count = 0;
    f->have_l1 = 0;
    return total;
}
