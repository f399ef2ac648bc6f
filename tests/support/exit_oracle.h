/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where a directional projection curve crosses the boundary of the
 * surface's domain, found independently of the tracer's exit locator
 * (src/trace/boundary_exit.c): bisection on the curve parameter t between
 * a t where the projection has a point in the domain and one where it has
 * none near, each t classified by a Newton corrector of its own on
 * S(u, v) = P(t) + lambda Dir in (u, v, lambda), (u, v) clamped to the
 * domain, started from the last point known inside. Where the root has
 * left the domain the clamped iteration cannot reach a zero residual, so
 * the bracket closes on the crossing.
 */
#ifndef PC_TEST_EXIT_ORACLE_H
#define PC_TEST_EXIT_ORACLE_H

#include "projcurve.h"

typedef struct exit_oracle_point {
    double t, u, v, lambda;
    double x[3]; /* S(u, v) */
} exit_oracle_point;

/* The crossing between t_in (the projection passes near (u_in, v_in),
 * inside the domain) and t_out (it has left the domain there). Returns 1
 * with *out the point of the projection nearest to the boundary on the
 * inside, to the bisection's limit (a few ulps of t); 0 when t_in is not
 * inside or t_out is not outside (*out then unchanged). dir need not be
 * unit. */
int exit_oracle_crossing(const projcurve_surface *s, const projcurve_curve *c,
                         const double dir[3], double t_in, double u_in, double v_in,
                         double t_out, exit_oracle_point *out);

/* Distance of (u, v) from the nearest side of the domain, relative to that
 * side's width (0 on the boundary). */
double exit_oracle_margin(const projcurve_surface *s, double u, double v);

/* Every branch end of r on the boundary (start BOUNDARY or end BOUNDARY)
 * against the crossing found from its neighbour vertex (inside) to one
 * step of the branch beyond the end (outside). */
typedef struct exit_oracle_report {
    size_t ends;        /* boundary ends checked */
    size_t not_found;   /* ends where no crossing lies in that bracket */
    double max_dist;    /* largest distance of S(end) from S at the crossing, or of
                           P(t of end) from P at the crossing, relative to the
                           model size */
    double max_dt;      /* largest |t(end) - t(crossing)| */
    double max_margin;  /* largest distance of an end from the boundary (relative) */
} exit_oracle_report;

void exit_oracle_check_ends(const projcurve_surface *s, const projcurve_curve *c,
                            const double dir[3], const projcurve_result *r,
                            exit_oracle_report *rep);

/* Prints the report (for failing tests). */
void exit_oracle_print(const char *name, const exit_oracle_report *rep);

#endif /* PC_TEST_EXIT_ORACLE_H */
