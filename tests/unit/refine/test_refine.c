/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tolerance control and composition (refine/): the composed pieces must be
 * within eps_D of the exact projection (3D Hausdorff distance), meet at
 * joints within eps_T, each lie in one Bezier patch, and the piece limit and
 * bad tolerances must give clear statuses.
 *
 * Oracles, independent of the refinement code:
 *  - a bicubic height field whose (x, y) map is the identity up to scale
 *    (control points at the Greville abscissae), projected along -z: the
 *    exact projection of P(t) = (x(t), y(t), h) is S(x(t)/X, y(t)/Y);
 *  - a half cylinder as an exact rational NURBS, projected along -z: the
 *    exact projection is (x, y, sqrt(R^2 - x^2)).
 * The distance is measured both ways on dense samples: each output sample is
 * projected onto the exact curve by its own Newton iteration on t, and each
 * exact sample onto its piece by Newton on s.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "piece_oracle.h"
#include "refine/refine.h"
#include "trace/projector.h"
#include "trace/result.h"

#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* A directional projector written for this test (DESIGN.md, "Numerics").   */
/* ------------------------------------------------------------------------ */

/* ------------------------------------------------------------------------ */
/* Test shapes with their exact projections.                               */
/* ------------------------------------------------------------------------ */

typedef struct shape {
    const char *name;
    projcurve_surface *surface;
    projcurve_curve *curve;
    double t0, t1;
    /* exact projection Q(t) and its first two derivatives */
    void (*exact)(const struct shape *sh, double t, pc_vec3 q[3]);
    /* exact (u, v) at t, for the traced polyline given to the refinement */
    void (*exact_uv)(const struct shape *sh, double t, double uv[2]);
    int orthogonal; /* 0: projection along -z */
    double bump;    /* height-field curves: amplitude of a narrow bump in y */
} shape;

/* The test's own projector: along -z, or orthogonal. */
static void make_projector(const shape *sh, pc_oracle_dir *d, pc_projector *proj)
{
    const double down[3] = {0.0, 0.0, -1.0};
    if (sh->orthogonal)
        pc_oracle_projector_orthogonal(sh->surface, sh->curve, proj);
    else
        pc_oracle_projector(sh->surface, sh->curve, down, d, proj);
}

/* Height field: x = 10 u, y = 8 v, z = h(u, v); the curve flies at z = 20. */
#define HF_X 10.0
#define HF_Y 8.0

/* Width (in t) of the narrow bump some tests add to the curve. */
#define HF_BUMP_WIDTH 0.01

static void hf_curve_xy(const shape *sh, double t, double xy[2], double d1[2], double d2[2])
{
    /* x from 0.3 to 9.7, y a wave across most of the v range, plus
     * sh->bump * exp(-((t - 1/2) / w)^2) */
    const double w = 3.0 * PI;
    const double z = (t - 0.5) / HF_BUMP_WIDTH, g = sh->bump * exp(-z * z);
    const double g1 = -2.0 * z / HF_BUMP_WIDTH * g;
    const double g2 = (4.0 * z * z - 2.0) / (HF_BUMP_WIDTH * HF_BUMP_WIDTH) * g;
    xy[0] = 0.3 + 9.4 * t;
    xy[1] = 4.0 + 3.2 * sin(w * t) + g;
    d1[0] = 9.4;
    d1[1] = 3.2 * w * cos(w * t) + g1;
    d2[0] = 0.0;
    d2[1] = -3.2 * w * w * sin(w * t) + g2;
}

static int hf_curve_fn(void *user, double t, double out[9])
{
    const shape *sh = user;
    double xy[2], d1[2], d2[2];
    hf_curve_xy(sh, t, xy, d1, d2);
    const double v[9] = {xy[0], xy[1], 20.0, d1[0], d1[1], 0.0, d2[0], d2[1], 0.0};
    memcpy(out, v, sizeof v);
    return 0;
}

static void hf_exact_uv(const shape *sh, double t, double uv[2])
{
    double xy[2], d1[2], d2[2];
    hf_curve_xy(sh, t, xy, d1, d2);
    uv[0] = xy[0] / HF_X;
    uv[1] = xy[1] / HF_Y;
}

