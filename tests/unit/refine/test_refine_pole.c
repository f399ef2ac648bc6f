/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Projections through and beside the pole of a sphere, with straight and
 * with cubic pcurves (PROJCURVE_OPT_PCURVE_DEGREE 1 and 3).
 *
 * At the poles of the rational sphere (tests/support/trace_shapes: v = 0
 * and v = 1, collapsed edges) Su = 0: the (u, v) curve of a line over the
 * pole (a meridian) jumps by pi in u there while the 3D projection stays
 * smooth, and one passing beside it turns through pi in u. The uv tangent
 * q' is not available at the pole (the Jacobian is singular); beside it
 * its u component carries an error ~6e-10 / (1 - v) (a finite-difference
 * check of q' on the meridian: exact in v, and in 3D, to 1 - v = 1e-8).
 * A cubic march whose run ends at the pole must still get there: every
 * cubic reaching the pole was invalid, every halved one accepted, and the
 * march made pieces of half the distance left, one after another, to the
 * piece limit.
 *
 * The oracle is analytic: seen along -z, the line P(t) = (x(t), y(t), H)
 * meets the sphere |X| = R twice, at E(t) = (x, y, +-sqrt(R^2 - x^2 - y^2))
 * (every hit is returned: two branches, over the north pole v = 1 and the
 * south pole v = 0), with E'(t) by the chain rule (the sphere is smooth at
 * its poles, so E is). The composed pieces are measured against E by pc_oracle_measure_branch (the
 * Hausdorff distance both ways on dense samples, Newton on t and on the
 * piece parameter), and each sample of every piece is checked on the
 * sphere (| |X| - R |) and on the rays (the distance of its (x, y) from the
 * line's).
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "directional/directional.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "piece_oracle.h"
#include "trace_shapes.h"

#define R 10.0
#define H 20.0 /* height of the lines above the sphere's centre */
#define EPS_T_DEG 1.0
/* Samples per piece for the on-sphere and on-ray checks. */
#define PIECE_SAMPLES 32
/* A composed piece is S at its pcurve exactly up to the rounding of the
 * composition (test_compose_poly: ~1e-13 of the size, the degree-6 rational
 * pieces of the sphere included): on the sphere to 1e-11 of R. */
#define ON_SPHERE_REL 1e-11
/* The Hausdorff distance measured by the oracle's Newton may exceed the
 * refinement's own deviation measure by the oracle's resolution (1e-12 of
 * the size) and by the rounding of eps_D * size: 1e-9 of eps_D covers it. */
#define HAUSDORFF_SLACK 1e-9
/* A branch starting at the pole starts within this of t = 0 (its seed
 * there is found 7e-12 after it): 1e-10 of the line's parameter is at most
 * 1.3e-9 in model units (|P'| = 12.6 at most, the lines lying inside the
 * sphere's outline, |E'| <= 2 |P'|), far below the smallest eps_D here. */
#define T_AT_POLE 1e-10
/* The cubic march approaches a pole ending its run by at most 6 halvings
 * (PC_CUBIC_END_APPROACH = 1/64) and ends with one straight rest: up to 7
 * pieces for each of the 4 branch ends at a pole, beyond what straight
 * pcurves need (a meridian's (u, v) curve is straight: 2 pieces a branch).
 * Where it stalled at the pole it made pieces of half the distance left,
 * one after another, to the piece limit of 50,000. */
#define POLE_END_PIECES (4 * 7)

typedef struct pole_line {
    const char *name;
    double a[2], b[2]; /* (x, y) at t = 0 and t = 1 */
} pole_line;

/* One branch's exact projection: the line on the upper (side 1) or the
 * lower (side -1) hemisphere. */
typedef struct pole_side {
    const struct pole_line *line;
    double side;
} pole_side;

static void line_point(const struct pole_line *l, double t, double xy[2], double dxy[2])
{
    for (int c = 0; c < 2; ++c) {
        xy[c] = l->a[c] + t * (l->b[c] - l->a[c]);
        dxy[c] = l->b[c] - l->a[c];
    }
}

/* E(t), E'(t) and E''(t) of the line's projection onto the sphere. */
static void exact_on_sphere(const void *user, double t, pc_vec3 q[3])
{
    const pole_side *ps = user;
    double xy[2], d[2];
    line_point(ps->line, t, xy, d);
    const double rho2 = xy[0] * xy[0] + xy[1] * xy[1];
    const double z = ps->side * sqrt(R * R - rho2);
    const double rr = xy[0] * d[0] + xy[1] * d[1]; /* (rho^2)' / 2 */
    const double dd = d[0] * d[0] + d[1] * d[1];
    const double dz = -rr / z;
    q[0] = vec3(xy[0], xy[1], z);
    q[1] = vec3(d[0], d[1], dz);
    q[2] = vec3(0.0, 0.0, -(dd + dz * dz) / z);
}

/* Distance of (x, y) from the infinite line through l's ends. */
static double off_line(const pole_line *l, double x, double y)
{
    const double dx = l->b[0] - l->a[0], dy = l->b[1] - l->a[1];
    return fabs((x - l->a[0]) * dy - (y - l->a[1]) * dx) / hypot(dx, dy);
}

typedef struct pole_outcome {
    size_t pieces, cubic_pieces;
} pole_outcome;

/* Projects l along -z onto the sphere with pcurves of degree `degree` at
 * eps_D = rel_eps * size and checks it against the analytic projection. */
static pole_outcome check_line(const projcurve_surface *s, const pole_line *l, int degree,
                               double rel_eps)
{
    pole_outcome out = {0, 0};
    const double pts[6] = {l->a[0], l->a[1], H, l->b[0], l->b[1], H};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    CHECK(c != NULL);
    if (c == NULL)
        return out;
    const double eps_d = rel_eps * s->size, down[3] = {0.0, 0.0, -1.0};
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, EPS_T_DEG));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, degree));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, down, o, &r));
    projcurve_options_destroy(o);
    if (r == NULL) {
        projcurve_curve_destroy(c);
        return out;
    }
    CHECK(r->n_branches == 2); /* one on each hemisphere */
    CHECK(projcurve_result_failure_count(r) == 0);
    double hausdorff = 0.0, on_sphere = 0.0, on_ray = 0.0;
    int sides = 0;
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        if (b->n_pieces == 0) {
            CHECK(b->n_pieces > 0);
            continue;
        }
        const pole_side ps = {l, b->pieces[0].ctrl[2] > 0.0 ? 1.0 : -1.0};
        sides |= ps.side > 0.0 ? 1 : 2;
        const pc_oracle_measure m = pc_oracle_measure_branch(b, exact_on_sphere, &ps, NULL);
        hausdorff = fmax(hausdorff, m.hausdorff);
        CHECK(m.max_gap <= 1e-12 * s->size);
        CHECK(m.max_angle <= EPS_T_DEG * (1.0 + 1e-9));
        out.pieces += b->n_pieces;
        double t_lo = 1.0, t_hi = 0.0;
        for (size_t k = 0; k < b->n_pieces; ++k) {
            const pc_piece *pc = &b->pieces[k];
            int d = 0;
            CHECK_OK(projcurve_result_piece_pcurve(NULL, r, i, k, &d, NULL));
            out.cubic_pieces += d == 3;
            t_lo = fmin(t_lo, fmin(pc->t0, pc->t1));
            t_hi = fmax(t_hi, fmax(pc->t0, pc->t1));
            for (int j = 0; j <= PIECE_SAMPLES; ++j) {
                pc_vec3 x;
                pc_oracle_piece_eval(pc, (double)j / PIECE_SAMPLES, &x, NULL);
                on_sphere = fmax(on_sphere, fabs(vec3_norm(x) - R));
                on_ray = fmax(on_ray, off_line(l, x.x, x.y));
            }
        }
        /* the whole line is over the sphere; a branch from the pole may
         * start T_AT_POLE after it (the seed found there) */
        CHECK(t_lo <= T_AT_POLE && t_hi == 1.0);
    }
    printf("%-22s degree %d eps_D %.0e: %5zu pieces (%5zu cubic), Hausdorff %.3f eps_D, "
           "off the sphere %.2g, off the rays %.3f eps_D\n",
           l->name, degree, rel_eps, out.pieces, out.cubic_pieces, hausdorff / eps_d, on_sphere,
           on_ray / eps_d);
    CHECK(sides == 3);
    CHECK(hausdorff <= eps_d * (1.0 + HAUSDORFF_SLACK));
    CHECK(on_sphere <= ON_SPHERE_REL * R);
    CHECK(on_ray <= eps_d * (1.0 + HAUSDORFF_SLACK));
    CHECK(degree == 3 || out.cubic_pieces == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    return out;
}

