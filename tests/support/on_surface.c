/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Pieces against S at their pcurves: see on_surface.h. Nothing here is
 * shared with compose/ (which builds the pieces from blossoms and Bernstein
 * products) or with the Bernstein sums of piece_oracle.c.
 */
#include "on_surface.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* de Casteljau on n + 1 points of dim coordinates each (n <= 2 * MAX_DEGREE):
 * convex combinations only, stable at any degree. */
static void de_casteljau(const double *pts, int n, int dim, double s, double *out)
{
    double work[4 * (2 * PROJCURVE_MAX_DEGREE + 1)];
    memcpy(work, pts, (size_t)(dim * (n + 1)) * sizeof *work);
    for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i)
            for (int c = 0; c < dim; ++c)
                work[dim * i + c] = (1.0 - s) * work[dim * i + c] + s * work[dim * (i + 1) + c];
    memcpy(out, work, (size_t)dim * sizeof *out);
}

void pc_test_piece_point(int degree, const double *ctrl, const double *weights, double s,
                         double out[3])
{
    double hw[4 * (2 * PROJCURVE_MAX_DEGREE + 1)], h[4];
    for (int i = 0; i <= degree; ++i) {
        const double w = weights != NULL ? weights[i] : 1.0;
        for (int c = 0; c < 3; ++c)
            hw[4 * i + c] = ctrl[3 * i + c] * w;
        hw[4 * i + 3] = w;
    }
    de_casteljau(hw, degree, 4, s, h);
    for (int c = 0; c < 3; ++c)
        out[c] = h[c] / h[3];
}

void pc_on_surface_measure(const projcurve_result *r, const projcurve_surface *s, int samples,
                           pc_on_surface_report *out)
{
    memset(out, 0, sizeof *out);
    const size_t n_branches = projcurve_result_branch_count(r);
    for (size_t i = 0; i < n_branches; ++i) {
        size_t n_pieces = 0;
        if (projcurve_result_branch_info(NULL, r, i, NULL, NULL, NULL, NULL, &n_pieces) !=
            PROJCURVE_OK) {
            ++out->failures;
            continue;
        }
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0, uv_degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
            double range[2], uv_range[4], uv[2 * PROJCURVE_MAX_PCURVE_POINTS];
            if (projcurve_result_piece(NULL, r, i, k, &degree, ctrl, w, range, uv_range) !=
                    PROJCURVE_OK ||
                projcurve_result_piece_pcurve(NULL, r, i, k, &uv_degree, uv) != PROJCURVE_OK ||
                degree < 1 || degree > 2 * PROJCURVE_MAX_DEGREE ||
                (uv_degree != 1 && uv_degree != 3)) {
                ++out->failures;
                continue;
            }
            ++out->pieces;
            ++out->pcurve_degree[uv_degree];
            out->worst_end = fmax(out->worst_end, fmax(fabs(uv[0] - uv_range[0]),
                                                       fabs(uv[1] - uv_range[1])));
            out->worst_end = fmax(out->worst_end, fmax(fabs(uv[2 * uv_degree] - uv_range[2]),
                                                       fabs(uv[2 * uv_degree + 1] - uv_range[3])));
            double hw[4 * PROJCURVE_MAX_PIECE_POINTS];
            for (int j = 0; j <= degree; ++j) {
                for (int c = 0; c < 3; ++c)
                    hw[4 * j + c] = w[j] * ctrl[3 * j + c];
                hw[4 * j + 3] = w[j];
            }
            for (int j = 0; j <= samples; ++j) {
                const double sp = (double)j / samples;
                double h[4], q[2], x[3];
                de_casteljau(hw, degree, 4, sp, h);
                de_casteljau(uv, uv_degree, 2, sp, q);
                if (projcurve_surface_eval(NULL, s, q[0], q[1], 0, x) != PROJCURVE_OK) {
                    ++out->failures;
                    continue;
                }
                const double d = hypot(hypot(h[0] / h[3] - x[0], h[1] / h[3] - x[1]),
                                       h[2] / h[3] - x[2]);
                if (!(d <= out->worst) && !isnan(out->worst)) { /* the first NaN stays */
                    out->worst = d;
                    out->worst_branch = i;
                    out->worst_piece = k;
                    out->worst_s = sp;
                }
            }
        }
    }
}

double pc_on_surface_check(const char *name, const projcurve_result *r,
                           const projcurve_surface *s, int pcurve_degree)
{
    double box[6], pieces = NAN;
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    const double size = hypot(hypot(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
    pc_on_surface_report rep;
    pc_on_surface_measure(r, s, PC_ON_SURFACE_SAMPLES, &rep);
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &pieces));
    CHECK(rep.failures == 0);
    CHECK((double)rep.pieces == pieces);
    CHECK(rep.worst_end == 0.0);
    CHECK(pcurve_degree == 3 || rep.pcurve_degree[3] == 0);
    if (!(rep.worst <= PC_ON_SURFACE_REL * size))
        fprintf(stderr,
                "%s: piece %zu of branch %zu is off S(pcurve) by %.3g at s = %g (bound %.3g)\n",
                name, rep.worst_piece, rep.worst_branch, rep.worst, rep.worst_s,
                PC_ON_SURFACE_REL * size);
    CHECK(rep.worst <= PC_ON_SURFACE_REL * size);
    return rep.worst / size;
}
