/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Benchmark cases (see cases.h).
 */
#include "cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MANIFEST_LINE_MAX 2048
#define MANIFEST_MAX_CASES 256

/* Real-surface cases: a file, which surface of it, and the curve built
 * over it. */
typedef struct real_case {
    const char *name;
    const char *file;  /* under real/ */
    int orthogonal;
    int small;         /* part of the quick subset */
} real_case;

static const real_case real_cases[] = {
    {"real_lens_directional", "sunglasses_lens.igs", 0, 1},
    {"real_lens_orthogonal", "sunglasses_lens.igs", 1, 1},
    {"real_joinsurf85_directional", "test-joinsurf_04.stp", 0, 0},
    {"real_joinsurf85_orthogonal", "test-joinsurf_04.stp", 1, 0},
};
#define N_REAL_CASES (sizeof real_cases / sizeof real_cases[0])

/* The curve over a real surface: a cubic through a zigzag of surface
 * points lifted along the normal. Directional cases lift along the normal
 * at the middle of the domain and project back along it; orthogonal ones
 * lift a little along each point's own normal. */
#define REAL_CURVE_POINTS 8
#define REAL_LIFT_DIRECTIONAL 0.3  /* fraction of the model size */
#define REAL_LIFT_ORTHOGONAL 0.01
#define REAL_TOL_DIST_REL 1e-5     /* eps_D as a fraction of the model size */
#define REAL_TOL_ANGLE_DEG 1.0

static int parse_manifest_line(char *line, pcb_case *c)
{
    char *fields[9];
    int n = 0;
    for (char *tok = line; n < 9; ++n) {
        fields[n] = tok;
        char *tab = strchr(tok, '\t');
        if (!tab) {
            ++n;
            break;
        }
        *tab = '\0';
        tok = tab + 1;
    }
    if (n < 8)
        return -1;
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%.*s", PCB_CASE_NAME_MAX - 1, fields[0]);
    c->orthogonal = strcmp(fields[1], "orthogonal") == 0;
    for (int i = 0; i < 3; ++i)
        c->dir[i] = strtod(fields[2 + i], NULL);
    c->tol_dist = strtod(fields[5], NULL);
    c->tol_angle_deg = strtod(fields[6], NULL);
    c->expected_branches = (int)strtol(fields[7], NULL, 10);
    return 0;
}

/* Reads the model and takes its first surface and (with need_curve) its
 * first curve. */
static void load_model(pcb_case *c, const char *path, int need_curve)
{
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK) {
        snprintf(c->error, sizeof c->error, "no context");
        return;
    }
    const projcurve_status st = projcurve_model_read_file(ctx, path, &c->model);
    if (st != PROJCURVE_OK) {
        snprintf(c->error, sizeof c->error, "%s: %s: %s", path, projcurve_status_string(st),
                 projcurve_context_message(ctx));
    } else {
        c->surface = projcurve_model_surface(c->model, 0);
        c->curve = need_curve ? projcurve_model_curve(c->model, 0) : NULL;
        if (!c->surface || (need_curve && !c->curve))
            snprintf(c->error, sizeof c->error, "%s: %zu surfaces, %zu curves", path,
                     projcurve_model_surface_count(c->model),
                     projcurve_model_curve_count(c->model));
    }
    projcurve_context_destroy(ctx);
}

static void normal_at(const projcurve_surface *s, double u, double v, double p[3], double n[3])
{
    double d[9];
    if (projcurve_surface_eval(NULL, s, u, v, 1, d) != PROJCURVE_OK) {
        p[0] = p[1] = p[2] = n[0] = n[1] = 0.0;
        n[2] = 1.0;
        return;
    }
    const double *su = d + 3, *sv = d + 6;
    n[0] = su[1] * sv[2] - su[2] * sv[1];
    n[1] = su[2] * sv[0] - su[0] * sv[2];
    n[2] = su[0] * sv[1] - su[1] * sv[0];
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; ++i) {
        p[i] = d[i];
        n[i] = len > 0.0 ? n[i] / len : (i == 2);
    }
}