/* The library's q' (the projector's derivatives, what the refinement's
 * uv tangent reads) against central differences of exact points (its
 * corrector at t -+ FD_DELTA), on the line 1e-3 beside the north pole,
 * where u' reaches ~2,000, at 1 - v from 4e-2 down to ~3e-5. The
 * difference quotient is off by FD_DELTA^2 q'''/6 (q''' ~ u' / tau^2 with
 * tau = 1e-3 / |P'| ~ 8e-5 the time to pass the pole: ~3e-6 relative) and
 * by the rounding of the exact points over FD_DELTA (the corrector ends
 * with a quadratic step, its points good to ~1e-15 in u and v: ~1e-8
 * relative). Measured: 2e-9 to 4e-7. */
#define FD_DELTA 1e-7
#define FD_REL 1e-5
#define TWO_PI 6.283185307179586
static void check_tangent_beside_pole(const projcurve_surface *s)
{
    const pole_line l = {"1e-3 beside the pole", {-6.0, -2.0 + 1e-3}, {6.0, 2.0 + 1e-3}};
    const double pts[6] = {l.a[0], l.a[1], H, l.b[0], l.b[1], H};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    CHECK(c != NULL);
    if (c == NULL)
        return;
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, s, c, vec3(0.0, 0.0, -1.0), 1e-12, 50);
    double worst = 0.0;
    for (int k = 1; k <= 5; ++k) {
        const double t = 0.5 - pow(10.0, -k); /* the pole is passed at t ~ 0.5 */
        double uv[3][2];
        for (int j = 0; j < 3; ++j) {
            const double tj = t + (j - 1) * FD_DELTA;
            double xy[2], d[2];
            line_point(&l, tj, xy, d);
            /* a start on the upper hemisphere: u = angle / 2 pi is within
             * the rational circle's distortion of the answer */
            const double angle = atan2(xy[1], xy[0]);
            uv[j][0] = (angle < 0.0 ? angle + TWO_PI : angle) / TWO_PI;
            uv[j][1] = 1.0 - 0.5 * hypot(xy[0], xy[1]) / R;
            int iterations = 0;
            CHECK(proj.correct(&proj, tj, uv[j], &iterations));
        }
        pc_proj_point q;
        CHECK(proj.derivatives(&proj, t, uv[1][0], uv[1][1], &q));
        const double fd[2] = {(uv[2][0] - uv[0][0]) / (2.0 * FD_DELTA),
                              (uv[2][1] - uv[0][1]) / (2.0 * FD_DELTA)};
        const double err = hypot(q.du - fd[0], q.dv - fd[1]) / hypot(fd[0], fd[1]);
        printf("q' at 1 - v = %.2g: (%.6g, %.6g), differences (%.6g, %.6g), relative %.2g\n",
               1.0 - uv[1][1], q.du, q.dv, fd[0], fd[1], err);
        worst = fmax(worst, err);
    }
    CHECK(worst <= FD_REL);
    projcurve_curve_destroy(c);
}

