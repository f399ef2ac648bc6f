/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench shape: curves projected onto whole real models
 * (projcurve_project_shape, directional and conical) beside Open CASCADE's
 * BRepProj_Projection (cylindrical and conical constructors) on the same
 * model read by its own reader, in the same run. Each model gets a line, a
 * cubic and a circle in a plane just outside its box, across the box's
 * longest side, projected through the box along its thinnest axis (or from
 * an eye point beyond that plane). Both outputs are measured the same way
 * (shape_accuracy.h); when Open CASCADE's is the more accurate, ours is run
 * again with eps_D below its measured error, so that the times compare at
 * equal or better measured accuracy. --case TEXT runs only the cases whose
 * name holds TEXT (e.g. "linkrods.step line dir"); with
 * $PCB_PROFILE_SECONDS set, each case runs only our projection, over and
 * over for that many CPU seconds (for perf record), and is not measured.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "brep/shape.h"
#include "json.h"
#include "shape_accuracy.h"
#include "svg.h"
#ifdef PCB_HAVE_OCCT_READ
#include "occt_shape.h"
#endif

#define SHAPE_REPS 7
#define SHAPE_MIN_RUN_S 0.02
#define SHAPE_OCCT_REPS 3
#define SHAPE_SAMPLES 64      /* per output piece (ours) or edge (Open CASCADE) */
#define SHAPE_MATCH_FLOOR 1e-9 /* matched eps_D no less than this times the model size */

static const char *const shape_models[] = {"real/bearing.iges", "real/hammer.iges",
                                           "real/linkrods.step", "real/test-joinsurf_01.stp"};
static const char *const curve_names[] = {"line", "cubic", "circle"};
enum { N_CURVES = 3 };

/* The model's box, its axes by extent (a: thinnest, b: longest, c: the
 * other) and the plane just outside it on axis a. */
typedef struct shape_frame {
    double lo[3], hi[3], size;
    int a, b, c;
    double plane;
} shape_frame;

static void frame_of(const projcurve_shape *s, shape_frame *f)
{
    for (int i = 0; i < 3; ++i) {
        f->lo[i] = INFINITY;
        f->hi[i] = -INFINITY;
    }
    for (size_t k = 0; k < s->n_faces; ++k)
        for (int i = 0; i < 3; ++i) {
            f->lo[i] = fmin(f->lo[i], s->boxes[6 * k + i]);
            f->hi[i] = fmax(f->hi[i], s->boxes[6 * k + i + 3]);
        }
    double e[3], sq = 0.0;
    for (int i = 0; i < 3; ++i) {
        e[i] = f->hi[i] - f->lo[i];
        sq += e[i] * e[i];
    }
    f->size = sqrt(sq);
    f->a = 0;
    for (int i = 1; i < 3; ++i)
        if (e[i] < e[f->a])
            f->a = i;
    f->b = (f->a + 1) % 3;
    f->c = (f->a + 2) % 3;
    if (e[f->c] > e[f->b]) {
        const int t = f->b;
        f->b = f->c;
        f->c = t;
    }
    f->plane = f->hi[f->a] + 0.05 * f->size;
}

/* A point of the frame: fraction x along b over the box widened by 5 %,
 * y along c around the middle (slightly off it, away from symmetry planes). */
static void frame_point(const shape_frame *f, double x, double y, double p[3])
{
    const double wb = f->hi[f->b] - f->lo[f->b], wc = f->hi[f->c] - f->lo[f->c];
    p[f->a] = f->plane;
    p[f->b] = f->lo[f->b] - 0.05 * wb + 1.1 * wb * x;
    p[f->c] = 0.5 * (f->lo[f->c] + f->hi[f->c]) + 0.0123 * wc + wc * y;
}

