/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_creases.h"

#include <math.h>

/* A parameter within this fraction of the domain's width of a knot lies on
 * its knot line: the tracer's last point before a failure is a corrected
 * point on the crease (measured within 1e-12 of the width on
 * test_pipe_out_true.step), far closer than any span of real extent. */
#define CREASE_TOL_REL 1e-9

/* 1 when x lies on an interior knot of multiplicity >= degree (S only C0
 * across it) of the knot vector knots (n_ctrl + degree + 1 entries). */
static int on_c0_knot(const double *knots, size_t n_ctrl, int degree, double x)
{
    const double lo = knots[degree], hi = knots[n_ctrl];
    const double tol = CREASE_TOL_REL * (hi - lo);
    /* the interior knots are knots[degree + 1 .. n_ctrl - 1]; one pass, each
     * run of equal knots counted once */
    size_t i = (size_t)degree + 1;
    while (i < n_ctrl) {
        size_t j = i;
        while (j + 1 < n_ctrl && knots[j + 1] == knots[i])
            ++j;
        const int multiplicity = (int)(j - i + 1);
        if (knots[i] > lo + tol && knots[i] < hi - tol && multiplicity >= degree &&
            fabs(x - knots[i]) <= tol)
            return 1;
        i = j + 1;
    }
    return 0;
}

static int on_crease(const pc_nurbs_surface *s, const double *tuv)
{
    return on_c0_knot(s->knots_u, s->n_u, s->deg_u, tuv[1]) ||
           on_c0_knot(s->knots_v, s->n_v, s->deg_v, tuv[2]);
}

void pc_ortho_name_crease_ends(const pc_projector *proj, projcurve_result *r)
{
    const pc_nurbs_surface *s = &proj->surface->nurbs;
    for (size_t k = 0; k < r->n_branches; ++k) {
        pc_branch *b = &r->branches[k];
        if (b->n_points == 0)
            continue;
        if (b->end == PROJCURVE_END_FAILED && on_crease(s, b->points + 3 * (b->n_points - 1)))
            b->end = PROJCURVE_END_BOUNDARY;
        if (b->start == PROJCURVE_START_JUMP && on_crease(s, b->points))
            b->start = PROJCURVE_START_BOUNDARY;
    }
}
