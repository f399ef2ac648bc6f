/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench rays: microseconds per ray on the same shape at 1, 100
 * and 10,000 patches (knots refined exactly), for rays that meet one patch
 * (vertical) and rays that cross the field obliquely; the cost should grow
 * like the logarithm of the patch count (the BVH depth).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "fit.h"
#include "json.h"
#include "shapes.h"
#include "svg.h"

#define N_RAYS 1024
#define RAY_HEIGHT 50.0      /* ray origins above the field (z in about [-8, 12]) */
#define RAY_MARGIN 0.5       /* keep origins this far inside the field */
#define RAYS_REPS 11
#define RAYS_MIN_RUN_S 0.02
#define MAX_HITS 8
#define SAMPLE_SEED 0x7a95ULL

static const size_t full_spans[] = {1, 10, 100};
static const size_t quick_spans[] = {1, 10};

typedef struct rays_bench {
    const projcurve_surface *surface;
    double origins[3 * N_RAYS];
    double dir[3];
    size_t next;
} rays_bench;

static int work_rays(void *user, size_t n)
{
    rays_bench *b = user;
    size_t total = 0;
    for (size_t i = 0; i < n; ++i) {
        const double *o = &b->origins[3 * (b->next++ % N_RAYS)];
        double hits[3 * MAX_HITS];
        size_t count = 0;
        if (projcurve_surface_intersect_line(NULL, b->surface, o, b->dir, 1, MAX_HITS, hits, NULL,
                                             &count) != PROJCURVE_OK)
            return 1;
        total += count;
    }
    pcb_consume((double)total);
    return 0;
}

/* Mean hits per ray over one pass (a vertical ray must hit exactly once). */
static double hits_per_ray(rays_bench *b)
{
    size_t total = 0;
    for (size_t i = 0; i < N_RAYS; ++i) {
        double hits[3 * MAX_HITS];
        size_t count = 0;
        if (projcurve_surface_intersect_line(NULL, b->surface, &b->origins[3 * i], b->dir, 1,
                                             MAX_HITS, hits, NULL, &count) != PROJCURVE_OK)
            return NAN;
        total += count;
    }
    return (double)total / N_RAYS;
}

typedef struct rays_row {
    double patches, us_vertical, us_oblique, build_ms, hits_vertical, hits_oblique;
} rays_row;

static int measure_row(const pcb_args *args, size_t spans, rays_row *row)
{
    projcurve_surface *surface = NULL;
    const double t0 = pcb_now_s();
    if (!pcb_ok(NULL, pcb_make_refined_patch(NULL, spans, &surface), "rays: surface"))
        return 1;
    row->build_ms = 1e3 * (pcb_now_s() - t0);
    row->patches = (double)(spans * spans);
    rays_bench *b = malloc(sizeof *b);
    if (!b) {
        projcurve_surface_destroy(surface);
        return 1;
    }
    b->surface = surface;
    b->next = 0;
    unsigned long long rng = SAMPLE_SEED;
    for (size_t i = 0; i < N_RAYS; ++i) {
        const double span = PCB_FIELD_SIZE - 2.0 * RAY_MARGIN;
        b->origins[3 * i] = RAY_MARGIN + span * pcb_rand01(&rng);
        b->origins[3 * i + 1] = RAY_MARGIN + span * pcb_rand01(&rng);
        b->origins[3 * i + 2] = RAY_HEIGHT;
    }
    const pcb_timing timing = pcb_timing_for(args, RAYS_REPS, RAYS_MIN_RUN_S);
    int rc = 0;
    b->dir[0] = 0.0, b->dir[1] = 0.0, b->dir[2] = -1.0;
    row->hits_vertical = hits_per_ray(b);
    rc |= pcb_time_median(&timing, work_rays, b, &row->us_vertical);
    /* Oblique: each ray crosses about a fifth of the field before it lands. */
    b->dir[0] = 0.3, b->dir[1] = 0.2, b->dir[2] = -1.0;
    row->hits_oblique = hits_per_ray(b);
    rc |= pcb_time_median(&timing, work_rays, b, &row->us_oblique);
    row->us_vertical *= 1e6;
    row->us_oblique *= 1e6;
    free(b);
    projcurve_surface_destroy(surface);
    return rc ? 1 : 0;
}

