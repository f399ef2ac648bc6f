/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The cap of the jump sweep's narrowed checks (PC_SWEEP_MAX_NARROWED,
 * trace/tracer.h; docs/tracing.md "Small patches between two checks"),
 * reached through the public API: past it the sweep goes on with its
 * ordinary steps and the call returns LIMIT_REACHED, with the result
 * (its branches valid) and a message naming the cap and the t where the
 * narrowing stopped; the call stays bounded.
 *
 * The surface: N_SPANS spans in u of a bilinear B-spline over x in
 * [XA, XB], two in v: a floor (v in [0, 1/2], z = 0, y from -1 to
 * Y0 + DELTA) under the straight curve P(t) = (-50 + 100 t, Y0, 5), and a
 * wall (v in [1/2, 1], the plane y = Y0 + DELTA, z in [0, 1]) beside the
 * rays' plane y = Y0. DELTA is below the pad of the patch boxes (1e-9 of
 * the surface's size, step_skip.c), so each wall patch's box holds rays of
 * the curve that never meet the wall (parallel to them, DELTA away, 250
 * times the corrector's tolerance): every check over the wall finds a wall
 * patch wholly between its ray and the next one's, neither ray meets its
 * box and no branch crosses it, and its step is narrowed to about a patch
 * width. The wall has more patches than the cap counts checks, so the
 * cap is reached over it.
 *
 * Oracle (analytic): the rays along -z meet the floor on the line y = Y0,
 * z = 0, for x(t) in [XA, XB]: one branch from t_in = (XA + 50) / 100 to
 * t_out = (XB + 50) / 100, from side to side, every vertex on S (z = 0,
 * y = Y0) and on its ray (x = x(t)), also composed (composition on).
 *
 * Oracle (the count): a narrowed check over the wall starts in some patch
 * i and is cut while patch i + 1 lies wholly inside its step, so it ends
 * in patch i + 1: one patch per narrowed check. The checks before the
 * wall approach it by halvings, at most log2(1/128 / W) < 10 of them. So
 * the cap's t lies in the patch t_in + PC_SWEEP_MAX_NARROWED W less at
 * most those (32 allowed).
 *
 * The same cap at the lowest level: pc_sweep_narrow with a finder whose
 * step_may_skip always says yes halves every step to the floor
 * (2^-PC_SWEEP_NARROW_FLOOR_LOG2 of the domain), records the t of the
 * PC_SWEEP_MAX_NARROWED-th narrowed check, and past it returns the step
 * unchanged without asking the finder.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bounded_call.h"
#include "check.h"
#include "trace/tracer.h"

/* Above PC_SWEEP_MAX_NARROWED: the cap is reached over the wall (at
 * t ~ 0.76 of [t_in, t_out] = [0.097, 0.901]). */
#define N_SPANS 20000
/* Not dyadic in t: no check lands on a knot line by chance. */
#define XA (-40.3)
#define XB 40.1
#define Y0 0.0
/* Below the box pad, 1e-9 * ~80; far above the corrector's 1e-12 * ~80. */
#define DELTA 2e-8
#define CURVE_Z 5.0
#define HALF_LENGTH 50.0
/* Vertices on S and on their rays to this, model units (~100): the
 * corrector's tolerance is 1e-12 of the model size. */
#define ON_RAY_TOL 1e-10
/* The branch's ends in t: snapped onto the sides u = 0, 1, their vertex
 * on its ray to ON_RAY_TOL (x to 1e-10, t to 1e-12 at |P'| = 100), a
 * factor 10 left for the exit's location (as test_trace_small_patch.c). */
#define END_T_TOL 1e-11
/* The call's CPU time in Release is well under a second; this is a
 * guard against a sweep that no longer ends, scaled for slow builds. */
#define MAX_CPU_SECONDS 5.0

static double curve_x(double t)
{
    return -HALF_LENGTH + 2.0 * HALF_LENGTH * t;
}

static projcurve_surface *floor_and_wall(void)
{
    const size_t nu = N_SPANS + 1, nv = 3;
    double *ctrl = malloc(3 * nu * nv * sizeof *ctrl);
    double *ku = malloc((nu + 2) * sizeof *ku);
    CHECK(ctrl != NULL && ku != NULL);
    if (ctrl == NULL || ku == NULL) {
        free(ctrl);
        free(ku);
        return NULL;
    }
    static const double kv[5] = {0, 0, 0.5, 1, 1};
    /* rows (v): the floor's far side, the floor/wall edge, the wall's top */
    static const double row_y[3] = {-1.0, Y0 + DELTA, Y0 + DELTA};
    static const double row_z[3] = {0.0, 0.0, 1.0};
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            double *c = ctrl + 3 * (nu * j + i);
            c[0] = XA + (XB - XA) * (double)i / N_SPANS;
            c[1] = row_y[j];
            c[2] = row_z[j];
        }
    ku[0] = 0.0;
    for (size_t i = 0; i < nu; ++i)
        ku[i + 1] = (double)i / N_SPANS;
    ku[nu + 1] = 1.0;
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, nu, nv, ctrl, NULL, ku, kv, &s));
    free(ctrl);
    free(ku);
    return s;
}