static projcurve_status make_curve(const shape_frame *f, int which, projcurve_curve **out)
{
    double ctrl[27], w[9];
    if (which == 0) {
        const double knots[] = {0, 0, 1, 1};
        frame_point(f, 0.0, 0.0, ctrl);
        frame_point(f, 1.0, 0.0, ctrl + 3);
        return projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, out);
    }
    if (which == 1) {
        const double knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
        const double ys[4] = {-0.15, 0.3, -0.3, 0.15};
        for (int i = 0; i < 4; ++i)
            frame_point(f, i / 3.0, ys[i], ctrl + 3 * i);
        return projcurve_curve_create_nurbs(NULL, 3, 4, ctrl, NULL, knots, out);
    }
    /* a circle of radius 0.3 of the shorter side, 9 rational quadratic poles */
    const double wb = f->hi[f->b] - f->lo[f->b], wc = f->hi[f->c] - f->lo[f->c];
    const double r = 0.3 * fmin(wb, wc);
    const double knots[] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    double centre[3];
    frame_point(f, 0.5 / 1.1 + 0.05 / 1.1 + 0.01, 0.0, centre);
    for (int i = 0; i < 9; ++i) {
        w[i] = i % 2 ? sqrt(0.5) : 1.0;
        double *p = ctrl + 3 * i;
        p[f->a] = f->plane;
        p[f->b] = centre[f->b] + r * cx[i];
        p[f->c] = centre[f->c] + r * cy[i];
    }
    return projcurve_curve_create_nurbs(NULL, 2, 9, ctrl, w, knots, out);
}

/* Dir (directional) or the eye (conical) of the frame. */
static void frame_vec(const shape_frame *f, int conical, double v[3])
{
    if (!conical) {
        v[0] = v[1] = v[2] = 0.0;
        v[f->a] = -1.0;
        return;
    }
    for (int i = 0; i < 3; ++i)
        v[i] = 0.5 * (f->lo[i] + f->hi[i]);
    v[f->a] = f->plane + f->size;
}

typedef struct ours_work {
    const projcurve_shape *shape;
    const projcurve_curve *curve;
    projcurve_projection_kind kind;
    const double *vec;
    const projcurve_options *opts;
} ours_work;

static int work_ours(void *user, size_t n)
{
    const ours_work *w = user;
    for (size_t i = 0; i < n; ++i) {
        projcurve_shape_result *r = NULL;
        const projcurve_status st =
            projcurve_project_shape(NULL, w->shape, w->curve, w->kind, w->vec, w->opts, &r);
        pcb_consume((double)projcurve_shape_result_curve_count(r));
        projcurve_shape_result_destroy(r);
        if (st != PROJCURVE_OK) {
            fprintf(stderr, "projcurve_project_shape: %s\n", projcurve_status_string(st));
            return 1;
        }
    }
    return 0;
}

/* Our figures of one projection. */
typedef struct ours_figures {
    double ms;
    size_t curves, pieces, poles, faces_projected;
    pcb_shape_accuracy acc;
    double eps_d;
} ours_figures;

/* Room for SHAPE_SAMPLES more points in *pts. */
static int grow(double **pts, size_t n, size_t *cap)
{
    if (n + SHAPE_SAMPLES <= *cap)
        return 0;
    *cap = 2 * *cap + SHAPE_SAMPLES;
    double *grown = realloc(*pts, 3 * *cap * sizeof **pts);
    if (grown == NULL)
        return -1;
    *pts = grown;
    return 0;
}

/* A rational Bezier piece at s in [0, 1] (de Casteljau on homogeneous points). */
static void bezier_at(int degree, const double *ctrl, const double *w, double s, double p[3])
{
    double h[4 * PROJCURVE_MAX_PIECE_POINTS];
    for (int i = 0; i <= degree; ++i) {
        for (int k = 0; k < 3; ++k)
            h[4 * i + k] = ctrl[3 * i + k] * w[i];
        h[4 * i + 3] = w[i];
    }
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i <= degree - r; ++i)
            for (int k = 0; k < 4; ++k)
                h[4 * i + k] = (1.0 - s) * h[4 * i + k] + s * h[4 * (i + 1) + k];
    for (int k = 0; k < 3; ++k)
        p[k] = h[k] / h[3];
}