static void hf_exact(const shape *sh, double t, pc_vec3 q[3])
{
    double xy[2], d1[2], d2[2];
    hf_curve_xy(sh, t, xy, d1, d2);
    const double u1 = d1[0] / HF_X, v1 = d1[1] / HF_Y, u2 = d2[0] / HF_X, v2 = d2[1] / HF_Y;
    double s6[18];
    projcurve_surface_eval(NULL, sh->surface, xy[0] / HF_X, xy[1] / HF_Y, 2, s6);
    pc_vec3 s[6];
    for (int k = 0; k < 6; ++k)
        s[k] = vec3_load(s6 + 3 * k);
    q[0] = s[0];
    q[1] = vec3_add(vec3_scale(s[1], u1), vec3_scale(s[2], v1));
    q[2] = vec3_add(vec3_add(vec3_scale(s[3], u1 * u1), vec3_scale(s[4], 2.0 * u1 * v1)),
                    vec3_add(vec3_scale(s[5], v1 * v1),
                             vec3_add(vec3_scale(s[1], u2), vec3_scale(s[2], v2))));
}

/* Clamped uniform knots of a degree-p spline with n control points on [0,1]. */
static void uniform_knots(int p, int n, double *knots)
{
    for (int k = 0; k < n + p + 1; ++k) {
        const int inner = k - p;
        const int spans = n - p;
        knots[k] = inner <= 0 ? 0.0 : (inner >= spans ? 1.0 : (double)inner / spans);
    }
}

static double greville(const double *knots, int p, int i)
{
    double s = 0.0;
    for (int k = 1; k <= p; ++k)
        s += knots[i + k];
    return s / p;
}

#define HF_MAX_CTRL 12

/* Degree p in both directions, nu x nv control points (at most HF_MAX_CTRL). */
static int make_height_field(shape *sh, int P, int NU, int NV, const char *name)
{
    double ku[HF_MAX_CTRL + 4], kv[HF_MAX_CTRL + 4], ctrl[3 * HF_MAX_CTRL * HF_MAX_CTRL];
    uniform_knots(P, NU, ku);
    uniform_knots(P, NV, kv);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6101);
    for (int j = 0; j < NV; ++j)
        for (int i = 0; i < NU; ++i) {
            double *c = ctrl + 3 * (j * NU + i);
            c[0] = HF_X * greville(ku, P, i);
            c[1] = HF_Y * greville(kv, P, j);
            c[2] = pc_test_rng_uniform(&rng, -1.5, 1.5);
        }
    memset(sh, 0, sizeof *sh);
    sh->name = name;
    sh->t0 = 0.0;
    sh->t1 = 1.0;
    sh->exact = hf_exact;
    sh->exact_uv = hf_exact_uv;
    if (projcurve_surface_create_nurbs(NULL, P, P, NU, NV, ctrl, NULL, ku, kv, &sh->surface) !=
        PROJCURVE_OK)
        return 0;
    /* sh is the curve's user data: it must stay where it is */
    return projcurve_curve_create_callback(NULL, hf_curve_fn, sh, 0.0, 1.0, &sh->curve) ==
           PROJCURVE_OK;
}

/* Half cylinder x^2 + z^2 = R^2, z >= 0, y in [-5, 5]: two rational quadratic
 * arcs in u (double knot at 1/2), linear in v with two spans. */
#define CYL_R 4.0

static void cyl_curve(double t, double out[9])
{
    const double w = 2.0 * PI;
    const double v[9] = {3.5 * sin(w * t), -4.5 + 9.0 * t, 10.0,
                         3.5 * w * cos(w * t), 9.0, 0.0,
                         -3.5 * w * w * sin(w * t), 0.0, 0.0};
    memcpy(out, v, sizeof v);
}

static int cyl_curve_fn(void *user, double t, double out[9])
{
    (void)user;
    cyl_curve(t, out);
    return 0;
}

static void cyl_exact(const shape *sh, double t, pc_vec3 q[3])
{
    (void)sh;
    double c[9];
    cyl_curve(t, c);
    const double x = c[0], x1 = c[3], x2 = c[6];
    const double z = sqrt(CYL_R * CYL_R - x * x);
    const double z1 = -x * x1 / z;
    const double z2 = -(x1 * x1 + x * x2 + z1 * z1) / z;
    q[0] = vec3(x, c[1], z);
    q[1] = vec3(x1, c[4], z1);
    q[2] = vec3(x2, c[7], z2);
}

