/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * End to end on the shared cases (tests/data/cases/MANIFEST.tsv): every
 * directional and orthogonal case is projected through the public API at
 * eps_D = 1e-2, 1e-3, 1e-4, 1e-5 and 1e-6 of the model size with eps_T = 1
 * degree, and at 1e-3 with 10 degrees, with straight and with cubic pcurves
 * (PROJCURVE_OPT_PCURVE_DEGREE 1 and 3). Every composed branch is measured
 * against the exact projection by the test oracles
 * (tests/support/piece_oracle): the Hausdorff distance both ways on dense
 * samples, the joint angles, the joins, and that each piece stays in one
 * Bezier patch. The exact projection at t is the oracle projector's own
 * Newton solution, started from the branch's pcurve. Every piece, read
 * through the public accessors, equals S at its pcurve at 100 parameters
 * (tests/support/on_surface).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "on_surface.h"
#include "piece_oracle.h"

#define MAX_CASES 32
#define NAME_LEN 96

typedef struct manifest_case {
    char name[NAME_LEN];
    int orthogonal;
    double dir[3];
    long expected_branches;
} manifest_case;

/* Rows of MANIFEST.tsv (name, mode, dir_x, dir_y, dir_z, tol_dist,
 * tol_angle_deg, expected_branches, notes). */
static size_t read_manifest(manifest_case *cases, size_t capacity)
{
    FILE *f = fopen(pc_test_data_path("cases/MANIFEST.tsv"), "r");
    if (f == NULL)
        return 0;
    char line[2048];
    size_t n = 0;
    while (n < capacity && fgets(line, sizeof line, f) != NULL) {
        if (line[0] == '#')
            continue;
        char mode[32];
        double tol_d, tol_a;
        manifest_case c;
        if (sscanf(line, "%95s %31s %lf %lf %lf %lf %lf %ld", c.name, mode, &c.dir[0], &c.dir[1],
                   &c.dir[2], &tol_d, &tol_a, &c.expected_branches) == 8 &&
            (strcmp(mode, "directional") == 0 || strcmp(mode, "orthogonal") == 0)) {
            c.orthogonal = strcmp(mode, "orthogonal") == 0;
            cases[n++] = c;
        }
    }
    fclose(f);
    return n;
}

static void check_case(const manifest_case *c, const projcurve_surface *s,
                       const projcurve_curve *curve, double rel_eps, double angle,
                       int pcurve_degree)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, rel_eps * s->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, angle));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, pcurve_degree));
    projcurve_result *r = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const projcurve_status st = c->orthogonal
                                    ? projcurve_project_orthogonal(ctx, s, curve, o, &r)
                                    : projcurve_project_directional(ctx, s, curve, c->dir, o, &r);
    CHECK_OK(st);
    if (st != PROJCURVE_OK) {
        fprintf(stderr, "%s: %s\n", c->name, projcurve_context_message(ctx));
        projcurve_context_destroy(ctx);
        projcurve_options_destroy(o);
        return;
    }
    CHECK((long)r->n_branches == c->expected_branches);
    pc_oracle_dir d;
    pc_projector proj;
    if (c->orthogonal)
        pc_oracle_projector_orthogonal(s, curve, &proj);
    else
        pc_oracle_projector(s, curve, c->dir, &d, &proj);
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, &s->grid, &sum);
    CHECK(sum.branches_without_pieces == 0);
    CHECK(sum.failures == 0);
    CHECK(sum.loose_points == 0); /* the oracle's exact points to 1e-12 of the size */
    CHECK(sum.worst.hausdorff <= rel_eps * s->size);
    CHECK(sum.worst.max_angle <= angle * (1.0 + 1e-9));
    CHECK(sum.worst.max_gap <= 1e-12 * s->size);
    CHECK(sum.worst.max_end_err <= 1e-9 * s->size);
    CHECK(sum.worst.off_patch == 0);
    const double off_surface = pc_on_surface_check(c->name, r, s, pcurve_degree);
    const size_t pieces = sum.pieces;
    const double worst = sum.worst.hausdorff / (rel_eps * s->size);
    const double worst_angle = sum.worst.max_angle;
    printf("%-28s pcurve %d eps_D %.0e eps_T %4.1f: %zu branches, %5zu pieces, Hausdorff "
           "%.2f eps_D, joints <= %.3f deg, on S to %.1e size\n",
           c->name, pcurve_degree, rel_eps, angle, r->n_branches, pieces, worst, worst_angle,
           off_surface);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
}

int main(void)
{
    manifest_case cases[MAX_CASES];
    const size_t n = read_manifest(cases, MAX_CASES);
    if (n == 0)
        pc_test_missing_data("cases/MANIFEST.tsv");
    static const double rel_eps[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    static const int pcurve_degrees[] = {1, 3};
    for (size_t k = 0; k < n; ++k) {
        char rel[NAME_LEN + 16];
        snprintf(rel, sizeof rel, "cases/%.*s.igs", NAME_LEN - 1, cases[k].name);
        projcurve_model *model = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(rel), &model));
        const projcurve_surface *s = projcurve_model_surface(model, 0);
        const projcurve_curve *curve = projcurve_model_curve(model, 0);
        CHECK(s != NULL && curve != NULL);
        for (size_t m = 0; m < 2 && s != NULL && curve != NULL; ++m) {
            for (size_t e = 0; e < sizeof rel_eps / sizeof rel_eps[0]; ++e)
                check_case(&cases[k], s, curve, rel_eps[e], 1.0, pcurve_degrees[m]);
            check_case(&cases[k], s, curve, 1e-3, 10.0, pcurve_degrees[m]);
        }
        projcurve_model_destroy(model);
    }
    return pc_test_finish("test_refine_cases");
}
