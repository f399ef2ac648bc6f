/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Analytic surfaces as exact NURBS (src/analytic/): for every kind, in a
 * tilted frame, dense samples of the NURBS equal the analytic point of the
 * mapped parameters (and lie on the implicit surface), eval o invert is the
 * identity, the angle maps round-trip, full turns close, poles and apexes
 * get a defined answer, bad descriptions are refused with a status.
 *
 * Tolerances: 1e-12 times the surface's size. The construction is a few
 * multiplications of unit vectors and cos/sin of the knot angles, and
 * rational evaluation adds some ulps per degree: the observed error is a
 * few 1e-16 relative, so 1e-12 leaves margin for other libm's and still
 * fails on any wrong weight or control point (which moves points by 1e-3
 * or more).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "analytic/analytic.h"
#include "check.h"
#include "projcurve.h"

#define PI 3.14159265358979323846
#define REL 1e-12
#define GRID 41

static projcurve_context *ctx;

static pc_frame tilted_frame(void)
{
    const double o[3] = {1.5, -2.0, 0.75}, axis[3] = {0.3, -0.4, 0.8}, ref[3] = {1.0, 0.2, 0.1};
    pc_frame f;
    CHECK_OK(pc_frame_make(ctx, o, axis, ref, &f));
    return f;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance of p from the analytic surface by its implicit equation in the
 * frame (an oracle independent of the parametrisation); -1 when the kind
 * has none here. */
static double implicit_distance(const pc_analytic_surface *s, const double *p)
{
    const pc_frame *f = &s->frame;
    double d[3], l[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        d[k] = p[k] - f->origin[k];
    for (int k = 0; k < 3; ++k) {
        l[0] += d[k] * f->x[k];
        l[1] += d[k] * f->y[k];
        l[2] += d[k] * f->z[k];
    }
    const double rho = hypot(l[0], l[1]);
    switch (s->kind) {
    case PC_ANALYTIC_PLANE: return fabs(l[2]);
    case PC_ANALYTIC_CYLINDER: return fabs(rho - s->radius);
    case PC_ANALYTIC_SPHERE: return fabs(sqrt(rho * rho + l[2] * l[2]) - s->radius);
    case PC_ANALYTIC_TORUS: return fabs(hypot(rho - s->radius, l[2]) - s->minor_radius);
    case PC_ANALYTIC_CONE: {
        /* distance from the generator line rho = R + z tan a (either side) */
        const double c = cos(s->semi_angle), sn = sin(s->semi_angle);
        const double a = fabs((rho - s->radius) * c - l[2] * sn);
        const double b = fabs((-rho - s->radius) * c - l[2] * sn);
        return a < b ? a : b;
    }
    default: return -1.0;
    }
}

typedef struct built {
    projcurve_surface *h;
    pc_angle_map mu, mv;
} built;

static built build(pc_arena *arena, const pc_analytic_surface *s, const double box[4])
{
    built b = {NULL, {0}, {0}};
    pc_rational_surface n;
    CHECK_OK(pc_analytic_to_nurbs(ctx, arena, s, box, &n, &b.mu, &b.mv));
    CHECK_OK(projcurve_surface_create_nurbs(ctx, n.deg_u, n.deg_v, n.n_u, n.n_v, n.ctrl,
                                            n.weights, n.knots_u, n.knots_v, &b.h));
    return b;
}

/* Dense samples of the NURBS against the analytic point of the mapped
 * parameters and the implicit equation; returns the largest error. */
static double sample_against_exact(const pc_analytic_surface *s, const built *b, double size)
{
    double dom[4], worst = 0.0;
    CHECK_OK(projcurve_surface_domain(ctx, b->h, dom));
    for (int i = 0; i < GRID; ++i)
        for (int j = 0; j < GRID; ++j) {
            const double su = dom[0] + (dom[1] - dom[0]) * i / (GRID - 1);
            const double sv = dom[2] + (dom[3] - dom[2]) * j / (GRID - 1);
            double p[3], q[3];
            if (projcurve_surface_eval(ctx, b->h, su, sv, 0, p) != PROJCURVE_OK) {
                CHECK(0);
                return 1e300;
            }
            pc_analytic_eval(s, pc_nurbs_to_angle(&b->mu, su), pc_nurbs_to_angle(&b->mv, sv), q);
            const double e = dist3(p, q), imp = implicit_distance(s, p);
            worst = fmax(worst, fmax(e, imp));
            if (e > REL * size || imp > REL * size) {
                pc_test_fail_at(__FILE__, __LINE__, "%s at (s, t) = (%.17g, %.17g): NURBS off the "
                                "exact point by %.3g, the implicit surface by %.3g (size %g)",
                                pc_analytic_kind_name(s->kind), su, sv, e, imp, size);
                return worst;
            }
        }
    return worst;
}

/* p = eval(u, v) then invert then eval: the same point. */
static void eval_invert_identity(const pc_analytic_surface *s, const double box[4], double size)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 17);
    for (int k = 0; k < 500; ++k) {
        const double u = pc_test_rng_uniform(&rng, box[0], box[1]);
        const double v = pc_test_rng_uniform(&rng, box[2], box[3]);
        double p[3], q[3], u2, v2;
        pc_analytic_eval(s, u, v, p);
        pc_analytic_invert(s, p, &u2, &v2);
        pc_analytic_eval(s, u2, v2, q);
        if (!(dist3(p, q) <= REL * size)) {
            pc_test_fail_at(__FILE__, __LINE__, "%s: eval(invert(eval(%.17g, %.17g))) moved by %.3g",
                            pc_analytic_kind_name(s->kind), u, v, dist3(p, q));
            return;
        }
        ++pc_test_checks;
    }
}