/* (u, v) of the point at angle a (from +x towards +z) and height y on the
 * half cylinder: on each quarter arc with weights (1, sqrt(1/2), 1),
 * tan(a'/2) = s / ((1 - s) sqrt2 + s), inverted. */
static void cyl_uv_of(double a, double y, double uv[2])
{
    const double local = a <= PI / 2 ? a : a - PI / 2;
    const double k = tan(local / 2) * sqrt(2.0);
    const double s = k / (1.0 + k - tan(local / 2));
    uv[0] = a <= PI / 2 ? 0.5 * s : 0.5 + 0.5 * s;
    uv[1] = (y + 5.0) / 10.0;
}

static void cyl_exact_uv(const shape *sh, double t, double uv[2])
{
    double c[9];
    cyl_curve(t, c);
    cyl_uv_of(atan2(sqrt(CYL_R * CYL_R - c[0] * c[0]), c[0]), c[1], uv);
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    proj.correct(&proj, t, uv, NULL);
}

static int make_cylinder(shape *sh)
{
    const double h = sqrt(0.5);
    const double arc[5][2] = {{CYL_R, 0}, {CYL_R, CYL_R}, {0, CYL_R}, {-CYL_R, CYL_R}, {-CYL_R, 0}};
    const double warc[5] = {1, h, 1, h, 1};
    const double ys[3] = {-5.0, 0.0, 5.0};
    double ctrl[3 * 15], weights[15];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) {
            double *c = ctrl + 3 * (j * 5 + i);
            c[0] = arc[i][0];
            c[1] = ys[j];
            c[2] = arc[i][1];
            weights[j * 5 + i] = warc[i];
        }
    const double ku[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1}, kv[5] = {0, 0, 0.5, 1, 1};
    memset(sh, 0, sizeof *sh);
    sh->name = "rational half cylinder";
    sh->t0 = 0.0;
    sh->t1 = 1.0;
    sh->exact = cyl_exact;
    sh->exact_uv = cyl_exact_uv;
    if (projcurve_surface_create_nurbs(NULL, 2, 1, 5, 3, ctrl, weights, ku, kv, &sh->surface) !=
        PROJCURVE_OK)
        return 0;
    return projcurve_curve_create_callback(NULL, cyl_curve_fn, NULL, 0.0, 1.0, &sh->curve) ==
           PROJCURVE_OK;
}

/* Orthogonal projection onto the same half cylinder of a curve winding
 * around it at radius 5 to 7: the foot point is the radial projection
 * Q = (R x / rho, y, R z / rho), rho = |(x, z)|. */
static void ortho_curve(double t, double out[9])
{
    const double th = 0.3 + 2.5 * t, th1 = 2.5, rad = 6.0 + sin(5.0 * t);
    const double rad1 = 5.0 * cos(5.0 * t), rad2 = -25.0 * sin(5.0 * t);
    const double c = cos(th), s = sin(th);
    const double v[9] = {rad * c, -4.0 + 8.0 * t, rad * s,
                         rad1 * c - rad * s * th1, 8.0, rad1 * s + rad * c * th1,
                         rad2 * c - 2.0 * rad1 * s * th1 - rad * c * th1 * th1, 0.0,
                         rad2 * s + 2.0 * rad1 * c * th1 - rad * s * th1 * th1};
    memcpy(out, v, sizeof v);
}

static int ortho_curve_fn(void *user, double t, double out[9])
{
    (void)user;
    ortho_curve(t, out);
    return 0;
}

static void ortho_exact(const shape *sh, double t, pc_vec3 q[3])
{
    (void)sh;
    double c[9];
    ortho_curve(t, c);
    const double rho = hypot(c[0], c[2]), rho1 = (c[0] * c[3] + c[2] * c[5]) / rho;
    q[0] = vec3(CYL_R * c[0] / rho, c[1], CYL_R * c[2] / rho);
    q[1] = vec3(CYL_R * (c[3] * rho - c[0] * rho1) / (rho * rho), c[4],
                CYL_R * (c[5] * rho - c[2] * rho1) / (rho * rho));
    q[2] = vec3(0.0, 0.0, 0.0); /* the oracle's Newton runs as Gauss-Newton */
}

static void ortho_exact_uv(const shape *sh, double t, double uv[2])
{
    double c[9];
    ortho_curve(t, c);
    cyl_uv_of(atan2(c[2], c[0]), c[1], uv);
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    proj.correct(&proj, t, uv, NULL);
}

