/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench cases: every shared case (tests/data/cases) and the
 * real-surface cases: time of the whole projection, branches, composed
 * pieces, control points, worst joint angle and the deviation from the
 * exact projection measured independently on dense samples (deviation.h).
 * Then the paper's Table 2 columns on Example 1 and the real surfaces for
 * eps_D x eps_T, with the number of pieces a uniform split would need.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "cases.h"
#include "deviation.h"
#include "exact.h"
#include "json.h"
#include "measure.h"
#include "svg.h"

#define CASES_REPS 7
#define CASES_MIN_RUN_S 0.02
#define MAX_TABLE2_ROWS 64

static const double full_eps_d[] = {1e-2, 1e-3, 1e-4, 1e-5};
static const double full_eps_t[] = {10.0, 1.0};
static const double quick_eps_d[] = {1e-2};
static const double quick_eps_t[] = {10.0};

/* Table 2 runs on these (real surfaces scale eps_D by size / 100, as if
 * they were 100 units across like Example 1). */
static const char *const table2_cases[] = {"song_yong_example1", "real_lens_directional",
                                           "real_joinsurf85_directional"};

typedef struct case_row {
    const pcb_case *c;
    pcb_measurement m;
    pcb_measurement straight; /* the same with straight pcurves (PCURVE_DEGREE 1) */
    pcb_method_pair methods;
    char status[PCB_CASE_ERROR_MAX + 16];
} case_row;

typedef struct table2_row {
    const char *name;
    int pcurve_degree;
    double eps_d, eps_t;
    pcb_measurement m;
} table2_row;

static void print_case(const case_row *r)
{
    const pcb_measurement *m = &r->m;
    const int exp = r->c->expected_branches;
    printf("%-30s %-5s %9.3f %4.0f/%-3s %7.0f %7.0f %8.0f %9.2f %11.3e %11.3e %s\n", r->c->name,
           r->c->orthogonal ? "orth" : "dir", m->ms, m->branches,
           exp < 0 ? "?" : (exp == (int)m->branches ? "ok" : "BAD"), m->pieces, m->control_points,
           m->points, m->max_joint_deg, m->deviation.hausdorff, r->c->tol_dist, r->status);
}

static void write_case_json(pcb_json *j, const case_row *r)
{
    const pcb_measurement *m = &r->m;
    pcb_json_object_begin(j, NULL);
    pcb_json_string(j, "name", r->c->name);
    pcb_json_string(j, "mode", r->c->orthogonal ? "orthogonal" : "directional");
    pcb_json_string(j, "status", r->status[0] ? r->status : "ok");
    pcb_json_number(j, "ms", m->ms);
    pcb_json_number(j, "branches", m->branches);
    pcb_json_int(j, "expected_branches", r->c->expected_branches);
    pcb_json_number(j, "pieces", m->pieces);
    pcb_json_number(j, "control_points", m->control_points);
    pcb_json_number(j, "points", m->points);
    pcb_json_number(j, "max_joint_angle_deg", m->max_joint_deg);
    pcb_json_number(j, "tol_dist", r->c->tol_dist);
    pcb_json_number(j, "tol_angle_deg", r->c->tol_angle_deg);
    pcb_json_number(j, "deviation", m->deviation.hausdorff);
    pcb_json_number(j, "result_to_exact", m->deviation.result_to_exact);
    pcb_json_number(j, "exact_to_result", m->deviation.exact_to_result);
    pcb_json_number(j, "straight_ms", r->straight.ms);
    pcb_json_number(j, "straight_pieces", r->straight.pieces);
    pcb_json_number(j, "straight_control_points", r->straight.control_points);
    pcb_json_number(j, "straight_max_joint_angle_deg", r->straight.max_joint_deg);
    pcb_json_number(j, "straight_deviation", r->straight.deviation.hausdorff);
    pcb_json_number(j, "compact_poles", m->compact_poles);
    pcb_json_number(j, "compact_degree", m->compact_degree);
    pcb_json_number(j, "compact_deviation", m->compact_deviation.hausdorff);
    pcb_json_number(j, "pcurve_poles", m->pcurve_poles);
    pcb_json_number(j, "pcurve_degree", m->pcurve_degree);
    pcb_json_number(j, "fit_ms", m->fit_ms);
    pcb_json_number(j, "straight_compact_poles", r->straight.compact_poles);
    pcb_json_number(j, "straight_pcurve_poles", r->straight.pcurve_poles);
    pcb_json_number(j, "straight_fit_ms", r->straight.fit_ms);
    pcb_json_object_end(j);
}