static void map_round_trip(const pc_angle_map *m)
{
    for (int i = 0; i <= 1000; ++i) {
        const double a = m->a0 + (m->a1 - m->a0) * i / 1000.0;
        const double s = pc_angle_to_nurbs(m, a);
        CHECK_NEAR(pc_nurbs_to_angle(m, s), a, REL * (1.0 + fabs(a)));
        CHECK_NEAR(pc_angle_to_nurbs(m, pc_nurbs_to_angle(m, a)), a, REL * (1.0 + fabs(a)));
    }
    /* s = angle at every segment end */
    CHECK_NEAR(pc_angle_to_nurbs(m, m->a0), m->a0, 0.0);
    CHECK_NEAR(pc_angle_to_nurbs(m, m->a1), m->a1, REL);
}

static void check_kind(const pc_analytic_surface *s, const double box[4], double size)
{
    pc_arena arena;
    pc_arena_init(&arena, 1 << 14);
    built b = build(&arena, s, box);
    if (b.h != NULL) {
        const double worst = sample_against_exact(s, &b, size);
        printf("%-10s largest error of %d x %d samples: %.2e (relative %.2e)\n",
               pc_analytic_kind_name(s->kind), GRID, GRID, worst, worst / size);
        if (b.mu.is_angle)
            map_round_trip(&b.mu);
        if (b.mv.is_angle)
            map_round_trip(&b.mv);
    }
    eval_invert_identity(s, box, size);
    projcurve_surface_destroy(b.h);
    pc_arena_release(&arena);
}

