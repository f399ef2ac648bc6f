/*
 * Composed pieces against the surface, through the public API only: every
 * piece of a result, read with projcurve_result_piece, is evaluated by de
 * Casteljau's algorithm in homogeneous coordinates and compared with
 * projcurve_surface_eval at its pcurve (projcurve_result_piece_pcurve, also
 * by de Casteljau) at evenly spaced parameters s in [0, 1]. A piece made by
 * composition lies on S exactly, so the two differ only by rounding.
 */
#ifndef PC_TEST_ON_SURFACE_H
#define PC_TEST_ON_SURFACE_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_on_surface_report {
    double worst;             /* largest |piece(s) - S(u(s), v(s))| */
    size_t worst_branch, worst_piece;
    double worst_s;
    double worst_end;         /* pcurve ends against the piece's uv_range */
    size_t pieces;            /* pieces read */
    size_t pcurve_degree[4];  /* pieces by pcurve degree (index 1 and 3) */
    int failures;             /* accessor or evaluation calls that failed */
} pc_on_surface_report;

/* Measures every piece of every branch of r at `samples` + 1 parameters. */
void pc_on_surface_measure(const projcurve_result *r, const projcurve_surface *s, int samples,
                           pc_on_surface_report *out);

#endif /* PC_TEST_ON_SURFACE_H */