static void write_table2_json(pcb_json *j, const table2_row *r)
{
    pcb_json_object_begin(j, NULL);
    pcb_json_string(j, "case", r->name);
    pcb_json_int(j, "pcurve_degree", r->pcurve_degree);
    pcb_json_number(j, "eps_d", r->eps_d);
    pcb_json_number(j, "eps_t_deg", r->eps_t);
    pcb_json_number(j, "pieces", r->m.pieces);
    pcb_json_number(j, "control_points", r->m.control_points);
    pcb_json_number(j, "max_joint_angle_deg", r->m.max_joint_deg);
    pcb_json_number(j, "ms", r->m.ms);
    pcb_json_number(j, "deviation", r->m.deviation.hausdorff);
    pcb_json_number(j, "uniform_pieces", r->m.uniform_pieces);
    pcb_json_object_end(j);
}

static void write_methods_json(pcb_json *j, const case_row *r)
{
    const pcb_method_pair *p = &r->methods;
    pcb_json_object_begin(j, NULL);
    pcb_json_string(j, "name", r->c->name);
    pcb_json_number(j, "second_order_ms", p->second_ms);
    pcb_json_number(j, "rk4_ms", p->rk4_ms);
    pcb_json_number(j, "rk4_over_second_order", p->rk4_over_second);
    pcb_json_number(j, "second_order_points", p->second_points);
    pcb_json_number(j, "rk4_points", p->rk4_points);
    pcb_json_object_end(j);
}

static void write_outputs(const pcb_args *args, const case_row *rows, size_t n,
                          const table2_row *t2, size_t n2)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) == 0) {
        pcb_json_object_begin(&j, NULL);
        pcb_json_array_begin(&j, "cases");
        for (size_t i = 0; i < n; ++i)
            write_case_json(&j, &rows[i]);
        pcb_json_array_end(&j);
        pcb_json_array_begin(&j, "methods");
        for (size_t i = 0; i < n; ++i)
            if (!rows[i].c->error[0])
                write_methods_json(&j, &rows[i]);
        pcb_json_array_end(&j);
        pcb_json_array_begin(&j, "table2");
        for (size_t i = 0; i < n2; ++i)
            write_table2_json(&j, &t2[i]);
        pcb_json_array_end(&j);
        pcb_json_int(&j, "quick", args->quick);
        pcb_json_object_end(&j);
        if (pcb_json_close(&j) != 0)
            fprintf(stderr, "cases: cannot write %s\n", args->json_path);
    }
    if (!args->svg_path)
        return;
    /* Pieces and uniform pieces against 1/eps_D for Example 1 at each eps_T. */
    double x[4][MAX_TABLE2_ROWS], y[4][MAX_TABLE2_ROWS], yu[4][MAX_TABLE2_ROWS],
        ms[4][MAX_TABLE2_ROWS];
    size_t m[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < n2; ++i) {
        if (strcmp(t2[i].name, table2_cases[0]) != 0)
            continue;
        const int k = (t2[i].eps_t > 5.0 ? 0 : 1) + (t2[i].pcurve_degree == 3 ? 2 : 0);
        x[k][m[k]] = 1.0 / t2[i].eps_d;
        y[k][m[k]] = t2[i].m.pieces;
        yu[k][m[k]] = t2[i].m.uniform_pieces;
        ms[k][m[k]] = t2[i].m.ms;
        ++m[k];
    }
    const pcb_series pieces[6] = {{"pieces, eps_T 10 deg", x[0], y[0], m[0]},
                                  {"pieces, eps_T 1 deg", x[1], y[1], m[1]},
                                  {"uniform split, eps_T 10 deg", x[0], yu[0], m[0]},
                                  {"uniform split, eps_T 1 deg", x[1], yu[1], m[1]},
                                  {"cubic pcurves, eps_T 10 deg", x[2], y[2], m[2]},
                                  {"cubic pcurves, eps_T 1 deg", x[3], y[3], m[3]}};
    const pcb_series times[4] = {{"eps_T 10 deg", x[0], ms[0], m[0]},
                                 {"eps_T 1 deg", x[1], ms[1], m[1]},
                                 {"cubic pcurves, eps_T 10 deg", x[2], ms[2], m[2]},
                                 {"cubic pcurves, eps_T 1 deg", x[3], ms[3], m[3]}};
    const pcb_plot plots[2] = {
        {"Example 1: composed pieces", "1 / eps_D", "pieces", 1, 1, pieces, 6},
        {"Example 1: whole projection", "1 / eps_D", "ms", 1, 1, times, 4}};
    if (pcb_svg_write(args->svg_path, plots, 2) != 0)
        fprintf(stderr, "cases: cannot write %s\n", args->svg_path);
}

