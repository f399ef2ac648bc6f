/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The reference for `eval`: a textbook bicubic B-spline evaluation with
 * second derivatives (The NURBS Book, algorithms A2.1 and A2.3, then the
 * tensor sum), written plainly, with nothing cached between calls.
 */
#ifndef PCB_NAIVE_EVAL_H
#define PCB_NAIVE_EVAL_H

#include <stddef.h>

typedef struct pcb_naive_surface {
    size_t n_u, n_v;         /* control net, u fastest */
    const double *knots_u;   /* n_u + 4, clamped */
    const double *knots_v;   /* n_v + 4 */
    const double *ctrl;      /* 3 * n_u * n_v Cartesian points */
} pcb_naive_surface;

/* out = S, Su, Sv, Suu, Suv, Svv (18 doubles). */
void pcb_naive_eval(const pcb_naive_surface *s, double u, double v, double out[18]);

#endif /* PCB_NAIVE_EVAL_H */
