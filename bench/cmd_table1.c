/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench table1: the paper's Table 1 ([SY13] s5) on Example 1.
 * Both tracers run with the same constant parametric increment dt, with
 * composition and jump detection off, so that the figure is the tracing
 * alone (the initial polyline of the paper): time, mean estimation error
 * ([SY13] eq. 3.8) and points, RK4 first order against second order,
 * timed pair by pair in one run. The table is made twice: with the paper's
 * Newton tolerances (s5: eps1 = eps2 = 1e-10, NEWTON_TOL = 1e-10, whose
 * sine test is the paper's third), the replication, and with the library's
 * default (1e-12), stricter than the paper.
 */
#include <math.h>
#include <stdio.h>

#include "bench.h"
#include "example1.h"
#include "json.h"
#include "svg.h"

#define TABLE1_REPS 7
#define TABLE1_MIN_RUN_S 0.05
#define MAX_ROWS 8
/* [SY13] s5: "in all of our experiments eps1 = eps2 = 1e-10". */
#define TABLE1_PAPER_NEWTON_TOL 1e-10

static const double full_dts[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
static const double quick_dts[] = {1e-2, 1e-3};

/* [SY13] Table 1, for the printout: RK4 ms, ours ms (2.53 GHz Core 2). */
static const double paper_ms[5][2] = {
    {1.927, 1.486}, {14.443, 9.372}, {151.814, 96.347}, {1698.425, 1076.167},
    {17359.394, 7194.017}};

typedef struct tracer {
    const pcb_example1 *ex;
    projcurve_options *opts;
} tracer;

static int work_trace(void *user, size_t n)
{
    const tracer *t = user;
    for (size_t i = 0; i < n; ++i) {
        projcurve_result *r = NULL;
        const projcurve_status st = projcurve_project_directional(NULL, t->ex->surface,
                                                                  t->ex->curve, t->ex->dir,
                                                                  t->opts, &r);
        projcurve_result_destroy(r);
        if (st != PROJCURVE_OK)
            return 1;
    }
    return 0;
}

/* newton_tol 0: the library's default. */
static projcurve_status make_options(double dt, int method, double newton_tol,
                                     projcurve_options **out)
{
    projcurve_options *o = NULL;
    projcurve_status st = projcurve_options_create(NULL, &o);
    if (st == PROJCURVE_OK && newton_tol > 0.0)
        st = projcurve_options_set_double(NULL, o, PROJCURVE_OPT_NEWTON_TOL, newton_tol);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, dt);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, method);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(NULL, o, PROJCURVE_OPT_JUMP_DETECTION, 0);
    if (st != PROJCURVE_OK) {
        projcurve_options_destroy(o);
        return st;
    }
    *out = o;
    return PROJCURVE_OK;
}

typedef struct table1_row {
    double dt, points, rk4_points, rk4_ms, second_ms, speedup, rk4_error, second_error;
    double branches, rk4_branches;
} table1_row;

/* One traced run: points, mean estimation error, branch count. */
static int trace_stats(const tracer *t, double *points, double *error, double *branches)
{
    projcurve_context *ctx = NULL;
    projcurve_result *r = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    projcurve_status st =
        projcurve_project_directional(ctx, t->ex->surface, t->ex->curve, t->ex->dir, t->opts, &r);
    if (st == PROJCURVE_OK)
        st = projcurve_result_stat(ctx, r, PROJCURVE_STAT_POINTS, points);
    if (st == PROJCURVE_OK)
        st = projcurve_result_stat(ctx, r, PROJCURVE_STAT_AVG_ERROR, error);
    *branches = (double)projcurve_result_branch_count(r);
    const int ok = pcb_ok(ctx, st, "table1: projection");
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    return ok;
}

static int measure_row(const pcb_args *args, const pcb_example1 *ex, double dt,
                       double newton_tol, table1_row *row)
{
    tracer rk4 = {ex, NULL}, second = {ex, NULL};
    int ok = pcb_ok(NULL, make_options(dt, PROJCURVE_METHOD_RK4, newton_tol, &rk4.opts),
                    "table1: options") &&
             pcb_ok(NULL,
                    make_options(dt, PROJCURVE_METHOD_SECOND_ORDER, newton_tol, &second.opts),
                    "table1: options");
    row->dt = dt;
    ok = ok && trace_stats(&rk4, &row->rk4_points, &row->rk4_error, &row->rk4_branches) &&
         trace_stats(&second, &row->points, &row->second_error, &row->branches);
    if (ok) {
        const pcb_timing timing = pcb_timing_for(args, TABLE1_REPS, TABLE1_MIN_RUN_S);
        pcb_pair pair;
        ok = pcb_time_pair(&timing, work_trace, &rk4, work_trace, &second, &pair) == 0;
        row->rk4_ms = 1e3 * pair.a_s;
        row->second_ms = 1e3 * pair.b_s;
        row->speedup = pair.ratio;
    }
    projcurve_options_destroy(rk4.opts);
    projcurve_options_destroy(second.opts);
    return ok;
}

