/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_minima.h"

#include "ortho/ortho_projector.h"

int pc_ortho_is_minimum(const pc_projector *proj, double t, double u, double v)
{
    int index = 0;
    return !pc_ortho_morse_index(proj, t, u, v, &index) || index == 0;
}

/* 1 when at least half of b's vertices are local minima. A branch split at
 * its centres of curvature has one index everywhere; the vote only keeps
 * a vertex next to a centre, where det K is rounding noise, from deciding. */
static int mostly_minima(const pc_projector *proj, const pc_branch *b)
{
    size_t minima = 0;
    for (size_t i = 0; i < b->n_points; ++i) {
        const double *p = b->points + 3 * i;
        minima += (size_t)pc_ortho_is_minimum(proj, p[0], p[1], p[2]);
    }
    return 2 * minima >= b->n_points;
}

void pc_ortho_keep_minima(const pc_projector *proj, projcurve_result *r)
{
    for (size_t i = r->n_branches; i-- > 0;)
        if (!mostly_minima(proj, &r->branches[i])) {
            r->stats.points -= (double)r->branches[i].n_points;
            pc_result_remove_branch(r, i);
        }
}
