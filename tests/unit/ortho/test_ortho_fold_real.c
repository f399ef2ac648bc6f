/*
 * Orthogonal projection onto a surface that folds onto itself:
 * linkrods.step surface 11 (rational 6 x 8), whose v lines reverse at
 * v ~ -0.0124 and v ~ -0.0225 (Sv turns by ~177 deg within 2e-3 of v, the
 * two sheets 7e-6 apart in space, |Sv| down to 2e-3 of |Su|). Curve 0 lies
 * ~3.7 away; many of its foot points sit on the fold edges, where the
 * normal flips, so a point 1e-7 from the exact foot of P(t) has a normal
 * line missing P(t) by ~1e3 eps_D.
 *
 * The real-data sweep's verifier (support/sweep_verify.c) picked t* by that
 * normal line and searched the exact point only around t*: it reported 27
 * of 2637 samples "far" (up to 19.8 eps_D) that are within 1e-4 eps_D of
 * the exact projection. Checked here: (1) the verifier accepts the result;
 * (2) an independent brute force agrees: for samples on the folds (|Sv| <
 * FOLD_SV_REL |Su|), the distance to the nearest foot point of P(t) over t
 * in the piece's range widened by half, each foot found by a pattern search
 * of the distance on (u, v) grids from the sample (no Newton, no normal).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "on_surface.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define SURFACE 11
#define CURVE 0
/* A sample is on a fold where |Sv| < FOLD_SV_REL |Su| (1 away from the
 * folds |Sv| ~ |Su|; at the fold edges 2e-3). */
#define FOLD_SV_REL 0.05
/* Samples brute-forced (strided over the fold samples; each costs ~0.1 s). */
#define MAX_BRUTE 12
#define T_SCAN 16
#define GOLDEN_ITER 40
/* Pattern search: a 9 x 9 grid, from 1e-3 of the domain down to 1e-15. */
#define GRID 8
#define SEARCH_MOVES 4000

typedef struct brute {
    const projcurve_surface *s;
    const projcurve_curve *c;
    double dom[4];
} brute;

static double d2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

/* The local minimum of |S - P(t)| reached from uv0 by pattern search: move
 * to the grid's minimum while it lies on the grid's border, zoom in when
 * inside. Returns its distance to x, HUGE_VAL when the search leaves the
 * domain (no interior minimum there) or does not settle in SEARCH_MOVES. */
static double foot_distance(const brute *b, double t, const double uv0[2], const double x[3])
{
    double p[3], c[2] = {uv0[0], uv0[1]}, foot[3] = {0, 0, 0}, best = HUGE_VAL;
    projcurve_curve_eval(NULL, b->c, t, 0, p);
    double hu = 1e-3 * (b->dom[1] - b->dom[0]), hv = 1e-3 * (b->dom[3] - b->dom[2]);
    for (int it = 0; it < SEARCH_MOVES; ++it) {
        if (hu < 1e-15 * (b->dom[1] - b->dom[0]))
            return sqrt(d2(foot, x));
        int bi = GRID / 2, bj = GRID / 2;
        double bc[2] = {c[0], c[1]};
        for (int i = 0; i <= GRID; ++i)
            for (int j = 0; j <= GRID; ++j) {
                const double u = fmin(fmax(c[0] - hu + 2 * hu * i / GRID, b->dom[0]), b->dom[1]);
                const double v = fmin(fmax(c[1] - hv + 2 * hv * j / GRID, b->dom[2]), b->dom[3]);
                double q[3];
                projcurve_surface_eval(NULL, b->s, u, v, 0, q);
                if (d2(q, p) < best)
                    best = d2(q, p), bc[0] = u, bc[1] = v, bi = i, bj = j, memcpy(foot, q, sizeof q);
            }
        const int border = bi == 0 || bi == GRID || bj == 0 || bj == GRID;
        if (border && (bc[0] == b->dom[0] || bc[0] == b->dom[1] || bc[1] == b->dom[2] ||
                       bc[1] == b->dom[3]))
            return HUGE_VAL;
        c[0] = bc[0], c[1] = bc[1];
        if (!border)
            hu *= 2.0 / GRID, hv *= 2.0 / GRID;
    }
    return HUGE_VAL;
}

/* min over t in [lo, hi] of foot_distance: a scan, then golden section
 * around its best point. */