/* Samples of a face piece: its compact 3D curve (what a CAD system gets),
 * or where the fit gave none (LIMIT_REACHED), its composed pieces; adds
 * the poles of what was sampled. */
static int sample_piece(const projcurve_result *fr, size_t branch, double **pts, size_t *n_pts,
                        size_t *cap, size_t *poles)
{
    projcurve_curve *cc = NULL;
    if (projcurve_result_branch_compact_curve(NULL, fr, branch, &cc) == PROJCURVE_OK) {
        size_t n_ctrl = 0;
        double t0 = 0, t1 = 0;
        projcurve_curve_nurbs_info(NULL, cc, NULL, &n_ctrl, NULL, NULL);
        projcurve_curve_domain(NULL, cc, &t0, &t1);
        *poles += n_ctrl;
        const int ok = grow(pts, *n_pts, cap) == 0;
        for (int i = 0; ok && i < SHAPE_SAMPLES; ++i)
            projcurve_curve_eval(NULL, cc, t0 + (t1 - t0) * i / (SHAPE_SAMPLES - 1.0), 0,
                                 *pts + 3 * (*n_pts)++);
        projcurve_curve_destroy(cc);
        return ok ? 0 : -1;
    }
    size_t n_pieces = 0;
    if (projcurve_result_branch_info(NULL, fr, branch, NULL, NULL, NULL, NULL, &n_pieces) !=
        PROJCURVE_OK)
        return -1;
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
        if (projcurve_result_piece(NULL, fr, branch, k, &degree, ctrl, w, NULL, NULL) !=
                PROJCURVE_OK ||
            grow(pts, *n_pts, cap) != 0)
            return -1;
        *poles += (size_t)degree + 1;
        for (int i = 0; i < SHAPE_SAMPLES; ++i)
            bezier_at(degree, ctrl, w, i / (SHAPE_SAMPLES - 1.0), *pts + 3 * (*n_pts)++);
    }
    return 0;
}

/* Samples every face piece into *pts (malloc'd) and counts pieces and poles. */
static int sample_ours(const projcurve_shape_result *r, ours_figures *fig, double **pts,
                       size_t *n_pts)
{
    size_t cap = 0;
    *pts = NULL;
    *n_pts = 0;
    fig->curves = projcurve_shape_result_curve_count(r);
    fig->pieces = fig->poles = 0;
    for (size_t c = 0; c < fig->curves; ++c) {
        size_t n_pieces = 0;
        projcurve_shape_result_curve_info(NULL, r, c, &n_pieces, NULL, NULL);
        for (size_t k = 0; k < n_pieces; ++k) {
            const projcurve_result *fr = NULL;
            size_t branch = 0;
            if (projcurve_shape_result_piece(NULL, r, c, k, NULL, &fr, &branch, NULL, NULL, NULL) !=
                    PROJCURVE_OK ||
                sample_piece(fr, branch, pts, n_pts, &cap, &fig->poles) != 0)
                return -1;
            ++fig->pieces;
        }
    }
    return 0;
}