static void elementary_kinds(void)
{
    const pc_frame f = tilted_frame();
    const double full[4] = {0.0, 2 * PI, 0.0, 2 * PI};
    pc_analytic_surface plane = {.kind = PC_ANALYTIC_PLANE, .frame = f};
    check_kind(&plane, (double[]){-3.0, 2.0, -1.0, 4.0}, 5.0);
    pc_analytic_surface cyl = {.kind = PC_ANALYTIC_CYLINDER, .frame = f, .radius = 2.5};
    check_kind(&cyl, (double[]){0.0, 2 * PI, -1.0, 3.0}, 5.0);
    check_kind(&cyl, (double[]){0.3, 1.9, -1.0, 3.0}, 5.0); /* a partial turn, 2 segments */
    pc_analytic_surface cone = {.kind = PC_ANALYTIC_CONE, .frame = f, .radius = 1.5,
                                .semi_angle = 0.4};
    check_kind(&cone, (double[]){0.0, 2 * PI, -1.0, 2.0}, 5.0);
    pc_analytic_surface sphere = {.kind = PC_ANALYTIC_SPHERE, .frame = f, .radius = 3.0};
    check_kind(&sphere, (double[]){0.0, 2 * PI, -PI / 2, PI / 2}, 6.0);
    check_kind(&sphere, (double[]){-1.0, 2.5, -0.5, 1.2}, 6.0);
    pc_analytic_surface torus = {.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 4.0,
                                 .minor_radius = 1.25};
    check_kind(&torus, full, 10.0);
    pc_analytic_surface horn = {.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 1.0,
                                .minor_radius = 1.0};
    check_kind(&horn, full, 4.0);
}

/* A torus as the revolution of a circle, and a cylinder as the extrusion
 * of one: the swept kinds against the elementary formulas. */
static void swept_kinds(void)
{
    const pc_frame f = tilted_frame();
    pc_arena arena;
    pc_arena_init(&arena, 1 << 14);
    pc_rational_curve circle;
    double centre[3];
    for (int k = 0; k < 3; ++k)
        centre[k] = f.origin[k] + 4.0 * f.x[k];
    CHECK_OK(pc_ellipse_arc(ctx, &arena, centre, f.x, f.z, 1.25, 1.25, 0.0, 2 * PI, &circle));
    pc_analytic_surface rev = {.kind = PC_ANALYTIC_REVOLUTION, .frame = f, .curve = &circle,
                               .curve_map = pc_angle_map_make(0.0, 2 * PI)};
    check_kind(&rev, (double[]){0.0, 2 * PI, 0.0, 2 * PI}, 10.0);
    pc_analytic_surface torus = {.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 4.0,
                                 .minor_radius = 1.25};
    for (int i = 0; i < 20; ++i) {
        const double u = 0.31 * i, v = 0.29 * i;
        double p[3], q[3];
        pc_analytic_eval(&rev, u, v, p);
        pc_analytic_eval(&torus, u, v, q);
        CHECK_NEAR(dist3(p, q), 0.0, REL * 10.0);
    }
    /* an ellipse swept along a tilted vector */
    pc_rational_curve ell;
    CHECK_OK(pc_ellipse_arc(ctx, &arena, f.origin, f.x, f.y, 2.0, 1.0, -1.0, 4.0, &ell));
    pc_analytic_surface ext = {.kind = PC_ANALYTIC_EXTRUSION, .frame = f, .curve = &ell,
                               .extrusion = {0.2, 0.5, 1.5},
                               .curve_map = pc_angle_map_make(-1.0, 4.0)};
    check_kind(&ext, (double[]){-1.0, 4.0, -1.0, 2.0}, 6.0);
    for (int i = 0; i < 20; ++i) {
        const double t = -1.0 + 0.25 * i, v = 0.1 * i - 1.0;
        double p[3], q[3];
        pc_analytic_eval(&ext, t, v, p);
        for (int k = 0; k < 3; ++k)
            q[k] = f.origin[k] + 2.0 * cos(t) * f.x[k] + sin(t) * f.y[k] + v * ext.extrusion[k];
        CHECK_NEAR(dist3(p, q), 0.0, REL * 6.0);
    }
    /* a profile that is not planar with the axis: a skew line turned about
     * z is a hyperboloid of one sheet, rho^2 = a^2 + (h tan b)^2 */
    const double o[3] = {1.5, -2.0, 0.75};
    pc_rational_curve skew;
    double start[3], dir[3];
    for (int k = 0; k < 3; ++k) {
        start[k] = o[k] + 1.0 * f.x[k];
        dir[k] = 0.5 * f.y[k] + f.z[k];
    }
    CHECK_OK(pc_line_segment(ctx, &arena, start, dir, -2.0, 2.0, &skew));
    pc_analytic_surface hyp = {.kind = PC_ANALYTIC_REVOLUTION, .frame = f, .curve = &skew};
    check_kind(&hyp, (double[]){0.0, 2 * PI, -2.0, 2.0}, 5.0);
    pc_arena_release(&arena);
}