static void write_rows(pcb_json *j, const char *name, const table1_row *rows, size_t n)
{
    pcb_json_array_begin(j, name);
    for (size_t i = 0; i < n; ++i) {
        const table1_row *r = &rows[i];
        pcb_json_object_begin(j, NULL);
        pcb_json_number(j, "dt", r->dt);
        pcb_json_number(j, "points", r->points);
        pcb_json_number(j, "rk4_ms", r->rk4_ms);
        pcb_json_number(j, "second_order_ms", r->second_ms);
        pcb_json_number(j, "rk4_error", r->rk4_error);
        pcb_json_number(j, "second_order_error", r->second_error);
        pcb_json_number(j, "rk4_points", r->rk4_points);
        pcb_json_number(j, "rk4_over_second_order", r->speedup);
        pcb_json_number(j, "second_order_us_per_point", 1e3 * r->second_ms / r->points);
        pcb_json_number(j, "rk4_us_per_point", 1e3 * r->rk4_ms / r->rk4_points);
        pcb_json_object_end(j);
    }
    pcb_json_array_end(j);
}

/* rows: with the paper's Newton tolerances; default_rows: the library's. */
static void write_json(const pcb_args *args, const pcb_example1 *ex, const table1_row *rows,
                       const table1_row *default_rows, size_t n)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) != 0)
        return;
    pcb_json_object_begin(&j, NULL);
    write_rows(&j, "rows", rows, n);
    pcb_json_number(&j, "newton_tol", TABLE1_PAPER_NEWTON_TOL);
    write_rows(&j, "library_default_rows", default_rows, n);
    pcb_json_string(&j, "example1_source", ex->source);
    pcb_json_int(&j, "quick", args->quick);
    pcb_json_object_end(&j);
    if (pcb_json_close(&j) != 0)
        fprintf(stderr, "table1: cannot write %s\n", args->json_path);
}

/* Fig. 7 of the paper (time per point against dt) and the errors. */
static void write_svg(const pcb_args *args, const table1_row *rows, size_t n)
{
    if (!args->svg_path)
        return;
    double dt[MAX_ROWS], rk4[MAX_ROWS], ours[MAX_ROWS], erk4[MAX_ROWS], eours[MAX_ROWS];
    for (size_t i = 0; i < n; ++i) {
        dt[i] = rows[i].dt;
        rk4[i] = 1e3 * rows[i].rk4_ms / rows[i].rk4_points;
        ours[i] = 1e3 * rows[i].second_ms / rows[i].points;
        erk4[i] = rows[i].rk4_error;
        eours[i] = rows[i].second_error;
    }
    const pcb_series times[2] = {{"RK4 (first order)", dt, rk4, n},
                                 {"second order", dt, ours, n}};
    const pcb_series errors[2] = {{"RK4 (first order)", dt, erk4, n},
                                  {"second order", dt, eours, n}};
    const pcb_plot plots[2] = {
        {"Example 1: time per traced point", "parametric increment dt", "us per point", 1, 1,
         times, 2},
        {"Example 1: mean estimation error (eq. 3.8)", "parametric increment dt",
         "mean |predicted - corrected|", 1, 1, errors, 2}};
    if (pcb_svg_write(args->svg_path, plots, 2) != 0)
        fprintf(stderr, "table1: cannot write %s\n", args->svg_path);
}

/* One table: every dt with the given Newton tolerance, printed. */
static int measure_table(const pcb_args *args, const pcb_example1 *ex, const double *dts, size_t n,
                         double newton_tol, table1_row *rows)
{
    printf("%8s %9s %10s %10s %8s %12s %12s %9s %9s | %10s %10s\n", "dt", "points", "rk4_ms",
           "second_ms", "rk4/2nd", "rk4_err", "second_err", "us/pt_rk4", "us/pt_2nd", "paper_rk4",
           "paper_2nd");
    for (size_t i = 0; i < n; ++i) {
        table1_row *r = &rows[i];
        if (!measure_row(args, ex, dts[i], newton_tol, r))
            return 1;
        printf("%8.0e %9.0f %10.3f %10.3f %8.2f %12.3e %12.3e %9.4f %9.4f | %10.3f %10.3f\n",
               r->dt, r->points, r->rk4_ms, r->second_ms, r->speedup, r->rk4_error,
               r->second_error, 1e3 * r->rk4_ms / r->rk4_points, 1e3 * r->second_ms / r->points,
               paper_ms[i][0], paper_ms[i][1]);
        if (r->branches != 1.0 || r->rk4_branches != 1.0) {
            fprintf(stderr, "table1: dt %.0e: %.0f / %.0f branches, expected 1\n", r->dt,
                    r->rk4_branches, r->branches);
            return 1;
        }
    }
    return 0;
}

int pcb_cmd_table1(const pcb_args *args)
{
    pcb_example1 ex;
    if (!pcb_example1_load(args->data_dir, &ex))
        return 1;
    const double *dts = args->quick ? quick_dts : full_dts;
    const size_t n = args->quick ? sizeof quick_dts / sizeof *quick_dts
                                 : sizeof full_dts / sizeof *full_dts;
    pcb_print_banner("table1: Example 1, constant dt, tracing only (compose and jumps off)", args);
    printf("Example 1 from %s\n", ex.source);
    table1_row rows[MAX_ROWS], default_rows[MAX_ROWS];
    printf("Newton tolerances of the paper (s5): NEWTON_TOL = %g\n", TABLE1_PAPER_NEWTON_TOL);
    int rc = measure_table(args, &ex, dts, n, TABLE1_PAPER_NEWTON_TOL, rows);
    if (rc == 0) {
        printf("the library's default NEWTON_TOL (stricter than the paper)\n");
        rc = measure_table(args, &ex, dts, n, 0.0, default_rows);
    }
    if (rc == 0) {
        write_json(args, &ex, rows, default_rows, n);
        write_svg(args, rows, n);
    }
    pcb_example1_free(&ex);
    return rc;
}