/* Times and measures ours with eps_D (0: the default). */
static int run_ours(const pcb_timing *timing, ours_work *w, double eps_d, int conical,
                    ours_figures *fig)
{
    projcurve_options *opts = NULL;
    if (projcurve_options_create(NULL, &opts) != PROJCURVE_OK)
        return -1;
    if (eps_d > 0.0)
        projcurve_options_set_double(NULL, opts, PROJCURVE_OPT_TOL_DISTANCE, eps_d);
    w->opts = opts;
    double s = 0.0;
    int rc = pcb_time_median(timing, work_ours, w, &s);
    fig->ms = 1e3 * s;
    projcurve_shape_result *r = NULL;
    projcurve_context *ctx = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    if (rc == 0 &&
        !pcb_ok(ctx, projcurve_project_shape(ctx, w->shape, w->curve, w->kind, w->vec, opts, &r),
                "projcurve_project_shape"))
        rc = -1;
    else if (rc != 0)
        pcb_ok(ctx, projcurve_project_shape(ctx, w->shape, w->curve, w->kind, w->vec, opts, &r),
               "projcurve_project_shape");
    projcurve_context_destroy(ctx);
    double *pts = NULL;
    size_t n = 0;
    if (rc == 0) {
        fig->faces_projected = projcurve_shape_result_face_count(r);
        rc = sample_ours(r, fig, &pts, &n);
    }
    if (rc == 0) {
        /* eps_D used: the first projected face reports it */
        const projcurve_result *fr = NULL;
        fig->eps_d = eps_d;
        if (fig->faces_projected > 0 &&
            projcurve_shape_result_face(NULL, r, 0, NULL, &fr, NULL, NULL) == PROJCURVE_OK && fr)
            projcurve_result_stat(NULL, fr, PROJCURVE_STAT_TOL_DISTANCE, &fig->eps_d);
        rc = pcb_shape_accuracy_of(w->shape, w->curve, conical, w->vec, pts, n, &fig->acc);
    }
    free(pts);
    projcurve_shape_result_destroy(r);
    projcurve_options_destroy(opts);
    return rc;
}

static double worst(const pcb_shape_accuracy *a)
{
    return fmax(a->face, a->ray);
}

typedef struct shape_row {
    char name[96];
    ours_figures ours;
    int have_occt;
    double occt_ms;
    int occt_wires, occt_edges;
    long occt_poles;
    pcb_shape_accuracy occt_acc;
} shape_row;

static void print_row(const shape_row *r)
{
    printf("%-30s %9.3f %4zu %5zu %6zu %9.2e %9.2e", r->name, r->ours.ms, r->ours.curves,
           r->ours.pieces, r->ours.poles, r->ours.acc.face, r->ours.acc.ray);
    if (r->have_occt)
        printf(" %10.2f %4d %5d %6ld %9.2e %9.2e %9.4f", r->occt_ms, r->occt_wires, r->occt_edges,
               r->occt_poles, r->occt_acc.face, r->occt_acc.ray,
               r->occt_ms > 0 ? r->ours.ms / r->occt_ms : 0.0);
    printf("\n");
}

static void json_row(pcb_json *json, const shape_row *r)
{
    pcb_json_object_begin(json, NULL);
    pcb_json_string(json, "name", r->name);
    pcb_json_number(json, "ours_ms", r->ours.ms);
    pcb_json_number(json, "ours_eps_d", r->ours.eps_d);
    pcb_json_int(json, "ours_faces_projected", (long long)r->ours.faces_projected);
    pcb_json_int(json, "ours_curves", (long long)r->ours.curves);
    pcb_json_int(json, "ours_pieces", (long long)r->ours.pieces);
    pcb_json_int(json, "ours_poles", (long long)r->ours.poles);
    pcb_json_number(json, "ours_face_error", r->ours.acc.face);
    pcb_json_number(json, "ours_ray_error", r->ours.acc.ray);
    if (r->have_occt) {
        pcb_json_number(json, "occt_ms", r->occt_ms);
        pcb_json_int(json, "occt_wires", r->occt_wires);
        pcb_json_int(json, "occt_edges", r->occt_edges);
        pcb_json_int(json, "occt_poles", r->occt_poles);
        pcb_json_number(json, "occt_face_error", r->occt_acc.face);
        pcb_json_number(json, "occt_ray_error", r->occt_acc.ray);
        pcb_json_number(json, "ours_over_occt", r->occt_ms > 0 ? r->ours.ms / r->occt_ms : 0.0);
    } else {
        pcb_json_null(json, "occt_ms");
    }
    pcb_json_object_end(json);
}