int main(void)
{
    projcurve_surface *s = shape_sphere(R);
    CHECK(s != NULL);
    if (s != NULL)
        check_tangent_beside_pole(s);
    const pole_line lines[] = {
        {"through the pole", {-6.0, -2.0}, {6.0, 2.0}},
        {"1e-3 beside the pole", {-6.0, -2.0 + 1e-3}, {6.0, 2.0 + 1e-3}},
        {"1e-4 beside the pole", {-6.0, -2.0 + 1e-4}, {6.0, 2.0 + 1e-4}},
        {"ending at the pole", {-6.0, -2.0}, {0.0, 0.0}},
        {"starting at the pole", {0.0, 0.0}, {4.0, -5.0}},
    };
    const double rel_eps[] = {1e-3, 1e-5, 1e-7};
    for (size_t e = 0; s != NULL && e < sizeof rel_eps / sizeof rel_eps[0]; ++e)
        for (size_t k = 0; k < sizeof lines / sizeof lines[0]; ++k) {
            const pole_outcome straight = check_line(s, &lines[k], 1, rel_eps[e]);
            const pole_outcome cubic = check_line(s, &lines[k], 3, rel_eps[e]);
            CHECK(cubic.pieces <= straight.pieces + POLE_END_PIECES);
        }
    projcurve_surface_destroy(s);
    return pc_test_finish("test_refine_pole");
}