static void closure(void)
{
    const pc_frame f = tilted_frame();
    pc_arena arena;
    pc_arena_init(&arena, 1 << 14);
    pc_analytic_surface sphere = {.kind = PC_ANALYTIC_SPHERE, .frame = f, .radius = 3.0};
    built b = build(&arena, &sphere, (double[]){0.0, 2 * PI, -PI / 2, PI / 2});
    double north[3], south[3];
    pc_analytic_eval(&sphere, 0.0, PI / 2, north);
    pc_analytic_eval(&sphere, 0.0, -PI / 2, south);
    for (int i = 0; i <= 16 && b.h; ++i) {
        const double s = 2 * PI * i / 16.0;
        double p[3], q[3];
        CHECK_OK(projcurve_surface_eval(ctx, b.h, s, PI / 2, 0, p));
        CHECK_NEAR(dist3(p, north), 0.0, REL * 6.0);
        CHECK_OK(projcurve_surface_eval(ctx, b.h, s, -PI / 2, 0, p));
        CHECK_NEAR(dist3(p, south), 0.0, REL * 6.0);
        /* the seam: s = 0 and s = 2 pi are the same meridian */
        CHECK_OK(projcurve_surface_eval(ctx, b.h, 0.0, s / 2 - PI / 2, 0, p));
        CHECK_OK(projcurve_surface_eval(ctx, b.h, 2 * PI, s / 2 - PI / 2, 0, q));
        CHECK_NEAR(dist3(p, q), 0.0, REL * 6.0);
    }
    projcurve_surface_destroy(b.h);
    pc_analytic_surface torus = {.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 4.0,
                                 .minor_radius = 1.25};
    b = build(&arena, &torus, (double[]){0.0, 2 * PI, 0.0, 2 * PI});
    for (int i = 0; i <= 16 && b.h; ++i) {
        const double s = 2 * PI * i / 16.0;
        double p[3], q[3];
        CHECK_OK(projcurve_surface_eval(ctx, b.h, s, 0.0, 0, p));
        CHECK_OK(projcurve_surface_eval(ctx, b.h, s, 2 * PI, 0, q));
        CHECK_NEAR(dist3(p, q), 0.0, REL * 10.0);
        CHECK_OK(projcurve_surface_eval(ctx, b.h, 0.0, s, 0, p));
        CHECK_OK(projcurve_surface_eval(ctx, b.h, 2 * PI, s, 0, q));
        CHECK_NEAR(dist3(p, q), 0.0, REL * 10.0);
    }
    projcurve_surface_destroy(b.h);
    pc_arena_release(&arena);
}

