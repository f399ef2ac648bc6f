/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * What the straight march (march.c) and the cubic march (march_cubic.c)
 * share: the candidate end of a step, the vertex a march falls back to
 * where the corrector cannot go on, and the end directions of a composed
 * piece.
 */
#include "refine/refine_internal.h"

#include <math.h>

/* The floor of a march's first step (a fraction of the branch's t range):
 * the step of the one-sided tangents (march.c, PC_SIDE_STEP_REL), above
 * which a piece's end directions are resolved. A run inherits the step of
 * the one before; after a stretch the corrector could barely follow
 * (linkrods.step surface 16, curve 87: steps of 1e-10 beside spans whose
 * nets rounding blew up) that step is so short that the composed piece's
 * end direction is rounding, the angle test fails at every shorter step,
 * and the whole next run became a gap. */
#define PC_MARCH_START_STEP_REL 1e-6

double pc_refine_march_start_step(const pc_refiner *r, double h)
{
    return fmax(h, PC_MARCH_START_STEP_REL * r->t_range);
}

int pc_refine_march_candidate(pc_refiner *r, const pc_rvertex *cur, const pc_rvertex *b,
                              double h, pc_rvertex *cand)
{
    const double remaining = b->t - cur->t;
    if (h >= remaining) {
        *cand = *b;
        return 1;
    }
    if (h > 0.5 * remaining) /* two balanced pieces rather than a long and a sliver */
        h = 0.5 * remaining;
    return pc_refine_exact_point(r, cur, b, cur->t + h, cand);
}

pc_rvertex pc_refine_next_known(const pc_refiner *r, const pc_rvertex *cur, const pc_rvertex *b)
{
    size_t k = pc_refine_guide_index(r, cur->t);
    while (k < r->n_guide && !(r->guide[k].t > cur->t))
        ++k;
    return k < r->n_guide && r->guide[k].t < b->t ? r->guide[k] : *b;
}

pc_vec3 pc_refine_end_direction(int n, const double *cw, int at_end)
{
    const double *e = cw + (at_end ? 4 * n : 0), *f = cw + (at_end ? 4 * (n - 1) : 4);
    const pc_vec3 c = vec3(e[0] / e[3], e[1] / e[3], e[2] / e[3]);
    const pc_vec3 d = vec3_axpy(vec3(f[0] - e[0], f[1] - e[1], f[2] - e[2]), -(f[3] - e[3]), c);
    return at_end ? vec3_scale(d, -1.0) : d;
}
