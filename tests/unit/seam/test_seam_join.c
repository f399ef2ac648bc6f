/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Branches across the seams and through the poles of closed NURBS surfaces
 * (seam/): a full cylinder, a sphere and a torus (tests/support/shapes.c,
 * exact rational NURBS: u = 0 and u = 1 on the half-plane y = 0, x > 0;
 * the torus's v = 0 and v = 1 on its outer equator; the sphere's poles on
 * its edges v = 0, v = 1). Lines whose projections cross them give one
 * branch per continuous curve, with the jumps recorded at the analytic
 * parameters; the tracer's own output (join_seams 0) has one more branch
 * per jump. Oracles are analytic: every vertex on the implicit surface and
 * on its ray (directional) or its normal (orthogonal); the compact pcurve,
 * unwrapped by the recorded jumps, and the compact 3D curve within eps_D
 * of the closed-form projection.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "api/project.h"
#include "check.h"
#include "directional/directional_project.h"
#include "geom/surface.h"
#include "ortho/ortho_project.h"
#include "seam/seam.h"
#include "shapes.h"

/* Vertices are exact points: the corrector's 1e-12 of the size, checked
 * at 1e-9 (far above rounding, far below any wrong point). */
#define POINT_TOL 1e-9
/* The jumps' t: the boundary exits are located to ~1e-12 in t on these
 * unit-speed lines; 1e-8 leaves room for the snap to the edge. */
#define JUMP_T_TOL 1e-8
/* A jump across a seam is the period to the edge snap (1e-12 of the
 * width); at a pole the u of the collapsed edge is ill-determined (S does
 * not move with it): the branch arrives with the u of its last steps,
 * 4.5e-5 from the meridian's here. */
#define SEAM_JUMP_TOL 1e-8
#define POLE_JUMP_TOL 1e-4

typedef enum shape_kind { CYLINDER, SPHERE, TORUS } shape_kind;
#define TORUS_R 2.0
#define TORUS_r 0.5