static int make_ortho_cylinder(shape *sh)
{
    if (!make_cylinder(sh))
        return 0;
    projcurve_curve_destroy(sh->curve);
    sh->curve = NULL;
    sh->name = "orthogonal, half cylinder";
    sh->exact = ortho_exact;
    sh->exact_uv = ortho_exact_uv;
    sh->orthogonal = 1;
    return projcurve_curve_create_callback(NULL, ortho_curve_fn, NULL, 0.0, 1.0, &sh->curve) ==
           PROJCURVE_OK;
}

static void free_shape(shape *sh)
{
    projcurve_surface_destroy(sh->surface);
    projcurve_curve_destroy(sh->curve);
}

static void shape_exact(const void *user, double t, pc_vec3 q[3])
{
    const shape *sh = user;
    sh->exact(sh, t, q);
}

static pc_oracle_measure measure_branch(const shape *sh, const pc_branch *b)
{
    return pc_oracle_measure_branch(b, shape_exact, sh, &sh->surface->grid);
}

/* A result with one branch: the exact projection at n_points even t over
 * [ta, tb] (in that order: tb < ta gives a descending branch). */
static projcurve_result *traced_result(const shape *sh, double ta, double tb, int n_points)
{
    projcurve_result *r = NULL;
    pc_branch *b = NULL;
    if (pc_result_create(NULL, 3, &r) != PROJCURVE_OK)
        return NULL;
    if (pc_result_add_branch(NULL, r, &b) != PROJCURVE_OK) {
        projcurve_result_destroy(r);
        return NULL;
    }
    for (int k = 0; k < n_points; ++k) {
        const double t = ta + (tb - ta) * k / (n_points - 1);
        double p[3] = {t, 0, 0};
        sh->exact_uv(sh, t, p + 1);
        pc_branch_add_point(NULL, b, 3, p);
    }
    b->start = PROJCURVE_START_CURVE_START;
    b->end = PROJCURVE_END_CURVE_END;
    return r;
}

/* ------------------------------------------------------------------------ */
/* Independent measurements on the output.                                  */
/* ------------------------------------------------------------------------ */

/* ------------------------------------------------------------------------ */
/* Tests                                                                    */
/* ------------------------------------------------------------------------ */

static void test_tolerances(shape *sh)
{
    static const double rel_eps[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    static const double angles[] = {10.0, 1.0};
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    const double size = sh->surface->size;
    for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
        for (size_t e = 0; e < sizeof rel_eps / sizeof rel_eps[0]; ++e) {
            pc_params o;
            pc_params_defaults(&o);
            o.tol_distance = rel_eps[e] * size;
            o.tol_angle_deg = angles[a];
            projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 41);
            CHECK(r != NULL);
            if (r == NULL)
                return;
            CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
            const pc_branch *b = &r->branches[0];
            CHECK(b->n_pieces > 0);
            if (b->n_pieces > 0) {
                const pc_oracle_measure m = measure_branch(sh, b);
                printf("%s: eps_D %.0e, eps_T %4.1f deg: %4zu pieces, Hausdorff %.3e (%.2f eps), "
                       "max joint %.3f deg\n",
                       sh->name, rel_eps[e], angles[a], b->n_pieces, m.hausdorff / size,
                       m.hausdorff / o.tol_distance, m.max_angle);
                CHECK(m.hausdorff <= o.tol_distance);
                CHECK(m.max_angle <= angles[a] * (1.0 + 1e-9));
                CHECK(m.max_gap <= 1e-12 * size);
                CHECK(m.max_end_err <= 1e-9 * size);
                CHECK(m.off_patch == 0);
                CHECK_NEAR(b->pieces[0].t0, sh->t0, 1e-15);
                CHECK_NEAR(b->pieces[b->n_pieces - 1].t1, sh->t1, 1e-15);
                /* the branch's points are the pieces' pcurve */
                CHECK(b->n_points == b->n_pieces + 1);
            }
            CHECK_NEAR(r->stats.tol_distance, o.tol_distance, 0.0);
            CHECK_NEAR(r->stats.pieces, (double)b->n_pieces, 0.0);
            projcurve_result_destroy(r);
        }
    }
}