static projcurve_curve *long_line(void)
{
    const double ctrl[6] = {-HALF_LENGTH, Y0, CURVE_Z, HALF_LENGTH, Y0, CURVE_Z};
    static const double knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

/* The t in "... by t = <t>; ..." of the message, NAN when absent. */
static double message_t(const char *msg)
{
    const char *at = msg != NULL ? strstr(msg, "by t = ") : NULL;
    return at != NULL ? strtod(at + strlen("by t = "), NULL) : NAN;
}

static void check_branch(const projcurve_surface *s, const projcurve_result *r)
{
    const size_t n = projcurve_result_branch_count(r);
    if (n != 1)
        printf("  %zu branches, expected 1\n", n);
    CHECK(n == 1);
    if (n != 1)
        return;
    const double t_in = (XA + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    const double t_out = (XB + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, &count, NULL));
    CHECK(start == PROJCURVE_START_BOUNDARY);
    CHECK(end == PROJCURVE_END_BOUNDARY);
    CHECK_NEAR(range[0], t_in, END_T_TOL);
    CHECK_NEAR(range[1], t_out, END_T_TOL);
    CHECK(count >= 2);
    double *pts = malloc(3 * (count > 0 ? count : 1) * sizeof *pts);
    CHECK(pts != NULL);
    if (pts == NULL)
        return;
    size_t got = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, count, pts, &got));
    CHECK(got == count);
    double worst_s = 0.0, worst_ray = 0.0;
    for (size_t k = 0; k < got; ++k) {
        double x[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, pts[3 * k + 1], pts[3 * k + 2], 0, x));
        /* on S: the floor, z = 0, y in [-1, Y0 + DELTA] */
        worst_s = fmax(worst_s, fabs(x[2]));
        /* on the ray along -z through P(t) */
        worst_ray = fmax(worst_ray, hypot(x[0] - curve_x(pts[3 * k]), x[1] - Y0));
    }
    free(pts);
    CHECK_NEAR(worst_s, 0.0, ON_RAY_TOL);
    CHECK_NEAR(worst_ray, 0.0, ON_RAY_TOL);
}

/* The directional projection along -z through the public API, with
 * composition on or off. */