/* Table 2 rows for one case with pcurves of the given degree; returns 0
 * when every row ran. */
static int run_table2(const pcb_args *args, const pcb_case *c, double scale, int pcurve_degree,
                      table2_row *rows, size_t *n_rows)
{
    const double *eps_d = args->quick ? quick_eps_d : full_eps_d;
    const double *eps_t = args->quick ? quick_eps_t : full_eps_t;
    const size_t nd = args->quick ? 1 : sizeof full_eps_d / sizeof *full_eps_d;
    const size_t nt = args->quick ? 1 : sizeof full_eps_t / sizeof *full_eps_t;
    const pcb_timing timing = pcb_timing_for(args, CASES_REPS, CASES_MIN_RUN_S);
    const pcb_sampling sampling = pcb_sampling_for(args->quick);
    int rc = 0;
    for (size_t t = 0; t < nt; ++t) {
        for (size_t d = 0; d < nd && *n_rows < MAX_TABLE2_ROWS; ++d) {
            table2_row *r = &rows[(*n_rows)++];
            pcb_case variant = *c;
            variant.tol_dist = eps_d[d] * scale;
            variant.tol_angle_deg = eps_t[t];
            variant.pcurve_degree = pcurve_degree;
            r->name = c->name;
            r->pcurve_degree = pcurve_degree;
            r->eps_d = variant.tol_dist;
            r->eps_t = eps_t[t];
            char status[160];
            if (pcb_measure_case(&variant, &timing, &sampling, pcurve_degree != 3, &r->m, status,
                                 sizeof status) != 0) {
                fprintf(stderr, "cases: table2 %s: %s\n", c->name, status);
                rc = 1;
            }
            printf("%-24s %5s %10.1e %6.0f %7.0f %8.0f %9.2f %10.3f %11.3e %9.0f\n", r->name,
                   pcurve_degree == 3 ? "cubic" : "line", r->eps_d,
                   r->eps_t, r->m.pieces, r->m.control_points, r->m.max_joint_deg, r->m.ms,
                   r->m.deviation.hausdorff, r->m.uniform_pieces);
        }
    }
    return rc;
}

static double model_scale(const pcb_case *c)
{
    if (strncmp(c->name, "real_", 5) != 0)
        return 1.0;
    double box[6];
    projcurve_surface_bounds(NULL, c->surface, box);
    return sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                (box[5] - box[2]) * (box[5] - box[2])) /
           100.0;
}

