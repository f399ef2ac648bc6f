/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench profile: every case's projection split by stage (seeding,
 * tracing, jump sweep, refinement, composition, verification, fitting), at
 * the case's eps_D and at Open CASCADE's measured accuracy: the deviations
 * `projcurve-bench occt --json FILE` measured, read back with --from FILE;
 * without it, at 1e-4 of the case's eps_D (about Open CASCADE's accuracy on
 * the directional cases, bench/README.md). --case NAME runs one case,
 * --pcurve-degree 1|3 sets PROJCURVE_OPT_PCURVE_DEGREE, and
 * $PCB_PROFILE_SECONDS the CPU time per row (default 0.1 s; longer for
 * perf record).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "cases.h"
#include "geom/surface.h"
#include "json.h"
#include "profile.h"
#include "svg.h"

/* Without --from, the tight run asks for this fraction of the case's eps_D. */
#define PCB_PROFILE_TIGHT 1e-4
/* Matched runs ask for no less than this fraction of the model size (as
 * the occt command). */
#define PCB_PROFILE_TOL_FLOOR 1e-10
#define PCB_PROFILE_MIN_S 0.1
/* occt.json files are a few kB. */
#define PCB_PROFILE_MAX_JSON (1u << 22)

/* Rows kept for the plot: every case at two tolerances. */
#define PCB_PROFILE_MAX_ROWS 128

/* Each stage's ms against the whole call's, one series per stage. */
static void write_svg(const char *path, const pcb_profile *rows, size_t n)
{
    if (path == NULL)
        return;
    static double x[PCB_PROFILE_MAX_ROWS], y[PC_STAGE_COUNT][PCB_PROFILE_MAX_ROWS];
    pcb_series series[PC_STAGE_COUNT];
    for (int s = 0; s < PC_STAGE_COUNT; ++s) {
        for (size_t i = 0; i < n; ++i) {
            x[i] = rows[i].total_ms;
            y[s][i] = rows[i].stage_ms[s] > 0.0 ? rows[i].stage_ms[s] : NAN;
        }
        series[s] = (pcb_series){pc_stage_name((pc_stage)s), x, y[s], n};
    }
    const pcb_plot plot = {"profile: CPU ms by stage", "ms per call", "ms in the stage", 1, 1,
                           series, PC_STAGE_COUNT};
    if (pcb_svg_write(path, &plot, 1) != 0)
        fprintf(stderr, "profile: cannot write %s\n", path);
}

/* The whole file, malloc'd and NUL-terminated, or NULL. */
static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    char *buf = malloc(PCB_PROFILE_MAX_JSON + 1);
    size_t n = buf ? fread(buf, 1, PCB_PROFILE_MAX_JSON, f) : 0;
    fclose(f);
    if (buf)
        buf[n] = '\0';
    return buf;
}

/* Open CASCADE's deviation for case `name` in occt.json text, or NaN: the
 * first "occt_deviation" after the case's "name" member. */
static double occt_deviation(const char *json, const char *name)
{
    if (json == NULL)
        return NAN;
    char key[512]; /* a case name (PCB_CASE_NAME_MAX) and the member syntax */
    snprintf(key, sizeof key, "\"name\": \"%s\"", name);
    const char *at = strstr(json, key);
    if (at == NULL)
        return NAN;
    const char *next = strstr(at + 1, "\"name\": ");
    const char *dev = strstr(at, "\"occt_deviation\": ");
    if (dev == NULL || (next != NULL && dev > next))
        return NAN;
    char *end = NULL;
    const double v = strtod(dev + strlen("\"occt_deviation\": "), &end);
    return end != dev + strlen("\"occt_deviation\": ") && isfinite(v) ? v : NAN;
}