static void api_case(const projcurve_surface *s, const projcurve_curve *c, int compose)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose));
    const double dir[3] = {0.0, 0.0, -1.0};
    projcurve_result *r = NULL;
    const double cpu0 = pc_bounded_cpu_now();
    const projcurve_status st = projcurve_project_directional(ctx, s, c, dir, o, &r);
    const double cpu = pc_bounded_cpu_now() - cpu0;
    const char *msg = projcurve_context_message(ctx);
    printf("  compose %d: status %d in %.3f s CPU: %s\n", compose, (int)st, cpu,
           msg != NULL ? msg : "(none)");

    CHECK_STATUS(st, PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(cpu < MAX_CPU_SECONDS * PC_TEST_SLOWDOWN);
    /* the message names the cap and the t */
    char cap[32];
    snprintf(cap, sizeof cap, "%d checks", PC_SWEEP_MAX_NARROWED);
    CHECK(msg != NULL && strstr(msg, "narrowed") != NULL && strstr(msg, cap) != NULL);
    const double t_in = (XA + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    const double w = (XB - XA) / N_SPANS / (2.0 * HALF_LENGTH);
    const double patch = (message_t(msg) - t_in) / w;
    if (!(patch >= PC_SWEEP_MAX_NARROWED - 32 && patch <= PC_SWEEP_MAX_NARROWED))
        printf("  cap in wall patch %.3f, expected in [%d, %d]\n", patch,
               PC_SWEEP_MAX_NARROWED - 32, PC_SWEEP_MAX_NARROWED);
    CHECK(patch >= PC_SWEEP_MAX_NARROWED - 32 && patch <= PC_SWEEP_MAX_NARROWED);
    /* the result is kept, and valid */
    CHECK(r != NULL);
    if (r != NULL)
        check_branch(s, r);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
}

/* A finder whose steps always may skip a patch; counts its calls. */
typedef struct always_skips {
    pc_seed_finder base;
    size_t calls;
} always_skips;

static int always_skip(pc_seed_finder *self, double ta, double tb, const pc_sweep_trail *trail)
{
    (void)ta;
    (void)tb;
    (void)trail;
    ((always_skips *)self)->calls++;
    return 1;
}

static void low_level_case(void)
{
    projcurve_result r;
    memset(&r, 0, sizeof r);
    pc_tracer tr;
    memset(&tr, 0, sizeof tr);
    tr.t_begin = 0.0;
    tr.t_end = 1.0;
    tr.r = &r;
    tr.narrow_capped_at = NAN;
    always_skips f;
    memset(&f, 0, sizeof f);
    f.base.step_may_skip = always_skip;
    /* dyadic t and steps: every value below is exact */
    const double step = 1.0 / 128.0, floor_dt = ldexp(1.0, -PC_SWEEP_NARROW_FLOOR_LOG2);
    const size_t halvings = PC_SWEEP_NARROW_FLOOR_LOG2 - 7; /* 1/128 down to the floor */
    double t = 0.0;
    size_t bad = 0;
    for (size_t k = 1; k <= PC_SWEEP_MAX_NARROWED + 3; ++k) {
        int narrowed = -1;
        const size_t calls = f.calls;
        const double dt = pc_sweep_narrow(&tr, &f.base, t, step, &narrowed);
        const int capped = k > PC_SWEEP_MAX_NARROWED;
        /* before the cap: halved to the floor, the finder asked once per
         * halving; past it: the step unchanged, the finder not asked */
        const int ok = capped ? dt == step && narrowed == 0 && f.calls == calls
                              : dt == floor_dt && narrowed == 1 && f.calls - calls == halvings;
        if (!ok && bad++ < 3)
            printf("  check %zu at t %.17g: step %.17g narrowed %d, %zu calls\n", k, t, dt,
                   narrowed, f.calls - calls);
        if (k == PC_SWEEP_MAX_NARROWED)
            CHECK(tr.narrow_capped_at == t);
        else if (k < PC_SWEEP_MAX_NARROWED)
            CHECK(isnan(tr.narrow_capped_at));
        t += dt;
    }
    CHECK(bad == 0);
    CHECK(tr.n_narrowed == PC_SWEEP_MAX_NARROWED);
    /* the t of the cap: PC_SWEEP_MAX_NARROWED - 1 floor steps from 0 */
    CHECK(tr.narrow_capped_at == (PC_SWEEP_MAX_NARROWED - 1) * floor_dt);
}

int main(void)
{
    pc_test_hang_guard(60);
    low_level_case();
    const double build0 = pc_bounded_cpu_now();
    projcurve_surface *s = floor_and_wall();
    printf("  surface of %d x 2 patches built in %.3f s CPU\n", N_SPANS,
           pc_bounded_cpu_now() - build0);
    projcurve_curve *c = long_line();
    for (int compose = 0; compose <= 1; ++compose)
        api_case(s, c, compose);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_trace_narrow_cap");
}
