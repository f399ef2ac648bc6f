/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench eval: nanoseconds per bicubic surface evaluation with
 * second derivatives (the tracer's hot path) and per closest-point query,
 * on a 16 x 16-span bicubic surface, beside a textbook evaluation loop
 * timed in the same run; and per cubic curve evaluation with second
 * derivatives (the tracer evaluates the projected curve at every step).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "json.h"
#include "naive_eval.h"
#include "shapes.h"
#include "svg.h"

#define EVAL_SPANS 16
#define EVAL_POINTS 4096        /* (u, v) samples cycled through */
#define CLOSEST_POINTS 256      /* query points for closest point */
#define CLOSEST_OFFSET 3.0      /* query points lie up to this far off S */
#define EVAL_REPS 15
#define EVAL_MIN_RUN_S 0.02
#define SAMPLE_SEED 0x5eedULL

typedef struct eval_bench {
    const projcurve_surface *surface;
    const projcurve_curve *curve;  /* cubic, EVAL_SPANS spans */
    pcb_naive_surface naive;
    double *uv;      /* 2 * EVAL_POINTS */
    double *query;   /* 3 * CLOSEST_POINTS */
    size_t next;     /* position in the cycle */
    int n_deriv;     /* derivative order asked of the library (work_*) */
} eval_bench;

#define MAX_ORDER 2

static int work_internal(void *user, size_t n)
{
    eval_bench *b = user;
    const pc_nurbs_surface *s = &b->surface->nurbs;
    size_t hint_u = 0, hint_v = 0;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double *uv = &b->uv[2 * (b->next++ % EVAL_POINTS)];
        pc_vec3 out[6];
        pc_nurbs_surface_eval(s, uv[0], uv[1], b->n_deriv, &hint_u, &hint_v, out);
        acc += out[0].z;
    }
    pcb_consume(acc);
    return 0;
}

static int work_public(void *user, size_t n)
{
    eval_bench *b = user;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double *uv = &b->uv[2 * (b->next++ % EVAL_POINTS)];
        double out[18];
        if (projcurve_surface_eval(NULL, b->surface, uv[0], uv[1], b->n_deriv, out) !=
            PROJCURVE_OK)
            return 1;
        acc += out[2];
    }
    pcb_consume(acc);
    return 0;
}

static int work_naive(void *user, size_t n)
{
    eval_bench *b = user;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double *uv = &b->uv[2 * (b->next++ % EVAL_POINTS)];
        double out[18];
        pcb_naive_eval(&b->naive, uv[0], uv[1], out);
        acc += out[17];
    }
    pcb_consume(acc);
    return 0;
}

static int work_curve(void *user, size_t n)
{
    eval_bench *b = user;
    const pc_nurbs_curve *c = &b->curve->nurbs;
    size_t hint = 0;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double t = c->t0 + (c->t1 - c->t0) * b->uv[b->next++ % (2 * EVAL_POINTS)];
        pc_vec3 out[3];
        pc_nurbs_curve_eval(c, t, 2, &hint, out);
        acc += out[0].z;
    }
    pcb_consume(acc);
    return 0;
}

/* A cubic space curve over the surface's field: control points on a
 * wavy line, uniform knots. */
static projcurve_status make_curve(projcurve_curve **out)
{
    enum { N = EVAL_SPANS + 3 };
    double ctrl[3 * N], knots[N + 4];
    for (size_t i = 0; i < N; ++i) {
        ctrl[3 * i] = PCB_FIELD_SIZE * (double)i / (double)(N - 1);
        ctrl[3 * i + 1] = 10.0 * sin(0.8 * (double)i);
        ctrl[3 * i + 2] = 20.0 + 5.0 * cos(1.3 * (double)i);
    }
    for (size_t k = 0; k < N + 4; ++k)
        knots[k] = k < 4 ? 0.0 : (k >= N ? (double)EVAL_SPANS : (double)(k - 3));
    return projcurve_curve_create_nurbs(NULL, 3, N, ctrl, NULL, knots, out);
}

static int work_closest(void *user, size_t n)
{
    eval_bench *b = user;
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double *p = &b->query[3 * (b->next++ % CLOSEST_POINTS)];
        double uv[2], dist;
        if (projcurve_surface_closest_point(NULL, b->surface, p, uv, NULL, &dist) != PROJCURVE_OK)
            return 1;
        acc += dist;
    }
    pcb_consume(acc);
    return 0;
}