static void write_outputs(const pcb_args *args, const rays_row *rows, size_t n, double log_slope)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) == 0) {
        pcb_json_object_begin(&j, NULL);
        pcb_json_array_begin(&j, "rows");
        for (size_t i = 0; i < n; ++i) {
            pcb_json_object_begin(&j, NULL);
            pcb_json_number(&j, "patches", rows[i].patches);
            pcb_json_number(&j, "us_per_ray", rows[i].us_vertical);
            pcb_json_number(&j, "us_per_oblique_ray", rows[i].us_oblique);
            pcb_json_number(&j, "hits_per_ray", rows[i].hits_vertical);
            pcb_json_number(&j, "hits_per_oblique_ray", rows[i].hits_oblique);
            pcb_json_number(&j, "build_ms", rows[i].build_ms);
            pcb_json_object_end(&j);
        }
        pcb_json_array_end(&j);
        pcb_json_number(&j, "us_per_ln_patches", log_slope);
        pcb_json_int(&j, "quick", args->quick);
        pcb_json_object_end(&j);
        if (pcb_json_close(&j) != 0)
            fprintf(stderr, "rays: cannot write %s\n", args->json_path);
    }
    if (!args->svg_path)
        return;
    double x[8], yv[8], yo[8];
    for (size_t i = 0; i < n; ++i) {
        x[i] = rows[i].patches;
        yv[i] = rows[i].us_vertical;
        yo[i] = rows[i].us_oblique;
    }
    const pcb_series series[2] = {{"vertical rays (1 patch met)", x, yv, n},
                                  {"oblique rays", x, yo, n}};
    const pcb_plot plot = {"line/surface intersection", "patches", "us per ray", 1, 0, series, 2};
    if (pcb_svg_write(args->svg_path, &plot, 1) != 0)
        fprintf(stderr, "rays: cannot write %s\n", args->svg_path);
}

int pcb_cmd_rays(const pcb_args *args)
{
    const size_t *spans = args->quick ? quick_spans : full_spans;
    const size_t n = args->quick ? sizeof quick_spans / sizeof *quick_spans
                                 : sizeof full_spans / sizeof *full_spans;
    rays_row rows[8];
    int rc = 0;
    pcb_print_banner("rays: same shape, refined knots", args);
    printf("%10s %12s %12s %10s %10s %10s\n", "patches", "us/ray", "us/oblique", "hits", "hits_obl",
           "build_ms");
    for (size_t i = 0; i < n; ++i) {
        rc |= measure_row(args, spans[i], &rows[i]);
        printf("%10.0f %12.3f %12.3f %10.3f %10.3f %10.2f\n", rows[i].patches, rows[i].us_vertical,
               rows[i].us_oblique, rows[i].hits_vertical, rows[i].hits_oblique, rows[i].build_ms);
        /* Every vertical ray over a height field meets it exactly once. */
        if (!(fabs(rows[i].hits_vertical - 1.0) < 1e-12)) {
            fprintf(stderr, "rays: %.0f patches: %.4f hits per vertical ray, expected 1\n",
                    rows[i].patches, rows[i].hits_vertical);
            rc = 1;
        }
    }
    double x[8], y[8], a, slope;
    for (size_t i = 0; i < n; ++i) {
        x[i] = rows[i].patches;
        y[i] = rows[i].us_vertical;
    }
    pcb_fit_log(x, y, n, &a, &slope);
    printf("fit: us/ray = %.3f + %.3f ln(patches)\n", a, slope);
    write_outputs(args, rows, n, slope);
    return rc;
}