/* The implicit function of the shape and its gradient at x. */
static double implicit_at(shape_kind k, const double x[3], double grad[3])
{
    const double rho = sqrt(x[0] * x[0] + x[1] * x[1]);
    switch (k) {
    case CYLINDER:
        grad[0] = 2 * x[0], grad[1] = 2 * x[1], grad[2] = 0;
        return x[0] * x[0] + x[1] * x[1] - 1.0;
    case SPHERE:
        grad[0] = 2 * x[0], grad[1] = 2 * x[1], grad[2] = 2 * x[2];
        return x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1.0;
    default:
        grad[0] = 2 * (rho - TORUS_R) * x[0] / rho;
        grad[1] = 2 * (rho - TORUS_R) * x[1] / rho;
        grad[2] = 2 * x[2];
        return (rho - TORUS_R) * (rho - TORUS_R) + x[2] * x[2] - TORUS_r * TORUS_r;
    }
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

typedef struct scenario {
    const char *name;
    shape_kind shape;
    double p0[3], p1[3];   /* the line P(t) = p0 + t (p1 - p0), t in [0, 1] */
    int orthogonal;
    double dir[3];         /* directional */
    size_t branches;       /* expected, joined */
    size_t jumps;          /* expected in all */
    /* the jumps of the first branch whose count is n_first: t, du, dv */
    size_t n_first;
    double first[2][3];
    double jump_tol;       /* of du, dv */
} scenario;

static projcurve_surface *make_surface(shape_kind k)
{
    const double o[3] = {0, 0, 0};
    pc_shape_surface s = k == CYLINDER ? pc_shape_cylinder(1.0, 2.0)
                         : k == SPHERE ? pc_shape_sphere(o, 1.0)
                                       : pc_shape_torus(TORUS_R, TORUS_r);
    projcurve_surface *h = pc_shape_surface_create(&s);
    pc_shape_surface_free(&s);
    return h;
}

static projcurve_curve *make_line(const scenario *sc)
{
    const double ctrl[6] = {sc->p0[0], sc->p0[1], sc->p0[2], sc->p1[0], sc->p1[1], sc->p1[2]};
    const double knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

static projcurve_result *project(projcurve_context *ctx, const scenario *sc,
                                 const projcurve_surface *s, const projcurve_curve *c, int join,
                                 int degree)
{
    pc_params p;
    pc_budget budget;
    CHECK_OK(pc_projection_params(ctx, NULL, s->size, &budget, &p));
    p.join_seams = join;
    p.pcurve_degree = degree; /* 1 or 3: every scenario runs in both */
    projcurve_result *r = NULL;
    const double n = norm3(sc->dir);
    const pc_vec3 d = {sc->dir[0] / (n > 0 ? n : 1), sc->dir[1] / (n > 0 ? n : 1),
                       sc->dir[2] / (n > 0 ? n : 1)};
    CHECK_OK(sc->orthogonal ? pc_ortho_project(ctx, s, c, &p, &r)
                            : pc_directional_project(ctx, s, c, d, &p, &r));
    return r;
}

/* The point of S at (u, v) lies on the shape and on its ray or normal. */
static void check_vertex(projcurve_context *ctx, const scenario *sc, const projcurve_surface *s,
                         const projcurve_curve *c, double t, const double uv[2])
{
    double x[3], p[3], g[3], d[3], cr[3];
    CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, x));
    CHECK_OK(projcurve_curve_eval(ctx, c, t, 0, p));
    CHECK_NEAR(implicit_at(sc->shape, x, g), 0.0, POINT_TOL);
    for (int k = 0; k < 3; ++k)
        d[k] = x[k] - p[k];
    if (sc->orthogonal) {
        cross3(d, g, cr);
        CHECK(norm3(cr) <= POINT_TOL * norm3(g));
    } else {
        cross3(d, sc->dir, cr);
        CHECK(norm3(cr) <= POINT_TOL * norm3(sc->dir));
    }
}

/* The (u, v) of S at t from the compact pcurve: its unwrapped value plus
 * the jumps at or before t. */
static void wrapped_uv(projcurve_context *ctx, const projcurve_result *r, size_t b,
                       const projcurve_curve *pcurve, double t, double uv[2])
{
    double q[3];
    CHECK_OK(projcurve_curve_eval(ctx, pcurve, t, 0, q));
    uv[0] = q[0];
    uv[1] = q[1];
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_seam_count(ctx, r, b, &n));
    for (size_t k = 0; k < n; ++k) {
        double tk, du, dv;
        CHECK_OK(projcurve_result_branch_seam(ctx, r, b, k, &tk, &du, &dv));
        if (tk <= t) {
            uv[0] += du;
            uv[1] += dv;
        }
    }
    /* the unwrapped spline's rounding may leave the domain by ~1e-15: the
     * evaluation clamps, as the library's own evaluators do */
    uv[0] = fmin(fmax(uv[0], 0.0), 1.0);
    uv[1] = fmin(fmax(uv[1], 0.0), 1.0);
}

/* The compact forms against the exact projection (the vertex oracle at
 * 101 t): S o pcurve is an exact point of S near the projection, the 3D
 * curve within eps_D of S o pcurve's exact counterpart. */