static void json_row(pcb_json *j, const char *name, const char *at, const pcb_profile *p)
{
    pcb_json_object_begin(j, NULL);
    pcb_json_string(j, "name", name);
    pcb_json_string(j, "at", at);
    pcb_json_number(j, "tol_dist", p->tol);
    pcb_json_number(j, "total_ms", p->total_ms);
    for (int s = 0; s < PC_STAGE_COUNT; ++s) {
        char key[64];
        snprintf(key, sizeof key, "%s_ms", pc_stage_name((pc_stage)s));
        pcb_json_number(j, key, p->stage_ms[s]);
    }
    pcb_json_number(j, "pieces", p->pieces);
    pcb_json_number(j, "points", p->points);
    pcb_json_number(j, "compact_poles", p->poles);
    pcb_json_number(j, "pcurve_poles", p->pcurve_poles);
    pcb_json_number(j, "calls", p->calls);
    pcb_json_object_end(j);
}

int pcb_cmd_profile(const pcb_args *args)
{
    pcb_case_list list;
    if (pcb_cases_load(args->data_dir, args->quick ? PCB_REAL_SMALL : PCB_REAL_ALL, &list) != 0)
        return 2;
    char *from = args->from_path ? read_file(args->from_path) : NULL;
    if (args->from_path && from == NULL) {
        fprintf(stderr, "profile: cannot read %s\n", args->from_path);
        pcb_cases_free(&list);
        return 2;
    }
    pcb_print_banner(args->pcurve_degree == 3   ? "profile: CPU ms per call by stage, cubic pcurves"
                     : args->pcurve_degree == 1 ? "profile: CPU ms per call by stage, straight pcurves"
                                                : "profile: CPU ms per call by stage, default options",
                     args);
    pcb_profile_print_header();
    pcb_json j;
    const int json = args->json_path && pcb_json_open(&j, args->json_path) == 0;
    if (json) {
        pcb_json_object_begin(&j, NULL);
        pcb_json_array_begin(&j, "rows");
    }
    /* $PCB_PROFILE_SECONDS: CPU seconds per row (longer for perf record) */
    const char *env = getenv("PCB_PROFILE_SECONDS");
    const double min_s = env && atof(env) > 0.0 ? atof(env) : PCB_PROFILE_MIN_S;
    int rc = 0;
    static pcb_profile rows[PCB_PROFILE_MAX_ROWS];
    size_t n_rows = 0;
    for (size_t i = 0; i < list.n; ++i) {
        pcb_case variant = list.items[i];
        if (args->pcurve_degree > 0)
            variant.pcurve_degree = args->pcurve_degree;
        const pcb_case *c = &variant;
        if (args->only_case && strcmp(c->name, args->only_case) != 0)
            continue;
        if (c->error[0]) {
            printf("%-30s not loaded: %s\n", c->name, c->error);
            continue;
        }
        double tight = from ? occt_deviation(from, c->name) : PCB_PROFILE_TIGHT * c->tol_dist;
        if (isfinite(tight))
            tight = fmax(tight, PCB_PROFILE_TOL_FLOOR * c->surface->size);
        const double tols[2] = {c->tol_dist, tight};
        const char *labels[2] = {"case", from ? "occt" : "x1e-4"};
        for (int k = 0; k < 2 && !(args->quick && k == 1); ++k) {
            if (!isfinite(tols[k]) || (k == 1 && !(tols[1] < tols[0])))
                continue;
            pcb_profile p;
            char status[256] = "";
            if (pcb_profile_case(c, tols[k], args->quick, min_s, &p, status,
                                 sizeof status) != 0) {
                printf("%-30s %-6s failed: %s\n", c->name, labels[k], status);
                rc = 1;
                continue;
            }
            pcb_profile_print(c->name, labels[k], &p);
            if (json)
                json_row(&j, c->name, labels[k], &p);
            if (n_rows < PCB_PROFILE_MAX_ROWS)
                rows[n_rows++] = p;
        }
        fflush(stdout);
    }
    if (json) {
        pcb_json_array_end(&j);
        pcb_json_int(&j, "quick", args->quick);
        pcb_json_object_end(&j);
        if (pcb_json_close(&j) != 0)
            fprintf(stderr, "profile: cannot write %s\n", args->json_path);
    }
    write_svg(args->svg_path, rows, n_rows);
    free(from);
    pcb_cases_free(&list);
    return rc;
}