/* A branch stored with decreasing t gives pieces in that order, same accuracy. */
static void test_descending(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    pc_params o;
    pc_params_defaults(&o);
    o.tol_distance = 1e-4 * sh->surface->size;
    projcurve_result *r = traced_result(sh, sh->t1, sh->t0, 30);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
    const pc_branch *b = &r->branches[0];
    CHECK(b->n_pieces > 0);
    if (b->n_pieces > 0) {
        CHECK_NEAR(b->pieces[0].t0, sh->t1, 0.0);
        CHECK_NEAR(b->pieces[b->n_pieces - 1].t1, sh->t0, 0.0);
        CHECK(b->pieces[0].t1 < b->pieces[0].t0);
        const pc_oracle_measure m = measure_branch(sh, b);
        CHECK(m.hausdorff <= o.tol_distance);
        CHECK(m.max_angle <= o.tol_angle_deg * (1.0 + 1e-9));
    }
    projcurve_result_destroy(r);
}

/* Automatic eps_D = 1e-4 of the model size; NULL options = defaults. */
static void test_automatic_tolerance(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 20);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    CHECK_NEAR(r->stats.tol_distance, 1e-4 * sh->surface->size, 1e-18);
    if (r->branches[0].n_pieces > 0) {
        const pc_oracle_measure m = measure_branch(sh, &r->branches[0]);
        CHECK(m.hausdorff <= r->stats.tol_distance);
    }
    projcurve_result_destroy(r);
}

static void test_bad_tolerances(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    static const struct {
        double dist, angle;
        long long pieces;
        projcurve_status expect;
    } cases[] = {
        {-1e-3, 1.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {NAN, 1.0, 100, PROJCURVE_ERR_NOT_FINITE},
        {INFINITY, 1.0, 100, PROJCURVE_ERR_NOT_FINITE},
        {1e-3, 0.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, -5.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, 90.5, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, NAN, 100, PROJCURVE_ERR_NOT_FINITE},
        {1e-3, 1.0, 0, PROJCURVE_ERR_OUT_OF_RANGE},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        pc_params o;
        pc_params_defaults(&o);
        o.tol_distance = cases[k].dist;
        o.tol_angle_deg = cases[k].angle;
        o.max_pieces = cases[k].pieces;
        projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 10);
        CHECK_STATUS(pc_refine_and_compose(ctx, &proj, &o, r), cases[k].expect);
        CHECK(strlen(projcurve_context_message(ctx)) > 0);
        CHECK(r->branches[0].n_pieces == 0);
        CHECK(r->branches[0].n_points == 10); /* untouched */
        projcurve_result_destroy(r);
    }
    /* the bounds themselves are accepted */
    pc_params o;
    pc_params_defaults(&o);
    o.tol_angle_deg = 90.0;
    o.tol_distance = 1e-2 * sh->surface->size;
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 10);
    CHECK_OK(pc_refine_and_compose(ctx, &proj, &o, r));
    projcurve_result_destroy(r);
    CHECK_STATUS(pc_refine_and_compose(ctx, NULL, &o, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context_destroy(ctx);
}

/* A tolerance that needs more pieces than allowed: LIMIT_REACHED, the branch
 * ends with END_LIMIT, and the pieces kept are a valid prefix. A second
 * branch after the limit gets no pieces and is marked too. */
static void test_piece_limit(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    pc_params o;
    pc_params_defaults(&o);
    o.tol_distance = 1e-6 * sh->surface->size;
    o.max_pieces = 7;
    projcurve_result *r = traced_result(sh, sh->t0, 0.5 * (sh->t0 + sh->t1), 20);
    pc_branch *second = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &second));
    for (int k = 0; k < 10; ++k) {
        const double t = 0.5 * (sh->t0 + sh->t1) + k * 0.05 * (sh->t1 - sh->t0);
        double p[3] = {t, 0, 0};
        sh->exact_uv(sh, t, p + 1);
        pc_branch_add_point(NULL, second, 3, p);
    }
    CHECK_STATUS(pc_refine_and_compose(ctx, &proj, &o, r), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(strstr(projcurve_context_message(ctx), "limit") != NULL);
    const pc_branch *b = &r->branches[0];
    CHECK(b->end == PROJCURVE_END_LIMIT);
    CHECK(b->n_pieces == 7);
    CHECK(b->n_points == b->n_pieces + 1);
    CHECK_NEAR(b->pieces[0].t0, sh->t0, 0.0);
    for (size_t i = 1; i < b->n_pieces; ++i)
        CHECK_NEAR(b->pieces[i].t0, b->pieces[i - 1].t1, 0.0);
    CHECK(r->branches[1].n_pieces == 0);
    CHECK(r->branches[1].end == PROJCURVE_END_LIMIT);
    CHECK_NEAR(r->stats.pieces, 7.0, 0.0);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
}