static void check_compact(projcurve_context *ctx, const scenario *sc, const projcurve_surface *s,
                          const projcurve_curve *c, const projcurve_result *r, size_t b,
                          double eps_d)
{
    projcurve_curve *pq = NULL, *c3 = NULL;
    CHECK_OK(projcurve_result_branch_compact_pcurve(ctx, r, b, &pq));
    CHECK_OK(projcurve_result_branch_compact_curve(ctx, r, b, &c3));
    if (pq == NULL || c3 == NULL)
        return;
    double range[2];
    CHECK_OK(projcurve_result_branch_info(ctx, r, b, range, NULL, NULL, NULL, NULL));
    double worst_q = 0.0, worst_c = 0.0;
    for (int i = 0; i <= 100; ++i) {
        const double t = range[0] + (range[1] - range[0]) * i / 100.0;
        double uv[2], x[3], p[3], g[3], d[3], cr[3], y[3];
        wrapped_uv(ctx, r, b, pq, t, uv);
        CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, x));
        CHECK_OK(projcurve_curve_eval(ctx, c, t, 0, p));
        for (int k = 0; k < 3; ++k)
            d[k] = x[k] - p[k];
        /* distance of S(q(t)) from its ray / normal line: the projection
         * within eps_D there */
        implicit_at(sc->shape, x, g);
        if (sc->orthogonal)
            cross3(d, g, cr), worst_q = fmax(worst_q, norm3(cr) / norm3(g));
        else
            cross3(d, sc->dir, cr), worst_q = fmax(worst_q, norm3(cr) / norm3(sc->dir));
        CHECK_OK(projcurve_curve_eval(ctx, c3, t, 0, y));
        for (int k = 0; k < 3; ++k)
            d[k] = y[k] - x[k];
        worst_c = fmax(worst_c, norm3(d));
    }
    /* S o q within eps_D of the exact point at t (here: of its line), the
     * 3D curve within eps_D of the exact point, so of S o q within 2 eps_D */
    if (!(worst_q <= eps_d && worst_c <= 2.0 * eps_d))
        fprintf(stderr, "%s branch %zu: compact %.3g, 3D %.3g (eps_D %.3g)\n", sc->name, b,
                worst_q, worst_c, eps_d);
    CHECK(worst_q <= eps_d);
    CHECK(worst_c <= 2.0 * eps_d);
    /* the pieces joined in space: one curve, exactly on S (rounding) */
    projcurve_curve *whole = NULL;
    CHECK_OK(projcurve_result_branch_curve(ctx, r, b, &whole));
    for (int i = 0; whole != NULL && i <= 40; ++i) {
        double x[3], g[3];
        CHECK_OK(projcurve_curve_eval(ctx, whole, range[0] + (range[1] - range[0]) * i / 40.0,
                                      0, x));
        CHECK_NEAR(implicit_at(sc->shape, x, g), 0.0, POINT_TOL);
    }
    projcurve_curve_destroy(whole);
    projcurve_curve_destroy(pq);
    projcurve_curve_destroy(c3);
}