static void degenerate_places(void)
{
    const pc_frame f = tilted_frame();
    double u, v, p[3];
    pc_analytic_surface sphere = {.kind = PC_ANALYTIC_SPHERE, .frame = f, .radius = 3.0};
    pc_analytic_eval(&sphere, 1.0, PI / 2, p);
    pc_analytic_invert(&sphere, p, &u, &v);
    CHECK_NEAR(v, PI / 2, 1e-7); /* the pole: latitude to sqrt(eps), longitude defined */
    CHECK(u >= 0.0 && u < 2 * PI);
    pc_analytic_invert(&sphere, f.origin, &u, &v); /* the centre */
    CHECK(u == 0.0 && v == 0.0);
    pc_analytic_surface cone = {.kind = PC_ANALYTIC_CONE, .frame = f, .radius = 1.5,
                                .semi_angle = 0.4};
    const double apex_v = -1.5 / tan(0.4);
    pc_analytic_eval(&cone, 0.7, apex_v, p);
    pc_analytic_invert(&cone, p, &u, &v);
    CHECK_NEAR(v, apex_v, REL * 5.0);
    CHECK(u >= 0.0 && u < 2 * PI);
    /* past the apex: the nappe on the other side of the axis */
    pc_analytic_eval(&cone, 0.7, apex_v - 2.0, p);
    pc_analytic_invert(&cone, p, &u, &v);
    CHECK_NEAR(v, apex_v - 2.0, REL * 10.0);
    CHECK_NEAR(u, 0.7, REL * 10.0);
    /* a cone box across its apex builds and stays exact */
    check_kind(&cone, (double[]){0.0, 2 * PI, apex_v - 1.0, apex_v + 1.0}, 5.0);
    pc_analytic_surface apex_cone = {.kind = PC_ANALYTIC_CONE, .frame = f, .radius = 0.0,
                                     .semi_angle = -0.6};
    check_kind(&apex_cone, (double[]){0.0, 2 * PI, 0.0, 2.0}, 5.0);
    pc_analytic_surface torus = {.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 4.0,
                                 .minor_radius = 1.25};
    double c[3];
    for (int k = 0; k < 3; ++k)
        c[k] = f.origin[k] + 4.0 * f.x[k];
    pc_analytic_invert(&torus, c, &u, &v); /* the centre circle: any v, defined */
    CHECK(u >= 0.0 && u < 2 * PI && v >= 0.0 && v < 2 * PI);
}