static double brute_distance(const brute *b, const double uv[2], const double x[3], double lo,
                             double hi)
{
    double best = HUGE_VAL, bt = lo;
    for (int k = 0; k <= T_SCAN; ++k) {
        const double t = lo + (hi - lo) * k / T_SCAN, d = foot_distance(b, t, uv, x);
        if (d < best)
            best = d, bt = t;
    }
    double a = fmax(lo, bt - (hi - lo) / T_SCAN), e = fmin(hi, bt + (hi - lo) / T_SCAN);
    for (int k = 0; k < GOLDEN_ITER; ++k) {
        const double c = e - 0.618 * (e - a), d = a + 0.618 * (e - a);
        const double fc = foot_distance(b, c, uv, x), fd = foot_distance(b, d, uv, x);
        best = fmin(best, fmin(fc, fd));
        if (fc <= fd)
            e = d;
        else
            a = c;
    }
    return best;
}

static int on_fold(const projcurve_surface *s, const double uv[2])
{
    double f[9];
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 1, f);
    const double su2 = f[3] * f[3] + f[4] * f[4] + f[5] * f[5];
    const double sv2 = f[6] * f[6] + f[7] * f[7] + f[8] * f[8];
    return sv2 < FOLD_SV_REL * FOLD_SV_REL * su2;
}

/* The brute force over the fold samples of every piece (8 intervals). */
static void check_brute(const brute *b, const projcurve_result *r, double eps_d)
{
    size_t fold = 0, checked = 0;
    double worst = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
        size_t seen = 0;
        const size_t stride = pass == 0 ? 1 : (fold + MAX_BRUTE - 1) / MAX_BRUTE;
        for (size_t br = 0; br < projcurve_result_branch_count(r); ++br) {
            size_t n = 0;
            projcurve_result_branch_info(NULL, r, br, NULL, NULL, NULL, NULL, &n);
            for (size_t k = 0; k < n; ++k) {
                int deg = 0, uv_deg = 0;
                double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
                double range[2], uvc[2 * PROJCURVE_MAX_PCURVE_POINTS];
                projcurve_result_piece(NULL, r, br, k, &deg, ctrl, w, range, NULL);
                projcurve_result_piece_pcurve(NULL, r, br, k, &uv_deg, uvc);
                for (int i = 0; i <= 8; ++i) {
                    const double sp = i / 8.0;
                    double x[3], uv[2] = {0, 0}, bern = 1.0;
                    pc_test_piece_point(deg, ctrl, w, sp, x);
                    for (int j = 0; j <= uv_deg; ++j) { /* the pcurve, cubic or linear */
                        bern = (uv_deg == 3 ? (j == 0 || j == 3 ? 1.0 : 3.0) : 1.0) *
                               pow(sp, j) * pow(1.0 - sp, uv_deg - j);
                        uv[0] += bern * uvc[2 * j], uv[1] += bern * uvc[2 * j + 1];
                    }
                    if (!on_fold(b->s, uv))
                        continue;
                    if (pass == 0) {
                        ++fold;
                        continue;
                    }
                    if (seen++ % stride != 0)
                        continue;
                    const double pad = 0.5 * (range[1] - range[0]);
                    const double d = brute_distance(b, uv, x, range[0] - pad, range[1] + pad);
                    worst = fmax(worst, d);
                    ++checked;
                }
            }
        }
    }
    printf("brute force: %zu of the samples on the folds, %zu checked, worst distance to the "
           "exact projection %.3g eps_D\n",
           fold, checked, worst / eps_d);
    CHECK(checked >= MAX_BRUTE / 2);
    /* The library promises eps_D; the samples measure ~1e-4 of it. */
    CHECK(worst <= eps_d);
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    brute b = {projcurve_model_surface(m, SURFACE), projcurve_model_curve(m, CURVE), {0}};
    projcurve_surface_domain(NULL, b.s, b.dom);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, b.s, b.c, NULL, &r));
    double eps_d = 0.0, box[6];
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    projcurve_surface_bounds(NULL, b.s, box);
    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, b.s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    /* The sweep's mesh: 8 cells per span, 48 to 256 per side. */
    const int cu = pc_sweep_mesh_cells(su);
    const int cv = pc_sweep_mesh_cells(sv);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)b.s, b.dom, cu, cv));
    const pc_sweep_input in = {b.s, b.c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(d2(box, box + 3)),
                               2.0 * eps_d, 32, 40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("sweep verifier: %zu samples, far %zu, off the projection %zu, worst %.3g eps_D\n",
           rep.samples, rep.far_from_exact, rep.off_projection, rep.worst_exact);
    CHECK(rep.samples > 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.off_projection == 0);
    check_brute(&b, r, eps_d);
    pc_oracle_mesh_free(&mesh);
    projcurve_result_destroy(r);
    projcurve_model_destroy(m);
    return pc_test_finish("test_ortho_fold_real");
}
