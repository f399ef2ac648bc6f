/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The pleat of linkrods.step surface 11 (tests/unit/trace/
 * test_trace_pleat_real.c: its v lines fold back on themselves, three
 * layers 1e-5 to 1e-4 apart, born and gone at cusps of the
 * parametrisation) seen from an eye point: curves 78 and 79 projected from
 * an eye above the curve's centre, far (1e3 model sizes: the rays within
 * 1e-3 rad of (0, 0, -1)) and nearer (30 sizes: rays fanning out by up to
 * ~0.02 rad, the pleats met at other t). As the directional projection
 * along (0, 0, -1), each layer is a branch ending on the cusps where it
 * meets the next (docs/tracing.md, "Pleats"; docs/conical.md): no branch
 * starts or ends FAILED, no failure is counted, and at t inside the
 * pleats as many branches are alive as the ray meets layers. (Before the
 * conical projector told the tracer where cusps are: 9 and 10 branches,
 * 8 and 9 failures, hits up to 28 eps_D from the result. Eyes nearer than ~10
 * sizes still leave the middle layer of a pleat shorter in t than two
 * sweep steps untraced, and eyes 1e4 sizes and more up fail along the
 * surface's vertical edge, which the curve runs on: docs/conical.md.)
 *
 * Independent checks (public API and the test's ray oracle only): every
 * traced vertex on its ray, in front of the curve; at evenly spaced t
 * every hit of the ray with the sweep's mesh of S within eps_D of the
 * pieces; the layers counted on a fine mesh of the pleat's band (as
 * test_trace_pleat_real, which says why the band).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "conical_check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define SURFACE 11
/* t samples of the completeness check; fewer in the slow builds */
#define SAMPLES (256 / PC_TEST_SLOWDOWN > 32 ? 256 / PC_TEST_SLOWDOWN : 32)
/* Vertices on their rays to the corrector's tolerance (1e-12 of the size)
 * and rounding (as test_conical_sweep). */
#define VERTEX_TOL_REL 1e-10

typedef struct pleat_setup {
    const projcurve_model *model;
    const pc_oracle_mesh *mesh, *band;
    double size;
} pleat_setup;

/* The unit ray from eye through P(t) into d, P(t) into p. */
static void ray_at(const projcurve_curve *c, const double eye[3], double t, double p[3],
                   double d[3])
{
    CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
    double len = 0.0;
    for (int i = 0; i < 3; ++i) {
        d[i] = p[i] - eye[i];
        len += d[i] * d[i];
    }
    for (int i = 0; i < 3; ++i)
        d[i] /= sqrt(len);
}

/* Hits of the ray of t on mesh that a projection must return: in front of
 * the curve by more than lambda_min and not grazing (as the sweep's
 * verifier counts them; the curve also runs along the surface's edge v1,
 * where S is vertical). Their points into x (up to 32). */
static size_t required_hits(const pc_oracle_mesh *mesh, const projcurve_surface *s,
                            const double p[3], const double d[3], double lambda_min,
                            double x[32][3])
{
    pc_oracle_hit hits[32];
    const size_t n_all = pc_oracle_line_hits(mesh, p, d, 1, hits, 32);
    const double grazing = sin(PC_VERIFY_GRAZING_DEG * 3.14159265358979323846 / 180.0);
    size_t n = 0;
    for (size_t i = 0; i < n_all && i < 32; ++i) {
        if (hits[i].lambda < lambda_min || !(hits[i].cos_dir >= grazing))
            continue;
        CHECK_OK(projcurve_surface_eval(NULL, s, hits[i].u, hits[i].v, 0, x[n]));
        ++n;
    }
    return n;
}

/* The branches of r alive at t whose point there (S at (u, v)
 * interpolated between the two vertices around t) is a hit that
 * required_hits would count: in front of the curve by more than
 * lambda_min, not grazing. (The curve runs on the surface's edge v1: a
 * branch there has lambda ~ 0, and neither counts it.) */
static size_t alive_at(const projcurve_result *r, const projcurve_surface *s, double t,
                       const double p[3], const double d[3], double lambda_min)
{
    const double grazing = sin(PC_VERIFY_GRAZING_DEG * 3.14159265358979323846 / 180.0);
    size_t alive = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        double range[2];
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, NULL, NULL, &n, NULL));
        if (!(range[0] <= t && t <= range[1]) || n < 2)
            continue;
        double *v = malloc(3 * n * sizeof *v);
        CHECK(v != NULL);
        if (v == NULL)
            return alive;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, v, &n));
        size_t k = 1;
        while (k + 1 < n && v[3 * k] < t)
            ++k;
        const double a = v[3 * k] > v[3 * (k - 1)]
                             ? (t - v[3 * (k - 1)]) / (v[3 * k] - v[3 * (k - 1)]) : 0.0;
        const double u = v[3 * (k - 1) + 1] + a * (v[3 * k + 1] - v[3 * (k - 1) + 1]);
        const double w = v[3 * (k - 1) + 2] + a * (v[3 * k + 2] - v[3 * (k - 1) + 2]);
        free(v);
        double f[9];
        CHECK_OK(projcurve_surface_eval(NULL, s, u, w, 1, f));
        const double nrm[3] = {f[4] * f[8] - f[5] * f[7], f[5] * f[6] - f[3] * f[8],
                               f[3] * f[7] - f[4] * f[6]};
        const double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        double lambda = 0.0, cosine = 0.0;
        for (int i = 0; i < 3; ++i) {
            lambda += (f[i] - p[i]) * d[i];
            cosine += nrm[i] * d[i];
        }
        alive += lambda >= lambda_min && len > 0.0 && fabs(cosine) / len >= grazing;
    }
    return alive;
}