static void run(const scenario *sc, int degree)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_surface *s = make_surface(sc->shape);
    projcurve_curve *c = make_line(sc);
    CHECK(s != NULL && c != NULL);
    if (s == NULL || c == NULL)
        return;
    projcurve_result *joined = project(ctx, sc, s, c, 1, degree);
    projcurve_result *split = project(ctx, sc, s, c, 0, degree);
    CHECK(joined != NULL && split != NULL);
    if (joined == NULL || split == NULL)
        return;
    const size_t nb = projcurve_result_branch_count(joined);
    double eps_d = 0.0;
    CHECK_OK(projcurve_result_stat(ctx, joined, PROJCURVE_STAT_TOL_DISTANCE, &eps_d));
    size_t jumps = 0, first_checked = 0;
    for (size_t b = 0; b < nb; ++b) {
        size_t n = 0, np = 0;
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_seam_count(ctx, joined, b, &n));
        CHECK_OK(projcurve_result_branch_info(ctx, joined, b, NULL, &start, &end, &np, NULL));
        jumps += n;
        CHECK(start != PROJCURVE_START_BOUNDARY && end != PROJCURVE_END_BOUNDARY);
        double *pts = malloc(3 * np * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(ctx, joined, b, np, pts, &np));
        for (size_t i = 0; i < np; ++i)
            check_vertex(ctx, sc, s, c, pts[3 * i], pts + 3 * i + 1);
        free(pts);
        if (n == sc->n_first && !first_checked) {
            first_checked = 1;
            for (size_t k = 0; k < n; ++k) {
                double t, du, dv;
                CHECK_OK(projcurve_result_branch_seam(ctx, joined, b, k, &t, &du, &dv));
                CHECK_NEAR(t, sc->first[k][0], JUMP_T_TOL);
                CHECK_NEAR(du, sc->first[k][1], sc->jump_tol);
                CHECK_NEAR(dv, sc->first[k][2], sc->jump_tol);
            }
        }
        check_compact(ctx, sc, s, c, joined, b, eps_d);
    }
    CHECK(first_checked);
    if (nb != sc->branches || jumps != sc->jumps)
        fprintf(stderr, "%s: %zu branches, %zu jumps\n", sc->name, nb, jumps);
    CHECK(nb == sc->branches);
    CHECK(jumps == sc->jumps);
    /* both IGES forms take the joined branches (unwrapped pcurves) */
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, s, joined));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, w, s, joined));
    projcurve_iges_writer_destroy(w);
    /* the tracer's own output: one more branch per jump */
    CHECK(projcurve_result_branch_count(split) == nb + jumps);
    double t = 0, du = 0, dv = 0;
    CHECK_STATUS(projcurve_result_branch_seam(ctx, joined, 0, 99, &t, &du, &dv),
                 PROJCURVE_ERR_INDEX);
    CHECK_STATUS(projcurve_result_branch_seam_count(ctx, joined, nb, &jumps), PROJCURVE_ERR_INDEX);
    projcurve_result_destroy(joined);
    projcurve_result_destroy(split);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    projcurve_context_destroy(ctx);
}

/* The visible projection of the cylinder (PROJCURVE_OPT_HITS nearest):
 * the front hit alone, still one branch across the seam. */
static void test_nearest_across_seam(void)
{
    const scenario sc = {"cylinder, nearest", CYLINDER, {3, -0.8, 0.5}, {3, 0.8, 1.5}, 0,
                         {-1, 0, 0}, 1, 1, 1, {{0.5, -1, 0}}, SEAM_JUMP_TOL};
    projcurve_surface *s = make_surface(sc.shape);
    projcurve_curve *c = make_line(&sc);
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS, PROJCURVE_HITS_NEAREST));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, sc.dir, o, &r));
    size_t n = 0;
    CHECK(projcurve_result_branch_count(r) == 1);
    CHECK_OK(projcurve_result_branch_seam_count(NULL, r, 0, &n));
    CHECK(n == 1);
    size_t np = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 0, NULL, &np));
    double *pts = malloc(3 * np * sizeof *pts);
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, np, pts, &np));
    for (size_t i = 0; i < np; ++i) {
        double x[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, pts[3 * i + 1], pts[3 * i + 2], 0, x));
        CHECK(x[0] > 0.0); /* the front half */
        check_vertex(NULL, &sc, s, c, pts[3 * i], pts + 3 * i + 1);
    }
    free(pts);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* The closure test on the control net (seam.h). */
static void test_closure(void)
{
    const double tol = 1e-9;
    const struct {
        shape_kind kind;
        int cu, cv;
        unsigned collapsed;
    } want[] = {{CYLINDER, 1, 0, 0},
                {SPHERE, 1, 0, PC_SIDE_V0 | PC_SIDE_V1},
                {TORUS, 1, 1, 0}};
    for (size_t i = 0; i < 3; ++i) {
        projcurve_surface *s = make_surface(want[i].kind);
        pc_closure cl;
        pc_surface_closure(&s->nurbs, tol * s->size, &cl);
        CHECK(cl.closed_u == want[i].cu && cl.closed_v == want[i].cv);
        CHECK(cl.collapsed == want[i].collapsed);
        projcurve_surface_destroy(s);
    }
    /* the plane: open; its seam rows 2 apart */
    pc_shape_surface plane = pc_shape_plane(3, 3, 2, 2);
    projcurve_surface *p = pc_shape_surface_create(&plane);
    pc_closure cl;
    pc_surface_closure(&p->nurbs, tol * p->size, &cl);
    CHECK(!cl.closed_u && !cl.closed_v && cl.collapsed == 0);
    projcurve_surface_destroy(p);
    pc_shape_surface_free(&plane);
    /* a cylinder whose seam rows have the same points but one weight
     * changed: the edge curves differ (weights not proportional) */
    pc_shape_surface cyl = pc_shape_cylinder(1.0, 2.0);
    cyl.weights[9] *= 2.0; /* pole (0, 1): u fastest, 9 per row */
    projcurve_surface *c = pc_shape_surface_create(&cyl);
    pc_surface_closure(&c->nurbs, tol * c->size, &cl);
    CHECK(!cl.closed_u);
    projcurve_surface_destroy(c);
    pc_shape_surface_free(&cyl);
}