static int failing_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    (void)self, (void)t, (void)uv;
    if (iterations)
        *iterations = 0;
    return 0;
}

/* A corrector that never converges: the refinement must still end, and
 * compose nothing it cannot check (no exact point between the traced
 * vertices, so no deviation): every segment is a gap, the branch keeps its
 * traced vertices, has no pieces and ends with END_FAILED. */
static void test_failing_corrector(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    proj.correct = failing_correct;
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 15);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    CHECK(r->n_branches == 1);
    const pc_branch *b = &r->branches[0];
    CHECK(b->n_pieces == 0);
    CHECK(b->n_points == 15);
    CHECK(b->end == PROJCURVE_END_FAILED);
    CHECK_NEAR(r->stats.pieces, 0.0, 0.0);
    projcurve_result_destroy(r);
}

/* Degenerate branches: one point (left alone), repeated parameters (the
 * repeats are dropped), and a result of 3D points (not refinable). */
static void test_degenerate_branches(shape *sh)
{
    pc_projector proj;
    pc_oracle_dir d;
    make_projector(sh, &d, &proj);
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 12);
    pc_branch *single = NULL, *repeated = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &single));
    double p[3] = {0.3, 0, 0};
    sh->exact_uv(sh, 0.3, p + 1);
    CHECK_OK(pc_branch_add_point(NULL, single, 3, p));
    CHECK_OK(pc_result_add_branch(NULL, r, &repeated));
    for (int k = 0; k < 6; ++k) {
        double q[3] = {0.4 + 0.02 * (k / 2), 0, 0};
        sh->exact_uv(sh, q[0], q + 1);
        CHECK_OK(pc_branch_add_point(NULL, repeated, 3, q));
    }
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    CHECK(r->branches[0].n_pieces > 0);
    CHECK(r->branches[1].n_pieces == 0 && r->branches[1].n_points == 1);
    CHECK(r->branches[2].n_pieces > 0);
    for (size_t i = 0; i < r->branches[2].n_pieces; ++i)
        CHECK(r->branches[2].pieces[i].t1 > r->branches[2].pieces[i].t0);
    projcurve_result_destroy(r);

    projcurve_result *r4 = NULL;
    CHECK_OK(pc_result_create(NULL, 4, &r4));
    CHECK_STATUS(pc_refine_and_compose(NULL, &proj, NULL, r4), PROJCURVE_ERR_INVALID_ARGUMENT);
    projcurve_result_destroy(r4);
}

/* One-sided exact tangent of the height-field projection at t on the patch
 * holding the piece: the patch's own derivatives (a degree-1 surface has a
 * crease on every knot line). */
static pc_vec3 hf_side_tangent(const shape *sh, const pc_piece *pc, double t)
{
    double xy[2], d1[2], d2[2];
    hf_curve_xy(sh, t, xy, d1, d2);
    const pc_patch_grid *g = &sh->surface->grid;
    const size_t k = pc_patch_grid_locate(g, 0.5 * (pc->uv[0] + pc->uv[2]),
                                          0.5 * (pc->uv[1] + pc->uv[3]));
    pc_vec3 d[3];
    pc_bezier_patch_eval(&g->patches[k], xy[0] / HF_X, xy[1] / HF_Y, 1, d);
    return vec3_add(vec3_scale(d[1], d1[0] / HF_X), vec3_scale(d[2], d1[1] / HF_Y));
}

static double angle_deg_between(pc_vec3 a, pc_vec3 b)
{
    return atan2(vec3_norm(vec3_cross(a, b)), vec3_dot(a, b)) * 180.0 / PI;
}

/* A degree-1 height field: S is only C0 on its knot lines, so the exact
 * projection has a corner wherever it crosses one. The refinement must keep
 * those corners (no endless splitting), meet eps_D, and hold every joint to
 * eps_T beyond the exact curve's own corner there. */