/* Projects curve from eye and checks it; returns the number of t at which
 * the band's rays meet three layers (so the caller knows the pleats were
 * crossed). */
static int check_eye(const pleat_setup *ps, size_t curve, const double eye[3], const char *name)
{
    const projcurve_surface *s = projcurve_model_surface(ps->model, SURFACE);
    const projcurve_curve *c = projcurve_model_curve(ps->model, curve);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, s, c, eye, NULL, &r));
    double eps_d = 0.0, t0 = 0.0, t1 = 1.0;
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    projcurve_curve_domain(NULL, c, &t0, &t1);
    const size_t failures = projcurve_result_failure_count(r);
    const size_t nb = projcurve_result_branch_count(r);

    /* soundness: vertices on their rays, in front of the curve */
    double min_lambda = 0.0;
    const double residual = cc_vertex_ray_residual(r, s, c, eye, &min_lambda);
    CHECK(residual <= VERTEX_TOL_REL * ps->size);
    CHECK(min_lambda >= -eps_d);
    size_t failed_ends = 0;
    for (size_t b = 0; b < nb; ++b) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, &start, &end, NULL, NULL));
        failed_ends += start == PROJCURVE_START_FAILED;
        failed_ends += end == PROJCURVE_END_FAILED;
    }

    /* completeness: every required hit of the sweep's mesh covered; the
     * layer count of the band against the branches alive */
    cc_pieces pieces;
    CHECK(cc_pieces_sample(r, &pieces));
    size_t required = 0, missed = 0, mismatched = 0;
    int three = 0;
    double worst = 0.0;
    for (int k = 0; k <= SAMPLES; ++k) {
        const double t = t0 + (t1 - t0) * k / SAMPLES;
        double p[3], d[3], x[32][3];
        ray_at(c, eye, t, p, d);
        const size_t n = required_hits(ps->mesh, s, p, d, 2.0 * eps_d, x);
        for (size_t i = 0; i < n; ++i) {
            const double dist = cc_pieces_dist(&pieces, x[i]);
            worst = fmax(worst, dist / eps_d);
            missed += !(dist <= eps_d);
        }
        required += n;
        const size_t layers = required_hits(ps->band, s, p, d, 2.0 * eps_d, x);
        const size_t alive = alive_at(r, s, t, p, d, 2.0 * eps_d);
        three += layers == 3;
        if (layers > 1 && alive != layers) {
            if (mismatched++ == 0)
                printf("  %s curve %zu, t %.4f: %zu layers, %zu branches alive\n", name, curve,
                       t, layers, alive);
        }
    }
    printf("%s, curve %zu: %zu branches, %zu failures, %zu failed ends; vertex residual "
           "%.2g size, min lambda %.3g; %zu hits required, %zu missed (worst %.3g eps_D); "
           "%d t with 3 layers, %zu with a wrong count alive\n",
           name, curve, nb, failures, failed_ends, residual / ps->size, min_lambda, required,
           missed, worst, three, mismatched);
    CHECK(required > 0);
    CHECK(missed == 0);
    CHECK(failures == 0);
    CHECK(failed_ends == 0);
    CHECK(mismatched == 0);
    cc_pieces_free(&pieces);
    projcurve_result_destroy(r);
    return three;
}

/* The centre of the curve's box (its points at 64 t). */
static void curve_centre(const projcurve_curve *c, double centre[3])
{
    double t0 = 0.0, t1 = 1.0, lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    projcurve_curve_domain(NULL, c, &t0, &t1);
    for (int k = 0; k <= 64; ++k) {
        double p[3];
        CHECK_OK(projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * k / 64, 0, p));
        for (int i = 0; i < 3; ++i) {
            lo[i] = fmin(lo[i], p[i]);
            hi[i] = fmax(hi[i], p[i]);
        }
    }
    for (int i = 0; i < 3; ++i)
        centre[i] = 0.5 * (lo[i] + hi[i]);
}

int main(void)
{
    pc_test_hang_guard(60);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    double dom[4], box[6];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    pc_oracle_mesh mesh, band;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom,
                               pc_sweep_mesh_cells(su), pc_sweep_mesh_cells(sv)));
    const double band_dom[4] = {dom[0], dom[1], -0.04, dom[3]};
    CHECK(pc_oracle_mesh_build(&band, pc_sweep_surface_eval, (void *)s, band_dom, 256, 256));
    double diag = 0.0;
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    const pleat_setup ps = {m, &mesh, &band, sqrt(diag)};
    static const size_t curves[] = {78, 79};
    static const struct { const char *name; double height; } eyes[] = {
        {"far eye", 1e3}, {"near eye", 30.0}};
    for (size_t k = 0; k < 2; ++k) {
        double eye[3];
        curve_centre(projcurve_model_curve(m, curves[k]), eye);
        for (size_t e = 0; e < 2; ++e) {
            const double at[3] = {eye[0], eye[1], eye[2] + eyes[e].height * ps.size};
            /* both eyes see the pleats: rays meeting three layers */
            CHECK(check_eye(&ps, curves[k], at, eyes[e].name) > 0);
        }
    }
    pc_oracle_mesh_free(&band);
    pc_oracle_mesh_free(&mesh);
    projcurve_model_destroy(m);
    return pc_test_finish("test_conical_pleat_real");
}