#ifdef PCB_HAVE_OCCT_READ
/* Open CASCADE's side of a row; 0, or -1 with the note printed. */
static int run_occt(const pcb_args *args, const pcb_occt_model *om, const projcurve_shape *shape,
                    const projcurve_curve *curve, int conical, const double vec[3], shape_row *row)
{
    pcb_nurbs_data d;
    if (pcb_curve_data(curve, &d) != 0)
        return -1;
    pcb_occt_shape_out out;
    int rc = pcb_occt_shape_project(om, &d, conical, vec, args->quick ? 1 : SHAPE_OCCT_REPS,
                                    SHAPE_SAMPLES, &out);
    pcb_nurbs_data_free(&d);
    if (rc != 0) {
        fprintf(stderr, "%s: %s\n", row->name, out.note);
    } else {
        row->have_occt = 1;
        row->occt_ms = out.ms;
        row->occt_wires = out.wires;
        row->occt_edges = out.edges;
        row->occt_poles = out.poles;
        rc = pcb_shape_accuracy_of(shape, curve, conical, vec, out.samples, out.n_samples,
                                   &row->occt_acc);
    }
    pcb_occt_shape_out_free(&out);
    return rc;
}
#endif

/* The times plotted, case by case. */
#define SHAPE_MAX_ROWS 32
typedef struct shape_plot {
    double x[SHAPE_MAX_ROWS], ours[SHAPE_MAX_ROWS], occt[SHAPE_MAX_ROWS];
    size_t n;
} shape_plot;

static void plot_add(shape_plot *p, const shape_row *r)
{
    if (p->n == SHAPE_MAX_ROWS)
        return; /* more cases than the plot holds: the table still has them */
    p->x[p->n] = (double)(p->n + 1);
    p->ours[p->n] = r->ours.ms;
    p->occt[p->n++] = r->have_occt ? r->occt_ms : NAN;
}

/* Every curve and kind onto one model; returns 0 or 1 (a failure). */
static int bench_model(const pcb_args *args, const char *rel, const pcb_timing *timing,
                       pcb_json *json, shape_plot *plot)
{
    char path[4096];
    pcb_join_path(path, sizeof path, args->data_dir, rel);
    projcurve_context *ctx = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    projcurve_model *model = NULL;
    if (!pcb_ok(ctx, projcurve_model_read_file(ctx, path, &model), path)) {
        projcurve_context_destroy(ctx);
        return 1;
    }
    /* the shape with the most faces (each model here has one solid or shell
     * that holds nearly all of them) */
    const projcurve_shape *shape = NULL;
    for (size_t i = 0; i < projcurve_model_shape_count(model); ++i) {
        const projcurve_shape *s = projcurve_model_shape(model, i);
        if (shape == NULL || s->n_faces > shape->n_faces)
            shape = s;
    }
    int failed = shape == NULL;
#ifdef PCB_HAVE_OCCT_READ
    pcb_occt_model *om = shape ? pcb_occt_model_read(path) : NULL;
    if (shape && om == NULL) {
        fprintf(stderr, "%s: Open CASCADE's reader failed\n", path);
        failed = 1;
    }
#endif
    shape_frame f;
    if (shape)
        frame_of(shape, &f);
    const char *profile_env = getenv("PCB_PROFILE_SECONDS");
    const double profile_s = profile_env ? atof(profile_env) : 0.0;
    for (int k = 0; shape && k < 2 * N_CURVES; ++k) {
        const int conical = k / N_CURVES, which = k % N_CURVES;
        if (args->quick && which != 0)
            continue;
        shape_row row;
        memset(&row, 0, sizeof row);
        snprintf(row.name, sizeof row.name, "%s %s %s", rel + 5, curve_names[which],
                 conical ? "conical" : "dir");
        if (args->only_case != NULL && strstr(row.name, args->only_case) == NULL)
            continue;
        projcurve_curve *curve = NULL;
        if (make_curve(&f, which, &curve) != PROJCURVE_OK) {
            failed = 1;
            continue;
        }
        double vec[3];
        frame_vec(&f, conical, vec);
        ours_work w = {shape, curve,
                       conical ? PROJCURVE_PROJECT_CONICAL : PROJCURVE_PROJECT_DIRECTIONAL, vec,
                       NULL};
        if (profile_s > 0.0) {
            /* a profiler's run: only our projection, over and over */
            const double t0 = pcb_now_s();
            size_t calls = 0;
            while (pcb_now_s() - t0 < profile_s && work_ours(&w, 1) == 0)
                ++calls;
            printf("%-30s %zu calls, %.3f ms each\n", row.name, calls,
                   1e3 * (pcb_now_s() - t0) / (double)(calls ? calls : 1));
            projcurve_curve_destroy(curve);
            continue;
        }
        int rc = run_ours(timing, &w, 0.0, conical, &row.ours);
#ifdef PCB_HAVE_OCCT_READ
        if (rc == 0 && om != NULL && run_occt(args, om, shape, curve, conical, vec, &row) != 0)
            failed = 1;
        /* equal or better measured accuracy: ours again below Open CASCADE's error */
        if (rc == 0 && row.have_occt && worst(&row.ours.acc) > worst(&row.occt_acc)) {
            const double eps = fmax(0.5 * worst(&row.occt_acc), SHAPE_MATCH_FLOOR * f.size);
            rc = run_ours(timing, &w, eps, conical, &row.ours);
        }
#endif
        if (rc != 0) {
            fprintf(stderr, "%s: our projection failed\n", row.name);
            failed = 1;
        } else {
            print_row(&row);
            json_row(json, &row);
            plot_add(plot, &row);
        }
        projcurve_curve_destroy(curve);
        fflush(stdout);
    }
#ifdef PCB_HAVE_OCCT_READ
    pcb_occt_model_free(om);
#endif
    projcurve_model_destroy(model);
    projcurve_context_destroy(ctx);
    return failed;
}

