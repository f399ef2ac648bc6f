/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench scaling: time of the whole directional projection against
 * 1/eps_D, against the number of patches (one shape, knots refined exactly:
 * 1 ... 10,000 patches) and against the curve length, with the growth
 * exponents fitted by least squares. Aims (benchmark issue): no faster than
 * (1/eps_D)^(1/2) and log(patches).
 */
#include <math.h>
#include <stdio.h>

#include "bench.h"
#include "fit.h"
#include "json.h"
#include "measure.h"
#include "shapes.h"
#include "svg.h"

#define SCALING_REPS 7
#define SCALING_MIN_RUN_S 0.02
#define CURVE_HEIGHT 40.0          /* the Lissajous curve flies this high */
#define BASE_T_END 6.283185307179586
#define BASE_TOL_DIST 1e-3
#define EPS_SPANS 16               /* surface of the eps_D and length series */
#define LENGTH_SAMPLES 20000       /* for the numerical curve length */
#define MAX_POINTS 16

static const double full_eps[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
static const double quick_eps[] = {1e-1, 1e-2};
static const size_t full_spans[] = {1, 2, 4, 10, 20, 40, 100};
static const size_t quick_spans[] = {1, 4};
static const double full_lengths[] = {0.25, 0.5, 1.0, 2.0, 4.0, 8.0};  /* x BASE_T_END */
static const double quick_lengths[] = {0.5, 1.0};

static const double down[3] = {0.0, 0.0, -1.0};

typedef struct series {
    double x[MAX_POINTS], ms[MAX_POINTS], pieces[MAX_POINTS], points[MAX_POINTS];
    size_t n;
} series;

typedef struct scaling_work {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    const projcurve_options *opts;
} scaling_work;

static int work_project(void *user, size_t n)
{
    const scaling_work *w = user;
    for (size_t i = 0; i < n; ++i) {
        projcurve_result *r = NULL;
        const projcurve_status st =
            projcurve_project_directional(NULL, w->surface, w->curve, down, w->opts, &r);
        projcurve_result_destroy(r);
        if (st != PROJCURVE_OK)
            return 1;
    }
    return 0;
}

/* Times one configuration and appends (x, ms, pieces, points) to s. */
static int measure_point(const pcb_args *args, const projcurve_surface *surface,
                         const projcurve_curve *curve, double tol, double x, series *s)
{
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    projcurve_result *r = NULL;
    int ok = 0;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    projcurve_status st = projcurve_options_create(ctx, &opts);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_double(ctx, opts, PROJCURVE_OPT_TOL_DISTANCE, tol);
    if (st == PROJCURVE_OK)
        st = projcurve_project_directional(ctx, surface, curve, down, opts, &r);
    pcb_measurement m;
    pcb_measurement_clear(&m);
    if (st == PROJCURVE_OK)
        st = pcb_result_shape(ctx, r, &m);
    if (pcb_ok(ctx, st, "scaling: projection")) {
        const pcb_timing timing = pcb_timing_for(args, SCALING_REPS, SCALING_MIN_RUN_S);
        scaling_work w = {surface, curve, opts};
        double seconds = NAN;
        ok = pcb_time_median(&timing, work_project, &w, &seconds) == 0;
        s->x[s->n] = x;
        s->ms[s->n] = 1e3 * seconds;
        s->pieces[s->n] = m.pieces;
        s->points[s->n] = m.points;
        printf("  %12.4g %10.3f %8.0f %9.0f %8.0f\n", x, 1e3 * seconds, m.pieces, m.points,
               m.branches);
        ++s->n;
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    return ok;
}

static double curve_length(const projcurve_curve *curve)
{
    double t0, t1, prev[3], len = 0.0;
    projcurve_curve_domain(NULL, curve, &t0, &t1);
    projcurve_curve_eval(NULL, curve, t0, 0, prev);
    for (int i = 1; i <= LENGTH_SAMPLES; ++i) {
        double p[3];
        projcurve_curve_eval(NULL, curve, t0 + (t1 - t0) * i / LENGTH_SAMPLES, 0, p);
        len += hypot(hypot(p[0] - prev[0], p[1] - prev[1]), p[2] - prev[2]);
        prev[0] = p[0], prev[1] = p[1], prev[2] = p[2];
    }
    return len;
}

static int run_eps(const pcb_args *args, const pcb_lissajous *liss, series *s)
{
    projcurve_surface *surface = NULL;
    projcurve_curve *curve = NULL;
    int ok = pcb_ok(NULL, pcb_make_bumpy_surface(NULL, EPS_SPANS, &surface), "scaling") &&
             pcb_ok(NULL, pcb_make_lissajous(NULL, liss, BASE_T_END, &curve), "scaling");
    const size_t n = args->quick ? sizeof quick_eps / sizeof *quick_eps
                                 : sizeof full_eps / sizeof *full_eps;
    printf("time against 1/eps_D (bicubic %dx%d spans, Lissajous curve)\n", EPS_SPANS, EPS_SPANS);
    printf("  %12s %10s %8s %9s %8s\n", "1/eps_D", "ms", "pieces", "points", "branches");
    for (size_t i = 0; ok && i < n; ++i) {
        const double eps = (args->quick ? quick_eps : full_eps)[i];
        ok = measure_point(args, surface, curve, eps, 1.0 / eps, s);
    }
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surface);
    return ok;
}

static int run_patches(const pcb_args *args, const pcb_lissajous *liss, series *s)
{
    projcurve_curve *curve = NULL;
    int ok = pcb_ok(NULL, pcb_make_lissajous(NULL, liss, BASE_T_END, &curve), "scaling");
    const size_t n = args->quick ? sizeof quick_spans / sizeof *quick_spans
                                 : sizeof full_spans / sizeof *full_spans;
    printf("time against patches (one bicubic shape, knots refined)\n");
    printf("  %12s %10s %8s %9s %8s\n", "patches", "ms", "pieces", "points", "branches");
    for (size_t i = 0; ok && i < n; ++i) {
        const size_t spans = (args->quick ? quick_spans : full_spans)[i];
        projcurve_surface *surface = NULL;
        ok = pcb_ok(NULL, pcb_make_refined_patch(NULL, spans, &surface), "scaling") &&
             measure_point(args, surface, curve, BASE_TOL_DIST, (double)(spans * spans), s);
        projcurve_surface_destroy(surface);
    }
    projcurve_curve_destroy(curve);
    return ok;
}

static int run_length(const pcb_args *args, const pcb_lissajous *liss, series *s)
{
    projcurve_surface *surface = NULL;
    int ok = pcb_ok(NULL, pcb_make_bumpy_surface(NULL, EPS_SPANS, &surface), "scaling");
    const size_t n = args->quick ? sizeof quick_lengths / sizeof *quick_lengths
                                 : sizeof full_lengths / sizeof *full_lengths;
    printf("time against curve length (same surface, longer Lissajous runs)\n");
    printf("  %12s %10s %8s %9s %8s\n", "length", "ms", "pieces", "points", "branches");
    for (size_t i = 0; ok && i < n; ++i) {
        const double t_end = BASE_T_END * (args->quick ? quick_lengths : full_lengths)[i];
        projcurve_curve *curve = NULL;
        ok = pcb_ok(NULL, pcb_make_lissajous(NULL, liss, t_end, &curve), "scaling") &&
             measure_point(args, surface, curve, BASE_TOL_DIST, curve_length(curve), s);
        projcurve_curve_destroy(curve);
    }
    projcurve_surface_destroy(surface);
    return ok;
}

static void write_series(pcb_json *j, const char *key, const char *x_name, const series *s)
{
    pcb_json_array_begin(j, key);
    for (size_t i = 0; i < s->n; ++i) {
        pcb_json_object_begin(j, NULL);
        pcb_json_number(j, x_name, s->x[i]);
        pcb_json_number(j, "ms", s->ms[i]);
        pcb_json_number(j, "pieces", s->pieces[i]);
        pcb_json_number(j, "points", s->points[i]);
        pcb_json_object_end(j);
    }
    pcb_json_array_end(j);
}

typedef struct exponents {
    double eps_ms, eps_pieces, patches_ms, patches_log_a, patches_log_b, length_ms;
} exponents;

static void write_outputs(const pcb_args *args, const series *se, const series *sp,
                          const series *sl, const exponents *e)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) == 0) {
        pcb_json_object_begin(&j, NULL);
        write_series(&j, "eps", "inv_eps_d", se);
        write_series(&j, "patches", "patches", sp);
        write_series(&j, "length", "length", sl);
        pcb_json_object_begin(&j, "exponents");
        pcb_json_number(&j, "ms_vs_inv_eps_d", e->eps_ms);
        pcb_json_number(&j, "pieces_vs_inv_eps_d", e->eps_pieces);
        pcb_json_number(&j, "ms_vs_patches", e->patches_ms);
        pcb_json_number(&j, "ms_per_ln_patches", e->patches_log_b);
        pcb_json_number(&j, "ms_vs_length", e->length_ms);
        pcb_json_object_end(&j);
        pcb_json_int(&j, "quick", args->quick);
        pcb_json_object_end(&j);
        if (pcb_json_close(&j) != 0)
            fprintf(stderr, "scaling: cannot write %s\n", args->json_path);
    }
    if (!args->svg_path)
        return;
    const pcb_series s_eps[1] = {{"ms", se->x, se->ms, se->n}};
    const pcb_series s_pieces[1] = {{"composed pieces", se->x, se->pieces, se->n}};
    const pcb_series s_patch[1] = {{"ms", sp->x, sp->ms, sp->n}};
    const pcb_series s_len[1] = {{"ms", sl->x, sl->ms, sl->n}};
    const pcb_plot plots[4] = {
        {"time against 1/eps_D", "1 / eps_D", "ms", 1, 1, s_eps, 1},
        {"pieces against 1/eps_D", "1 / eps_D", "pieces", 1, 1, s_pieces, 1},
        {"time against patches", "patches", "ms", 1, 0, s_patch, 1},
        {"time against curve length", "curve length", "ms", 1, 1, s_len, 1}};
    if (pcb_svg_write(args->svg_path, plots, 4) != 0)
        fprintf(stderr, "scaling: cannot write %s\n", args->svg_path);
}