int pcb_cmd_cases(const pcb_args *args)
{
    pcb_case_list list;
    /* Quick runs leave the real surfaces out: their fine tolerances make
     * the accuracy check the slowest part, and the manifest cases cover
     * every code path. */
    const pcb_real_cases real = args->quick ? PCB_REAL_NONE : PCB_REAL_ALL;
    if (pcb_cases_load(args->data_dir, real, &list) != 0)
        return 2;
    case_row *rows = calloc(list.n ? list.n : 1, sizeof *rows);
    table2_row *t2 = calloc(MAX_TABLE2_ROWS, sizeof *t2);
    size_t n2 = 0;
    int rc = 0;
    if (!rows || !t2) {
        rc = 1;
        goto cleanup;
    }
    pcb_print_banner("cases: whole projection, deviation measured on dense exact samples", args);
    printf("%-30s %-5s %9s %8s %7s %7s %8s %9s %11s %11s\n", "case", "mode", "ms", "branches",
           "pieces", "ctrl", "points", "joint_deg", "deviation", "eps_D");
    const pcb_timing timing = pcb_timing_for(args, CASES_REPS, CASES_MIN_RUN_S);
    const pcb_sampling sampling = pcb_sampling_for(args->quick);
    for (size_t i = 0; i < list.n; ++i) {
        case_row *r = &rows[i];
        r->c = &list.items[i];
        pcb_measurement_clear(&r->m);
        if (r->c->error[0]) {
            /* Real files the reader cannot take are reported, not fatal. */
            snprintf(r->status, sizeof r->status, "not loaded: %s", r->c->error);
            if (strncmp(r->c->name, "real_", 5) != 0)
                rc = 1;
        } else if (pcb_measure_case(r->c, &timing, &sampling, 0, &r->m, r->status,
                                    sizeof r->status) != 0) {
            rc = 1;
        } else if (r->c->expected_branches >= 0 &&
                   (double)r->c->expected_branches != r->m.branches) {
            snprintf(r->status, sizeof r->status, "expected %d branches",
                     r->c->expected_branches);
        }
        print_case(r);
        fflush(stdout);
    }
    printf("\nstraight pcurves (PCURVE_DEGREE 1) against the default (cubic) ones, same "
           "tolerances\n");
    printf("%-30s %9s %9s %7s %7s %9s %11s %11s %8s\n", "case", "cubic_ms", "line_ms", "cub_pc",
           "line_pc", "joint_deg", "deviation", "eps_D", "line/cub");
    for (size_t i = 0; i < list.n; ++i) {
        case_row *r = &rows[i];
        pcb_measurement_clear(&r->straight);
        if (r->c->error[0])
            continue;
        pcb_case straight = *r->c;
        straight.pcurve_degree = 1;
        char status[PCB_CASE_ERROR_MAX + 16] = "";
        if (pcb_measure_case(&straight, &timing, &sampling, 0, &r->straight, status,
                             sizeof status) != 0) {
            fprintf(stderr, "cases: straight %s: %s\n", r->c->name, status);
            rc = 1;
        }
        printf("%-30s %9.3f %9.3f %7.0f %7.0f %9.2f %11.3e %11.3e %8.2f\n", r->c->name, r->m.ms,
               r->straight.ms, r->m.pieces, r->straight.pieces, r->straight.max_joint_deg,
               r->straight.deviation.hausdorff, r->c->tol_dist, r->straight.ms / r->m.ms);
        fflush(stdout);
    }
    printf("\ncompact results (src/fit/): poles and degree of the 3D curves and pcurves "
           "(all branches), their deviation, the time the fits add; default (cubic) / "
           "straight pieces\n");
    printf("%-30s %8s %9s %6s %9s %6s %11s %9s %8s %9s %9s\n", "case", "ctrl", "3d_poles",
           "3d_deg", "uv_poles", "uv_deg", "deviation", "fit_ms", "fit_%", "str_3d", "str_uv");
    for (size_t i = 0; i < list.n; ++i) {
        const case_row *r = &rows[i];
        if (r->c->error[0])
            continue;
        const pcb_measurement *m = &r->m;
        printf("%-30s %8.0f %9.0f %6.0f %9.0f %6.0f %11.3e %9.3f %8.1f %9.0f %9.0f\n",
               r->c->name, m->control_points, m->compact_poles, m->compact_degree,
               m->pcurve_poles, m->pcurve_degree, m->compact_deviation.hausdorff, m->fit_ms,
               100.0 * m->fit_ms / m->ms, r->straight.compact_poles, r->straight.pcurve_poles);
    }
    printf("\nsecond order against RK4, whole projection, same tolerances\n");
    printf("%-30s %10s %10s %8s %9s %9s\n", "case", "second_ms", "rk4_ms", "rk4/2nd", "pts_2nd",
           "pts_rk4");
    for (size_t i = 0; i < list.n; ++i) {
        case_row *r = &rows[i];
        if (r->c->error[0])
            continue;
        char status[PCB_CASE_ERROR_MAX];
        if (pcb_compare_methods(r->c, &timing, &r->methods, status, sizeof status) != 0) {
            fprintf(stderr, "cases: methods %s: %s\n", r->c->name, status);
            rc = 1;
        }
        printf("%-30s %10.3f %10.3f %8.2f %9.0f %9.0f\n", r->c->name, r->methods.second_ms,
               r->methods.rk4_ms, r->methods.rk4_over_second, r->methods.second_points,
               r->methods.rk4_points);
        fflush(stdout);
    }
    printf("\nTable 2 ([SY13]): eps_D x eps_T%s\n",
           args->quick ? "" : "; real surfaces: eps_D x size/100");
    printf("%-24s %5s %10s %6s %7s %8s %9s %10s %11s %9s\n", "case", "uv", "eps_D", "eps_T",
           "pieces", "ctrl", "joint_deg", "ms", "deviation", "uniform");
    /* Quick runs prove the Table 2 path on Example 1 alone. */
    const size_t n_table2 = args->quick ? 1 : sizeof table2_cases / sizeof *table2_cases;
    for (size_t k = 0; k < n_table2; ++k)
        for (size_t i = 0; i < list.n; ++i)
            if (!strcmp(list.items[i].name, table2_cases[k]) && !list.items[i].error[0])
                for (int degree = 1; degree <= 3; degree += 2)
                    rc |= run_table2(args, &list.items[i], model_scale(&list.items[i]), degree, t2,
                                     &n2);
    write_outputs(args, rows, list.n, t2, n2);
cleanup:
    free(rows);
    free(t2);
    pcb_cases_free(&list);
    return rc;
}
