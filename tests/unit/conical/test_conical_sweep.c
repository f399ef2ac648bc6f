/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * No missed branch, by brute force: the conical projection of the test
 * curves of the bumpy cases of tests/data/cases from eyes behind the
 * curve (seen along the cases' directions, at two distances: the nearer
 * the eye, the more the rays fan out) must come within eps_D of every hit
 * that projcurve_surface_intersect_line finds on the rays of 1,500 evenly
 * spaced t; every traced vertex lies on its ray, in front of the curve.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "conical_check.h"

/* t samples of the brute force (the directional case test takes 10,000;
 * here 1,500 per eye keeps the test within a second). */
#define N_SAMPLES 1500
/* Hits where the ray is within this angle of the tangent plane are not
 * required (as the directional sweep's PC_VERIFY_GRAZING_DEG): the branch
 * ends at the fold there and the exact point is ill-conditioned. */
#define GRAZING_DEG 2.0
/* Vertices on their rays to the corrector's tolerance (1e-12 of the size)
 * and rounding. */
#define VERTEX_TOL_REL 1e-10

typedef struct sweep_case {
    const char *name;
    double dir[3];   /* the case's projection direction */
} sweep_case;

static const sweep_case CASES[] = {
    {"bumpy_bicubic_8x8_down", {0.0, 0.0, -1.0}},
    {"bumpy_boundary_exit_reenter", {0.0, 0.0, -1.0}},
    {"deg5_quintic_9x8_down", {0.0, 0.0, -1.0}},
    {"fold_c_sheet_jump", {0.0, 0.0, -1.0}},
};

/* 1 when the ray d meets S at (u, v) within GRAZING_DEG of its tangent plane. */
static int grazing(const projcurve_surface *s, double u, double v, const double d[3])
{
    double f[9];
    if (projcurve_surface_eval(NULL, s, u, v, 1, f) != PROJCURVE_OK)
        return 1;
    const double n[3] = {f[4] * f[8] - f[5] * f[7], f[5] * f[6] - f[3] * f[8],
                         f[3] * f[7] - f[4] * f[6]};
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double sine = len > 0.0 ? fabs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / len : 0.0;
    return sine < sin(GRAZING_DEG * 3.14159265358979323846 / 180.0);
}

/* The brute force over t: returns the largest distance of a required hit
 * from the pieces, in units of eps_d. */
static double sweep(const projcurve_surface *s, const projcurve_curve *c, const double eye[3],
                    const cc_pieces *pieces, double eps_d, size_t *required,
                    size_t *excluded)
{
    double t0 = 0.0, t1 = 1.0, worst = 0.0;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    for (int k = 0; k <= N_SAMPLES; ++k) {
        const double t = t0 + (t1 - t0) * k / N_SAMPLES;
        double p[3], d[3], len = 0.0;
        projcurve_curve_eval(NULL, c, t, 0, p);
        for (int i = 0; i < 3; ++i) {
            d[i] = p[i] - eye[i];
            len += d[i] * d[i];
        }
        len = sqrt(len);
        for (int i = 0; i < 3; ++i)
            d[i] /= len;
        double hits[3 * 16];
        unsigned flags[16];
        size_t n = 0;
        CHECK_OK(projcurve_surface_intersect_line(NULL, s, p, d, 1, 16, hits, flags, &n));
        for (size_t j = 0; j < n && j < 16; ++j) {
            if ((flags[j] & PROJCURVE_HIT_TANGENT) || grazing(s, hits[3 * j], hits[3 * j + 1], d)) {
                ++*excluded;
                continue;
            }
            const double lambda = hits[3 * j + 2];
            const double x[3] = {p[0] + lambda * d[0], p[1] + lambda * d[1],
                                 p[2] + lambda * d[2]};
            const double gap = cc_pieces_dist(pieces, x) / eps_d;
            if (gap > worst && gap > 1.0)
                printf("  missed at t = %.9g: hit %zu (lambda %.6g) %.3g eps_D away\n", t, j,
                       lambda, gap);
            worst = fmax(worst, gap);
            ++*required;
        }
    }
    return worst;
}

static void run_eye(const char *name, const projcurve_surface *s, const projcurve_curve *c,
                    const double eye[3], double size)
{
    const double eps_d = 1e-4 * size; /* the automatic default */
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, s, c, eye, NULL, &r));
    if (r == NULL)
        return;
    CHECK(projcurve_result_failure_count(r) == 0);
    double min_lambda;
    const double res = cc_vertex_ray_residual(r, s, c, eye, &min_lambda);
    size_t required = 0, excluded = 0;
    cc_pieces pieces;
    CHECK(cc_pieces_sample(r, &pieces));
    const double worst = sweep(s, c, eye, &pieces, eps_d, &required, &excluded);
    cc_pieces_free(&pieces);
    printf("%s, eye (%.4g, %.4g, %.4g): %zu branches, ray residual %.3g, min lambda %.3g; "
           "%zu hits required, %zu grazing, farthest %.3g eps_D\n",
           name, eye[0], eye[1], eye[2], projcurve_result_branch_count(r), res / size,
           min_lambda, required, excluded, worst);
    CHECK(res <= VERTEX_TOL_REL * size);
    CHECK(min_lambda >= -eps_d);
    CHECK(required > 0);
    /* the pieces lie within eps_D of the exact projection; sampled as
     * polylines of 16 chords they may add a sagitta far below 1 % */
    CHECK(worst <= 1.01);
    projcurve_result_destroy(r);
}

static void run_case(const sweep_case *sc)
{
    char rel[256];
    snprintf(rel, sizeof rel, "cases/%s.igs", sc->name);
    projcurve_model *m = NULL;
    const projcurve_status st = projcurve_model_read_file(NULL, pc_test_data_path(rel), &m);
    CHECK_OK(st);
    if (st != PROJCURVE_OK)
        return;
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    for (size_t i = 0; i < projcurve_model_curve_count(m); ++i) {
        const projcurve_curve *c = projcurve_model_curve(m, i);
        double t0 = 0.0, t1 = 1.0, mid[3];
        projcurve_curve_domain(NULL, c, &t0, &t1);
        projcurve_curve_eval(NULL, c, 0.5 * (t0 + t1), 0, mid);
        /* behind the curve's middle along -dir, far (rays nearly
         * parallel) and near (half the surface's size: fanned out) */
        const double far = 2.0 * size, near = 0.5 * size;
        const double e_far[3] = {mid[0] - far * sc->dir[0], mid[1] - far * sc->dir[1],
                                 mid[2] - far * sc->dir[2]};
        const double e_near[3] = {mid[0] - near * sc->dir[0], mid[1] - near * sc->dir[1],
                                  mid[2] - near * sc->dir[2]};
        run_eye(sc->name, s, c, e_far, size);
        run_eye(sc->name, s, c, e_near, size);
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    for (size_t k = 0; k < sizeof CASES / sizeof CASES[0]; ++k)
        run_case(&CASES[k]);
    return pc_test_finish("test_conical_sweep");
}
