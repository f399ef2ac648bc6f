/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Directional projection onto real CAD surfaces (tests/data/real): a
 * wavy cubic curve held above the surface's bounding box along its thinnest
 * axis, projected back along (a slight tilt of) that axis. Dense brute force
 * must find nothing the tracer missed, every vertex must satisfy the
 * projection equation, and composition must succeed.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_SAMPLES 3000
/* vertices on the projection to this fraction of the model size */
#define RESIDUAL_REL 1e-11

static void run(const char *file, size_t surface_index)
{
    char rel[256];
    snprintf(rel, sizeof rel, "real/%s", file);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path(rel), &m) != PROJCURVE_OK) {
        pc_test_fail_at(__FILE__, __LINE__, "%s: not readable", file);
        return;
    }
    const projcurve_surface *s = projcurve_model_surface(m, surface_index);
    CHECK(s != NULL);
    if (s == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    const double ext[3] = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
    const int thin = ext[0] <= ext[1] && ext[0] <= ext[2] ? 0 : (ext[1] <= ext[2] ? 1 : 2);
    const int a = (thin + 1) % 3, b = (thin + 2) % 3;
    const double size = sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
    /* five control points across the box, 30% to 70% of its extents,
     * waving in the other direction, one diagonal above the box */
    double pts[15];
    for (int i = 0; i < 5; ++i) {
        const double f = 0.15 + 0.175 * i;
        pts[3 * i + a] = box[a] + f * ext[a];
        pts[3 * i + b] = box[b] + (0.5 + 0.25 * ((i % 2) ? 1 : -1) * (i == 0 || i == 4 ? 0.0 : 1.0)) * ext[b];
        pts[3 * i + thin] = box[thin + 3] + size;
    }
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    double d[3] = {0, 0, 0};
    d[thin] = -1.0;
    d[a] = 0.03;
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    printf("%s (%zu branches) ", file, projcurve_result_branch_count(r));
    trace_oracle_print("", &rep);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_REL * size);
    CHECK(rep.behind == 0);
    const size_t nb = projcurve_result_branch_count(r);
    projcurve_result_destroy(r);
    /* composed with the defaults */
    r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, d, NULL, &r));
    /* composition keeps the traced branches; where it cannot (a gap it
     * leaves, a stretch it cannot verify, both near the horn's folds) the
     * result says so: each failure place (projcurve_result_failure_count)
     * splits one branch (the rest resumes with START_FAILED) or drops one
     * stretch, so the count moves by at most one per failure. Whether such
     * a place opens depends on the rounding of the build (FMA clones or
     * not): the Release build has one on the horn, the Debug build one
     * more there and one on the blade. */
    const size_t composed = projcurve_result_branch_count(r);
    const size_t failures = projcurve_result_failure_count(r);
    CHECK(composed <= nb + failures && composed + failures >= nb);
    for (size_t i = 0; i < composed; ++i) {
        size_t pieces = 0;
        projcurve_result_branch_info(NULL, r, i, NULL, NULL, NULL, NULL, &pieces);
        CHECK(pieces > 0);
    }
    if (failures > 0)
        printf("%s composed: %zu branches (traced %zu), %zu failure place(s) reported\n", file,
               composed, nb, failures);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
}

int main(void)
{
    FILE *probe = fopen(pc_test_data_path("real/SOURCES.md"), "r");
    if (probe == NULL)
        pc_test_missing_data("real/SOURCES.md");
    fclose(probe);
    run("sunglasses_lens.igs", 0);
    run("bladex_upper.iges", 0);
    run("horn.xml", 0);
    run("egg.xml", 0);
    return pc_test_finish("test_trace_real");
}
