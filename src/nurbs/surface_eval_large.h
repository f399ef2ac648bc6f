/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Surface evaluation for degrees above PC_SMALL_DEGREE (surface_eval_large.c).
 */
#ifndef PC_NURBS_SURFACE_EVAL_LARGE_H
#define PC_NURBS_SURFACE_EVAL_LARGE_H

#include "nurbs/nurbs.h"

/* As pc_nurbs_surface_eval with the spans found and (u, v) in the domain;
 * any degree. */
void pc_surface_eval_large(const pc_nurbs_surface *s, double u, double v, size_t span_u,
                           size_t span_v, int n_deriv, pc_vec3 *out);

#endif /* PC_NURBS_SURFACE_EVAL_LARGE_H */