static void test_creased_surface(void)
{
    shape sh;
    CHECK(make_height_field(&sh, 1, 7, 6, "degree-1 height field"));
    pc_oracle_dir d;
    pc_projector proj;
    make_projector(&sh, &d, &proj);
    static const double angles[] = {10.0, 1.0};
    for (size_t a = 0; a < 2; ++a) {
        pc_params o;
        pc_params_defaults(&o);
        o.tol_distance = 1e-4 * sh.surface->size;
        o.tol_angle_deg = angles[a];
        projcurve_result *r = traced_result(&sh, sh.t0, sh.t1, 41);
        CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
        const pc_branch *b = &r->branches[0];
        CHECK(b->n_pieces > 0 && b->n_pieces < 1000);
        if (b->n_pieces > 0) {
            const pc_oracle_measure m = measure_branch(&sh, b);
            CHECK(m.hausdorff <= o.tol_distance);
            CHECK(m.off_patch == 0);
            double worst_excess = 0.0;
            for (size_t i = 1; i < b->n_pieces; ++i) {
                const pc_piece *pv = &b->pieces[i - 1], *pc = &b->pieces[i];
                const int n = pv->degree;
                const pc_vec3 t_end = vec3_sub(vec3_load(pv->ctrl + 3 * n),
                                               vec3_load(pv->ctrl + 3 * (n - 1)));
                const pc_vec3 t_start = vec3_sub(vec3_load(pc->ctrl + 3), vec3_load(pc->ctrl));
                const double corner = angle_deg_between(hf_side_tangent(&sh, pv, pc->t0),
                                                        hf_side_tangent(&sh, pc, pc->t0));
                worst_excess = fmax(worst_excess, angle_deg_between(t_end, t_start) - corner);
            }
            printf("%s: eps_T %4.1f deg: %zu pieces, joints exceed the exact corners by <= %.3f "
                   "deg\n",
                   sh.name, angles[a], b->n_pieces, worst_excess);
            CHECK(worst_excess <= angles[a] * (1.0 + 1e-9));
        }
        projcurve_result_destroy(r);
    }
    free_shape(&sh);
}

/* A narrow bump (width 0.01 in t, 1.5 high) in the middle of the curve,
 * resolved by the traced polyline (spacing 0.005): the sampling of the
 * deviation must not step over it. */
static void test_narrow_bump(void)
{
    shape sh;
    CHECK(make_height_field(&sh, 3, 9, 7, "bicubic, narrow bump"));
    sh.bump = 1.5;
    pc_oracle_dir d;
    pc_projector proj;
    make_projector(&sh, &d, &proj);
    static const double rel_eps[] = {1e-2, 1e-4};
    for (size_t e = 0; e < 2; ++e) {
        pc_params o;
        pc_params_defaults(&o);
        o.tol_distance = rel_eps[e] * sh.surface->size;
        o.tol_angle_deg = 10.0;
        projcurve_result *r = traced_result(&sh, sh.t0, sh.t1, 201);
        CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
        const pc_branch *b = &r->branches[0];
        CHECK(b->n_pieces > 0);
        if (b->n_pieces > 0) {
            const pc_oracle_measure m = measure_branch(&sh, b);
            printf("%s: eps_D %.0e: %zu pieces, Hausdorff %.2f eps_D\n", sh.name, rel_eps[e],
                   b->n_pieces, m.hausdorff / o.tol_distance);
            CHECK(m.hausdorff <= o.tol_distance);
            CHECK(m.max_angle <= o.tol_angle_deg * (1.0 + 1e-9));
        }
        projcurve_result_destroy(r);
    }
    free_shape(&sh);
}

int main(void)
{
    shape shapes[3];
    if (!make_height_field(&shapes[0], 3, 9, 7, "bicubic height field") ||
        !make_cylinder(&shapes[1]) || !make_ortho_cylinder(&shapes[2]))
        pc_test_skip("surface or curve creation is not available");
    for (int k = 0; k < 3; ++k) {
        test_tolerances(&shapes[k]);
        test_descending(&shapes[k]);
        test_automatic_tolerance(&shapes[k]);
    }
    test_bad_tolerances(&shapes[0]);
    test_piece_limit(&shapes[0]);
    test_failing_corrector(&shapes[0]);
    test_failing_corrector(&shapes[1]);
    test_degenerate_branches(&shapes[0]);
    test_creased_surface();
    test_narrow_bump();
    for (int k = 0; k < 3; ++k)
        free_shape(&shapes[k]);
    return pc_test_finish("test_refine");
}