int pcb_cmd_shape(const pcb_args *args)
{
    pcb_print_banner("shape: curves onto whole models, ours vs BRepProj_Projection", args);
#ifndef PCB_HAVE_OCCT_READ
    printf("BENCH-SKIPPED: Open CASCADE (with its STEP / IGES readers) was not found at "
           "configure time: our side only, no comparison\n");
#endif
    pcb_json json;
    if (pcb_json_open(&json, args->json_path) != 0)
        return 2;
    pcb_json_object_begin(&json, NULL);
    pcb_json_array_begin(&json, "cases");
    printf("%-30s %9s %4s %5s %6s %9s %9s %10s %4s %5s %6s %9s %9s %9s\n", "case", "ours ms",
           "crv", "pcs", "poles", "face err", "ray err", "occt ms", "wire", "edges", "poles",
           "face err", "ray err", "ours/occt");
    const pcb_timing timing = pcb_timing_for(args, SHAPE_REPS, SHAPE_MIN_RUN_S);
    int failed = 0;
    shape_plot times = {.n = 0};
    /* --quick (the CI smoke run, also under the sanitizers): the line
     * cases of the two-face model, a second where hammer's take minutes */
    const size_t n_models = args->quick ? 1 : sizeof shape_models / sizeof *shape_models;
    for (size_t m = 0; m < n_models; ++m)
        failed |= bench_model(args, args->quick ? shape_models[3] : shape_models[m], &timing, &json,
                              &times);
    pcb_json_array_end(&json);
    pcb_json_object_end(&json);
    if (args->svg_path != NULL) {
        const pcb_series series[2] = {{"ours (projcurve_project_shape)", times.x, times.ours, times.n},
                                      {"BRepProj_Projection", times.x, times.occt, times.n}};
        const pcb_plot plot = {"curves onto whole models (cases in the table's order)", "case",
                               "ms per projection", 0, 1, series, 2};
        if (pcb_svg_write(args->svg_path, &plot, 1) != 0)
            failed = 2;
    }
    return pcb_json_close(&json) != 0 ? 2 : failed;
}