/* Largest difference between the library's and the textbook evaluation:
 * a benchmark of a wrong answer is worthless. */
static double max_difference(const eval_bench *b)
{
    double worst = 0.0;
    for (size_t i = 0; i < EVAL_POINTS; ++i) {
        const double *uv = &b->uv[2 * i];
        double ours[18], ref[18];
        if (projcurve_surface_eval(NULL, b->surface, uv[0], uv[1], 2, ours) != PROJCURVE_OK)
            return INFINITY;
        pcb_naive_eval(&b->naive, uv[0], uv[1], ref);
        for (int k = 0; k < 18; ++k)
            worst = fmax(worst, fabs(ours[k] - ref[k]) / (1.0 + fabs(ref[k])));
    }
    return worst;
}

/* Query points: surface points pushed off along z by up to CLOSEST_OFFSET. */
static void make_queries(eval_bench *b, unsigned long long *rng)
{
    for (size_t i = 0; i < CLOSEST_POINTS; ++i) {
        double out[3];
        double *q = &b->query[3 * i];
        projcurve_surface_eval(NULL, b->surface, pcb_rand01(rng), pcb_rand01(rng), 0, out);
        q[0] = out[0];
        q[1] = out[1];
        q[2] = out[2] + CLOSEST_OFFSET * (2.0 * pcb_rand01(rng) - 1.0);
    }
}

/* ns per evaluation by derivative order (0, 1, 2), internal and public. */
typedef struct by_order {
    double order[MAX_ORDER + 1], internal_ns[MAX_ORDER + 1], public_ns[MAX_ORDER + 1];
} by_order;

static void write_svg(const pcb_args *args, const by_order *o)
{
    if (!args->svg_path)
        return;
    const pcb_series series[2] = {{"pc_nurbs_surface_eval", o->order, o->internal_ns, 3},
                                  {"projcurve_surface_eval", o->order, o->public_ns, 3}};
    const pcb_plot plot = {"bicubic evaluation, 16x16 spans", "derivative order",
                           "ns per evaluation", 0, 0, series, 2};
    if (pcb_svg_write(args->svg_path, &plot, 1) != 0)
        fprintf(stderr, "eval: cannot write %s\n", args->svg_path);
}

static void write_json(const pcb_args *args, const pcb_pair *internal, const pcb_pair *public_,
                       double closest_s, double curve_s, double diff, const by_order *o)
{
    pcb_json j;
    if (pcb_json_open(&j, args->json_path) != 0)
        return;
    char machine[128];
    pcb_machine_name(machine, sizeof machine);
    pcb_json_object_begin(&j, NULL);
    pcb_json_number(&j, "eval_ns", 1e9 * internal->a_s);
    pcb_json_number(&j, "closest_point_ns", 1e9 * closest_s);
    pcb_json_number(&j, "curve_eval_ns", 1e9 * curve_s);
    pcb_json_number(&j, "public_eval_ns", 1e9 * public_->a_s);
    pcb_json_number(&j, "naive_eval_ns", 1e9 * internal->b_s);
    pcb_json_number(&j, "eval_over_naive", internal->ratio);
    pcb_json_number(&j, "public_eval_over_naive", public_->ratio);
    pcb_json_number(&j, "max_relative_difference", diff);
    pcb_json_int(&j, "spans", EVAL_SPANS);
    pcb_json_array_begin(&j, "by_order");
    for (int k = 0; k <= MAX_ORDER; ++k) {
        pcb_json_object_begin(&j, NULL);
        pcb_json_int(&j, "n_deriv", k);
        pcb_json_number(&j, "internal_ns", o->internal_ns[k]);
        pcb_json_number(&j, "public_ns", o->public_ns[k]);
        pcb_json_object_end(&j);
    }
    pcb_json_array_end(&j);
    pcb_json_string(&j, "machine", machine);
    pcb_json_int(&j, "quick", args->quick);
    pcb_json_object_end(&j);
    if (pcb_json_close(&j) != 0)
        fprintf(stderr, "eval: cannot write %s\n", args->json_path);
}