static void bad_input(void)
{
    const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, zz[3] = {0, 0, 3};
    pc_frame f;
    CHECK_STATUS(pc_frame_make(ctx, o, zero, NULL, &f), PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK_STATUS(pc_frame_make(ctx, o, z, zz, &f), PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "parallel") != NULL);
    CHECK_STATUS(pc_frame_make(ctx, o, z, zero, &f), PROJCURVE_ERR_ZERO_DIRECTION);
    const double nan3[3] = {NAN, 0, 0};
    CHECK_STATUS(pc_frame_make(ctx, nan3, z, NULL, &f), PROJCURVE_ERR_NOT_FINITE);
    CHECK_OK(pc_frame_make(ctx, o, z, NULL, &f));
    pc_arena arena;
    pc_arena_init(&arena, 1 << 12);
    pc_rational_surface n;
    const double box[4] = {0, 2 * PI, 0, 1};
    pc_analytic_surface s = {.kind = PC_ANALYTIC_CYLINDER, .frame = f, .radius = 0.0};
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, box, &n, NULL, NULL),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    s.radius = -1.0;
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, box, &n, NULL, NULL),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    s.kind = PC_ANALYTIC_SPHERE;
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_INVALID_ARGUMENT);
    s = (pc_analytic_surface){.kind = PC_ANALYTIC_TORUS, .frame = f, .radius = 1.0,
                              .minor_radius = 1.5};
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "spindle") != NULL);
    s = (pc_analytic_surface){.kind = PC_ANALYTIC_CONE, .frame = f, .radius = 1.0,
                              .semi_angle = PI / 2};
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_INVALID_ARGUMENT);
    s.semi_angle = 0.0;
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_INVALID_ARGUMENT);
    s = (pc_analytic_surface){.kind = PC_ANALYTIC_EXTRUSION, .frame = f};
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_ZERO_DIRECTION);
    s.extrusion[2] = 1.0;
    CHECK_STATUS(pc_analytic_check(ctx, &s), PROJCURVE_ERR_NULL_ARGUMENT);
    s = (pc_analytic_surface){.kind = PC_ANALYTIC_CYLINDER, .frame = f, .radius = 1.0};
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, (double[]){0, 7, 0, 1}, &n, NULL, NULL),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, (double[]){0, 1, 1, 1}, &n, NULL, NULL),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, (double[]){0, NAN, 0, 1}, &n, NULL, NULL),
                 PROJCURVE_ERR_NOT_FINITE);
    s.kind = PC_ANALYTIC_SPHERE;
    CHECK_STATUS(pc_analytic_to_nurbs(ctx, &arena, &s, (double[]){0, 1, -2, 1}, &n, NULL, NULL),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    pc_rational_curve c;
    CHECK_STATUS(pc_ellipse_arc(ctx, &arena, o, f.x, f.y, 0.0, 1.0, 0.0, 1.0, &c),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(pc_ellipse_arc(ctx, &arena, o, f.x, f.y, 1.0, 1.0, 0.0, 7.0, &c),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(pc_line_segment(ctx, &arena, o, zero, 0.0, 1.0, &c), PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK_STATUS(pc_line_segment(ctx, &arena, o, z, 1.0, 1.0, &c), PROJCURVE_ERR_INVALID_ARGUMENT);
    pc_arena_release(&arena);
}

/* Circles and ellipses: NURBS point at s = the analytic point at the
 * mapped t; lines keep their parameter. */
static void curves(void)
{
    const pc_frame f = tilted_frame();
    pc_arena arena;
    pc_arena_init(&arena, 1 << 12);
    const double ranges[][2] = {{0.0, 2 * PI}, {-0.4, 0.9}, {1.0, 1.0 + 1.5 * PI}, {-7.0, -6.9}};
    const double axes[][2] = {{2.0, 2.0}, {3.0, 0.5}};
    for (size_t r = 0; r < 4; ++r)
        for (size_t a = 0; a < 2; ++a) {
            pc_rational_curve c;
            CHECK_OK(pc_ellipse_arc(ctx, &arena, f.origin, f.x, f.y, axes[a][0], axes[a][1],
                                    ranges[r][0], ranges[r][1], &c));
            projcurve_curve *h = NULL;
            CHECK_OK(projcurve_curve_create_nurbs(ctx, c.degree, c.n_ctrl, c.ctrl, c.weights,
                                                  c.knots, &h));
            if (h == NULL)
                continue;
            const pc_angle_map m = pc_angle_map_make(ranges[r][0], ranges[r][1]);
            for (int i = 0; i <= 200; ++i) {
                const double s = ranges[r][0] + (ranges[r][1] - ranges[r][0]) * i / 200.0;
                const double t = pc_nurbs_to_angle(&m, s);
                double p[3], q[3];
                CHECK_OK(projcurve_curve_eval(ctx, h, s, 0, p));
                for (int k = 0; k < 3; ++k)
                    q[k] = f.origin[k] + axes[a][0] * cos(t) * f.x[k] + axes[a][1] * sin(t) * f.y[k];
                CHECK_NEAR(dist3(p, q), 0.0, REL * 3.0);
            }
            map_round_trip(&m);
            projcurve_curve_destroy(h);
        }
    pc_rational_curve line;
    const double d[3] = {1.0, -2.0, 0.5};
    CHECK_OK(pc_line_segment(ctx, &arena, f.origin, d, -1.5, 2.5, &line));
    for (int i = 0; i <= 10; ++i) {
        const double t = -1.5 + 0.4 * i;
        double p[3];
        pc_rational_curve_eval(&line, t, p);
        for (int k = 0; k < 3; ++k)
            CHECK_NEAR(p[k], f.origin[k] + t * d[k], REL * 5.0);
    }
    pc_arena_release(&arena);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    elementary_kinds();
    swept_kinds();
    closure();
    degenerate_places();
    bad_input();
    curves();
    projcurve_context_destroy(ctx);
    return pc_test_finish("analytic_surfaces");
}
