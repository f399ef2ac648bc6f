/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Creases of a faceted surface: test_pipe_out_true.step surface 0 is
 * degree 1 x 1 with 30 x 30 uniform spans on [-1500, 1500]^2, so only C0
 * across every interior knot line (u or v a multiple of 100). A foot point
 * reaching a convex crease does not continue on the next facet (the
 * nearest point stays on the crease, a foot point of neither facet), and
 * the tracer failed there: before, 3 of the 7 traced branches of curve 0
 * ended FAILED on a knot line, and the branches found in mid-curve on one
 * started as JUMP. The defined answer (docs/orthogonal.md): such a branch
 * ends with PROJCURVE_END_BOUNDARY, one starting on a crease starts with
 * PROJCURVE_START_BOUNDARY, as on the boundary of a smooth piece.
 *
 * Checked on the traced branches (COMPOSE = 0), every curve of the file:
 * no FAILED end on a knot line; every BOUNDARY end or start on the domain's edge or on a
 * knot line (the closed form of the knots, not the library's test).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"

/* On a knot line or edge: within this of a multiple of 100 (the tracer's
 * corrected points on a crease are within ~1e-12 of the width of it). */
#define LINE_TOL 3e-6

static int on_line(double x)
{
    return fabs(x / 100.0 - nearbyint(x / 100.0)) * 100.0 <= LINE_TOL;
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/test_pipe_out_true.step"),
                                  &m) != PROJCURVE_OK)
        pc_test_missing_data("real/test_pipe_out_true.step");
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    CHECK(s != NULL);
    double dom[4] = {0, 0, 0, 0};
    if (s != NULL)
        projcurve_surface_domain(NULL, s, dom);
    CHECK(dom[0] == -1500.0 && dom[1] == 1500.0 && dom[2] == -1500.0 && dom[3] == 1500.0);
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0));
    size_t failed = 0, failed_on_line = 0, off_line = 0, at_creases = 0, branches = 0;
    for (size_t ci = 0; s != NULL && projcurve_model_curve(m, ci) != NULL; ++ci) {
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_orthogonal(NULL, s, projcurve_model_curve(m, ci), o, &r));
        for (size_t b = 0; r != NULL && b < projcurve_result_branch_count(r); ++b) {
            projcurve_branch_start start;
            projcurve_branch_end end;
            size_t n = 0;
            CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, &start, &end, &n, NULL));
            double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
            CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
            const double *first = pts, *last = pts + 3 * (n - 1);
            if (end == PROJCURVE_END_FAILED) {
                failed += 1;
                failed_on_line += on_line(last[1]) || on_line(last[2]);
            }
            if (end == PROJCURVE_END_BOUNDARY) {
                off_line += !(on_line(last[1]) || on_line(last[2]));
                at_creases += 1;
            }
            if (start == PROJCURVE_START_BOUNDARY) {
                off_line += !(on_line(first[1]) || on_line(first[2]));
                at_creases += 1;
            }
            ++branches;
            free(pts);
        }
        projcurve_result_destroy(r);
    }
    printf("surface 0, every curve: %zu traced branches, %zu FAILED ends (%zu on a knot line), "
           "%zu boundary ends and starts, %zu of them off the knot lines\n",
           branches, failed, failed_on_line, at_creases, off_line);
    CHECK(branches > 0);
    /* One branch of curve 2 still fails inside a facet, 76 from the crease
     * u = 0 it was heading for (the tracer's steps, not a crease end). */
    CHECK(failed_on_line == 0 && failed <= 1);
    CHECK(at_creases > 0);
    CHECK(off_line == 0);
    projcurve_options_destroy(o);
    projcurve_model_destroy(m);
    return pc_test_finish("test_ortho_creases");
}