int main(void)
{
    test_closure();
    test_nearest_across_seam();
    /* the cylinder along -x: the front hit crosses the seam at y = 0 (from
     * u ~ 1 to u ~ 0), the back one does not */
    const scenario cyl_dir = {"cylinder, directional", CYLINDER, {3, -0.8, 0.5}, {3, 0.8, 1.5},
                              0, {-1, 0, 0}, 2, 1, 1, {{0.5, -1, 0}}, SEAM_JUMP_TOL};
    const scenario cyl_ortho = {"cylinder, orthogonal", CYLINDER, {2, -1, 0.5}, {2, 1, 1.5},
                                1, {0, 0, 0}, 1, 1, 1, {{0.5, -1, 0}}, SEAM_JUMP_TOL};
    /* over the north pole along the meridian plane at angle 1 rad: u jumps
     * by half the period there (u(a + pi) = u(a) + 1/2 on this circle) */
    const double ca = cos(1.0), sa = sin(1.0);
    const scenario sph_ortho = {"sphere, orthogonal", SPHERE, {-0.6 * ca, -0.6 * sa, 2},
                                {0.6 * ca, 0.6 * sa, 2}, 1, {0, 0, 0}, 1, 1, 1,
                                {{0.5, -0.5, 0}}, POLE_JUMP_TOL};
    /* the torus: the nearest foot crosses the u seam at t = 1/2 (y = 0)
     * and the v seam (the outer equator) at t = 0.6 (z = 0) */
    const scenario tor_ortho = {"torus, orthogonal", TORUS, {3, -1, -0.6}, {3, 1, 0.4},
                                1, {0, 0, 0}, 1, 2, 2, {{0.5, -1, 0}, {0.6, 0, -1}}, SEAM_JUMP_TOL};
    /* along -z over both poles: the front hit through the north pole, the
     * back one through the south pole */
    const scenario sph_dir = {"sphere, directional", SPHERE, {-0.6 * ca, -0.6 * sa, 3},
                              {0.6 * ca, 0.6 * sa, 3}, 0, {0, 0, -1}, 2, 2, 1,
                              {{0.5, -0.5, 0}}, POLE_JUMP_TOL};
    /* along -x through the whole tube: four hits; the outer front one
     * crosses both seams (y = 0 at t = 1/2, z = 0 at t = 0.6), the inner
     * front one the u seam, the outer back one the v seam */
    const scenario tor_dir = {"torus, directional", TORUS, {4, -1, -0.3}, {4, 1, 0.2},
                              0, {-1, 0, 0}, 4, 4, 2, {{0.5, -1, 0}, {0.6, 0, -1}},
                              SEAM_JUMP_TOL};
    for (int degree = 1; degree <= 3; degree += 2) {
        run(&cyl_dir, degree);
        run(&sph_dir, degree);
        run(&tor_dir, degree);
        run(&cyl_ortho, degree);
        run(&sph_ortho, degree);
        run(&tor_ortho, degree);
    }
    return pc_test_finish("test_seam_join");
}
