/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Matching the points a full seed search found to the active branches,
 * [SY13] s3.4: what is not matched starts a new branch. Generic over the
 * kind of projection: only distances on S are compared.
 */
#include "trace/tracer.h"

static pc_vec3 surface_point(const projcurve_surface *s, double u, double v)
{
    pc_vec3 out;
    pc_nurbs_surface_eval(&s->nurbs, u, v, 0, NULL, NULL, &out);
    return out;
}

void pc_match_seeds(const projcurve_surface *s, const pc_seed *active, size_t n_active,
                    const pc_seed *found, size_t n_found, double ds, unsigned char *matched)
{
    for (size_t k = 0; k < n_found; ++k)
        matched[k] = 0;
    for (size_t i = 0; i < n_active; ++i) {
        const pc_vec3 a = surface_point(s, active[i].u, active[i].v);
        size_t best = n_found;
        double best_d = ds;
        for (size_t k = 0; k < n_found; ++k) {
            if (matched[k])
                continue;
            const double d = vec3_dist(a, surface_point(s, found[k].u, found[k].v));
            if (d <= best_d) {
                best = k;
                best_d = d;
            }
        }
        if (best < n_found)
            matched[best] = 1;
    }
}