/* Builds the curve of a real case over its loaded surface. */
static void define_real_curve(pcb_case *c, int orthogonal)
{
    double dom[4], box[6];
    projcurve_surface_domain(NULL, c->surface, dom);
    projcurve_surface_bounds(NULL, c->surface, box);
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    double centre[3], n_mid[3];
    normal_at(c->surface, 0.5 * (dom[0] + dom[1]), 0.5 * (dom[2] + dom[3]), centre, n_mid);
    double ctrl[3 * REAL_CURVE_POINTS];
    for (int i = 0; i < REAL_CURVE_POINTS; ++i) {
        const double fu = 0.2 + 0.6 * (double)i / (REAL_CURVE_POINTS - 1);
        const double fv = (i % 2) ? 0.65 : 0.35;
        double p[3], n[3];
        normal_at(c->surface, dom[0] + fu * (dom[1] - dom[0]), dom[2] + fv * (dom[3] - dom[2]),
                  p, n);
        for (int k = 0; k < 3; ++k)
            ctrl[3 * i + k] = orthogonal ? p[k] + REAL_LIFT_ORTHOGONAL * size * n[k]
                                         : p[k] + REAL_LIFT_DIRECTIONAL * size * n_mid[k];
    }
    double knots[REAL_CURVE_POINTS + 4];
    for (int i = 0; i < REAL_CURVE_POINTS + 4; ++i) {
        const int k = i - 3;
        knots[i] = k <= 0 ? 0.0 : k >= REAL_CURVE_POINTS - 3 ? 1.0
                                                             : (double)k / (REAL_CURVE_POINTS - 3);
    }
    if (projcurve_curve_create_nurbs(NULL, 3, REAL_CURVE_POINTS, ctrl, NULL, knots,
                                     &c->own_curve) != PROJCURVE_OK) {
        snprintf(c->error, sizeof c->error, "could not build the curve");
        return;
    }
    c->curve = c->own_curve;
    for (int k = 0; k < 3; ++k)
        c->dir[k] = -n_mid[k];
    c->tol_dist = REAL_TOL_DIST_REL * size;
}

static void load_real_case(const char *data_dir, const real_case *rc, pcb_case *c)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", rc->name);
    c->orthogonal = rc->orthogonal;
    c->tol_angle_deg = REAL_TOL_ANGLE_DEG;
    c->expected_branches = -1;
    char path[1024];
    snprintf(path, sizeof path, "%s/real/%s", data_dir, rc->file);
    load_model(c, path, 0);
    if (!c->error[0])
        define_real_curve(c, rc->orthogonal);
}

int pcb_cases_load(const char *data_dir, pcb_real_cases real, pcb_case_list *list)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cases/MANIFEST.tsv", data_dir);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cannot read %s\n", path);
        return -1;
    }
    list->items = calloc(MANIFEST_MAX_CASES + N_REAL_CASES, sizeof *list->items);
    list->n = 0;
    if (!list->items) {
        fclose(f);
        return -1;
    }
    char line[MANIFEST_LINE_MAX];
    while (fgets(line, sizeof line, f) && list->n < MANIFEST_MAX_CASES) {
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '#' || line[0] == '\0')
            continue;
        pcb_case *c = &list->items[list->n];
        if (parse_manifest_line(line, c) != 0)
            continue;
        ++list->n;
        snprintf(path, sizeof path, "%s/cases/%s.igs", data_dir, c->name);
        load_model(c, path, 1);
    }
    fclose(f);
    for (size_t i = 0; i < N_REAL_CASES; ++i)
        if (real == PCB_REAL_ALL || (real == PCB_REAL_SMALL && real_cases[i].small))
            load_real_case(data_dir, &real_cases[i], &list->items[list->n++]);
    return 0;
}

void pcb_cases_free(pcb_case_list *list)
{
    for (size_t i = 0; i < list->n; ++i) {
        projcurve_model_destroy(list->items[i].model);
        projcurve_surface_destroy(list->items[i].own_surface);
        projcurve_curve_destroy(list->items[i].own_curve);
    }
    free(list->items);
    list->items = NULL;
    list->n = 0;
}

projcurve_status pcb_case_options(projcurve_context *ctx, const pcb_case *c,
                                  projcurve_options **out)
{
    projcurve_options *o = NULL;
    projcurve_status st = projcurve_options_create(ctx, &o);
    if (st == PROJCURVE_OK && c->tol_dist > 0.0)
        st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, c->tol_dist);
    if (st == PROJCURVE_OK && c->tol_angle_deg > 0.0)
        st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_ANGLE_DEG, c->tol_angle_deg);
    if (st == PROJCURVE_OK && c->pcurve_degree > 0)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, c->pcurve_degree);
    if (st != PROJCURVE_OK) {
        projcurve_options_destroy(o);
        return st;
    }
    *out = o;
    return PROJCURVE_OK;
}

projcurve_status pcb_case_project(projcurve_context *ctx, const pcb_case *c,
                                  const projcurve_options *opts, projcurve_result **out)
{
    return c->orthogonal ? projcurve_project_orthogonal(ctx, c->surface, c->curve, opts, out)
                         : projcurve_project_directional(ctx, c->surface, c->curve, c->dir, opts,
                                                         out);
}