int pcb_cmd_eval(const pcb_args *args)
{
    eval_bench b = {0};
    double *ctrl = NULL, *knots = NULL;
    projcurve_surface *surface = NULL;
    projcurve_curve *curve = NULL;
    int rc = 1;
    b.uv = malloc(2 * EVAL_POINTS * sizeof *b.uv);
    b.query = malloc(3 * CLOSEST_POINTS * sizeof *b.query);
    if (!b.uv || !b.query || pcb_bumpy_net(EVAL_SPANS, &ctrl, &knots) != 0)
        goto cleanup;
    if (!pcb_ok(NULL, pcb_make_bumpy_surface(NULL, EVAL_SPANS, &surface), "eval: surface"))
        goto cleanup;
    b.surface = surface;
    if (!pcb_ok(NULL, make_curve(&curve), "eval: curve"))
        goto cleanup;
    b.curve = curve;
    b.naive = (pcb_naive_surface){EVAL_SPANS + 3, EVAL_SPANS + 3, knots, knots, ctrl};
    unsigned long long rng = SAMPLE_SEED;
    for (size_t i = 0; i < 2 * EVAL_POINTS; ++i)
        b.uv[i] = pcb_rand01(&rng);
    make_queries(&b, &rng);

    pcb_print_banner("eval: bicubic 16x16 spans, S..Svv per evaluation", args);
    const double diff = max_difference(&b);
    const pcb_timing timing = pcb_timing_for(args, EVAL_REPS, EVAL_MIN_RUN_S);
    pcb_pair internal, public_;
    double closest_s = NAN, curve_s = NAN;
    by_order o;
    for (int k = 0; k <= MAX_ORDER; ++k) {
        b.n_deriv = k;
        o.order[k] = k;
        if (pcb_time_median(&timing, work_internal, &b, &o.internal_ns[k]) ||
            pcb_time_median(&timing, work_public, &b, &o.public_ns[k])) {
            fprintf(stderr, "eval: a timed call failed\n");
            goto cleanup;
        }
        o.internal_ns[k] *= 1e9;
        o.public_ns[k] *= 1e9;
    }
    b.n_deriv = MAX_ORDER;  /* the headline figures: with second derivatives */
    if (pcb_time_pair(&timing, work_internal, &b, work_naive, &b, &internal) ||
        pcb_time_pair(&timing, work_public, &b, work_naive, &b, &public_) ||
        pcb_time_median(&timing, work_closest, &b, &closest_s) ||
        pcb_time_median(&timing, work_curve, &b, &curve_s)) {
        fprintf(stderr, "eval: a timed call failed\n");
        goto cleanup;
    }
    printf("%-36s %10s %14s\n", "measure", "ns", "ratio to naive");
    printf("%-36s %10.1f %14.2f\n", "pc_nurbs_surface_eval (internal)", 1e9 * internal.a_s,
           internal.ratio);
    printf("%-36s %10.1f %14.2f\n", "projcurve_surface_eval (public)", 1e9 * public_.a_s,
           public_.ratio);
    printf("%-36s %10.1f %14s\n", "textbook A2.1+A2.3 loop (naive)", 1e9 * internal.b_s, "1");
    printf("%-36s %10.1f\n", "projcurve_surface_closest_point", 1e9 * closest_s);
    printf("%-36s %10.1f\n", "pc_nurbs_curve_eval (cubic, C..C'')", 1e9 * curve_s);
    printf("by derivative order (internal / public ns):");
    for (int k = 0; k <= MAX_ORDER; ++k)
        printf("  %d: %.1f / %.1f", k, o.internal_ns[k], o.public_ns[k]);
    printf("\nmax relative difference library vs textbook: %.2e\n", diff);
    write_json(args, &internal, &public_, closest_s, curve_s, diff, &o);
    write_svg(args, &o);
    rc = diff <= 1e-9 ? 0 : 1;
    if (rc)
        fprintf(stderr, "eval: library and textbook evaluations disagree (%.3g)\n", diff);
cleanup:
    projcurve_surface_destroy(surface);
    projcurve_curve_destroy(curve);
    free(ctrl);
    free(knots);
    free(b.uv);
    free(b.query);
    return rc;
}