int pcb_cmd_scaling(const pcb_args *args)
{
    const pcb_lissajous liss = {CURVE_HEIGHT};
    series se = {.n = 0}, sp = {.n = 0}, sl = {.n = 0};
    pcb_print_banner("scaling: whole directional projection along -z", args);
    const int ok = run_eps(args, &liss, &se) && run_patches(args, &liss, &sp) &&
                   run_length(args, &liss, &sl);
    exponents e;
    e.eps_ms = pcb_fit_power(se.x, se.ms, se.n);
    e.eps_pieces = pcb_fit_power(se.x, se.pieces, se.n);
    e.patches_ms = pcb_fit_power(sp.x, sp.ms, sp.n);
    pcb_fit_log(sp.x, sp.ms, sp.n, &e.patches_log_a, &e.patches_log_b);
    e.length_ms = pcb_fit_power(sl.x, sl.ms, sl.n);
    printf("exponents: ms ~ (1/eps_D)^%.3f, pieces ~ (1/eps_D)^%.3f, ms ~ patches^%.3f "
           "(ms = %.3f + %.4f ln patches), ms ~ length^%.3f\n",
           e.eps_ms, e.eps_pieces, e.patches_ms, e.patches_log_a, e.patches_log_b, e.length_ms);
    write_outputs(args, &se, &sp, &sl, &e);
    return ok ? 0 : 1;
}
