/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench brep: time to read and build each real model (surfaces
 * with their patch grids and BVHs, faces with their flattened loops and
 * classification grids, shapes), and nanoseconds per point classified on
 * its faces (projcurve_face_classify), beside the same points counted over
 * every segment of the face's loops (the winding number without the grid)
 * in the same run; and, where Open CASCADE's data exchange toolkits are
 * installed, its reader on the same file (time, faces, wires).
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "brep/face.h"
#include "json.h"
#include "svg.h"
#ifdef PCB_HAVE_OCCT_READ
#include "occt_read.h"
#endif

#define BREP_POINTS 4096 /* sample points per face, cycled through */
#define BREP_REPS 9
#define BREP_MIN_RUN_S 0.02
#define BREP_SEED 0xb4e9ULL

static const char *const brep_models[] = {
    "real/sunglasses_lens.igs", "real/bladex_upper.iges", "real/hammer.iges",
    "real/bearing.iges", "real/linkrods.step", "real/test-joinsurf_01.stp",
    "real/test-joinsurf_04.stp", "real/test_pipe_out_true.step"};

typedef struct read_work {
    const char *path;
} read_work;

static int work_read(void *user, size_t n)
{
    const read_work *w = user;
    for (size_t i = 0; i < n; ++i) {
        projcurve_model *m = NULL;
        if (projcurve_model_read_file(NULL, w->path, &m) != PROJCURVE_OK)
            return 1;
        pcb_consume((double)projcurve_model_face_count(m));
        projcurve_model_destroy(m);
    }
    return 0;
}

typedef struct classify_work {
    const projcurve_model *model;
    double *uv; /* 2 * BREP_POINTS per face */
    size_t next;
} classify_work;

#ifdef PCB_HAVE_OCCT_READ
/* Median CPU ms of Open CASCADE's reader over reps runs (one untimed). */
static int occt_read_ms(const char *path, int reps, double *ms, int *faces, int *wires)
{
    double t[PCB_MAX_REPS];
    if (reps > PCB_MAX_REPS)
        reps = PCB_MAX_REPS;
    for (int i = 0; i <= reps; ++i) {
        double s = 0.0;
        if (pcb_occt_read(path, &s, faces, wires) != 0)
            return -1;
        if (i > 0)
            t[i - 1] = s;
    }
    *ms = 1e3 * pcb_median(t, (size_t)reps);
    return 0;
}
#endif

static int work_classify(void *user, size_t n)
{
    classify_work *w = user;
    const size_t faces = projcurve_model_face_count(w->model);
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i, ++w->next) {
        const size_t k = w->next % (faces * BREP_POINTS);
        projcurve_where where = PROJCURVE_OUT;
        projcurve_face_classify(NULL, projcurve_model_face(w->model, k / BREP_POINTS),
                                w->uv[2 * k], w->uv[2 * k + 1], &where);
        acc += (double)where;
    }
    pcb_consume(acc);
    return 0;
}

static int work_brute(void *user, size_t n)
{
    classify_work *w = user;
    const size_t faces = projcurve_model_face_count(w->model);
    double acc = 0.0;
    for (size_t i = 0; i < n; ++i, ++w->next) {
        const size_t k = w->next % (faces * BREP_POINTS);
        const projcurve_face *f = projcurve_model_face(w->model, k / BREP_POINTS);
        acc += pc_winding_brute(f->cls.seg, f->cls.n_seg, w->uv[2 * k], w->uv[2 * k + 1]);
    }
    pcb_consume(acc);
    return 0;
}

int pcb_cmd_brep(const pcb_args *args)
{
    pcb_print_banner("brep: read + build each model, classification ns per point", args);
    pcb_json json;
    if (pcb_json_open(&json, args->json_path) != 0)
        return 2;
    pcb_json_object_begin(&json, NULL);
    pcb_json_array_begin(&json, "models");
    const pcb_timing timing = pcb_timing_for(args, BREP_REPS, BREP_MIN_RUN_S);
    int failed = 0;
    enum { N_MODELS = sizeof brep_models / sizeof *brep_models };
    double xs[N_MODELS], grid_ns[N_MODELS], brute_ns[N_MODELS];
    size_t n_plotted = 0;
    printf("%-26s %6s %6s %8s %10s %12s %12s %8s%s\n", "model", "faces", "loops", "segments",
           "read ms", "classify ns", "brute ns", "brute/x",
#ifdef PCB_HAVE_OCCT_READ
           "    occt ms faces/wires"
#else
           ""
#endif
    );
    for (size_t m = 0; m < sizeof brep_models / sizeof *brep_models; ++m) {
        char path[4096];
        pcb_join_path(path, sizeof path, args->data_dir, brep_models[m]);
        projcurve_context *ctx = NULL;
        projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
        projcurve_model *model = NULL;
        if (!pcb_ok(ctx, projcurve_model_read_file(ctx, path, &model), path)) {
            projcurve_context_destroy(ctx);
            failed = 1;
            continue;
        }
        const size_t faces = projcurve_model_face_count(model);
        size_t loops = 0, segments = 0;
        classify_work cw = {.model = model, .uv = malloc((2 * faces * BREP_POINTS + 1) * sizeof(double))};
        unsigned long long seed = BREP_SEED;
        for (size_t f = 0; f < faces && cw.uv; ++f) {
            const projcurve_face *face = projcurve_model_face(model, f);
            loops += projcurve_face_loop_count(face);
            segments += face->cls.n_seg;
            double box[4];
            projcurve_face_bounds(NULL, face, box, NULL);
            for (size_t i = 0; i < BREP_POINTS; ++i) {
                double *uv = cw.uv + 2 * (f * BREP_POINTS + i);
                uv[0] = box[0] + (box[1] - box[0]) * pcb_rand01(&seed);
                uv[1] = box[2] + (box[3] - box[2]) * pcb_rand01(&seed);
            }
        }
        read_work rw = {path};
        double read_s = 0.0;
        pcb_pair pair = {0, 0, 0};
        const int ok = cw.uv != NULL && faces > 0 && pcb_time_median(&timing, work_read, &rw, &read_s) == 0 &&
                       pcb_time_pair(&timing, work_classify, &cw, work_brute, &cw, &pair) == 0;
        failed |= !ok && faces > 0;
        const char *name = brep_models[m] + 5;
        double occt_ms = -1.0;
        int occt_faces = -1, occt_wires = -1;
#ifdef PCB_HAVE_OCCT_READ
        if (occt_read_ms(path, args->quick ? 1 : 5, &occt_ms, &occt_faces, &occt_wires) != 0)
            failed = 1;
#endif
        printf("%-26s %6zu %6zu %8zu %10.2f %12.1f %12.1f %8.1f", name, faces, loops, segments,
               1e3 * read_s, 1e9 * pair.a_s, 1e9 * pair.b_s, pair.a_s > 0 ? pair.b_s / pair.a_s : 0.0);
        if (occt_ms >= 0.0)
            printf(" %10.1f %5d/%d", occt_ms, occt_faces, occt_wires);
        printf("\n");
        if (ok) {
            xs[n_plotted] = (double)segments / (double)faces;
            grid_ns[n_plotted] = 1e9 * pair.a_s;
            brute_ns[n_plotted++] = 1e9 * pair.b_s;
        }
        pcb_json_object_begin(&json, NULL);
        pcb_json_string(&json, "model", name);
        pcb_json_int(&json, "faces", (long long)faces);
        pcb_json_int(&json, "unbuilt", (long long)projcurve_model_unbuilt_face_count(model));
        pcb_json_int(&json, "loops", (long long)loops);
        pcb_json_int(&json, "segments", (long long)segments);
        pcb_json_number(&json, "read_ms", 1e3 * read_s);
        pcb_json_number(&json, "classify_ns", 1e9 * pair.a_s);
        pcb_json_number(&json, "brute_ns", 1e9 * pair.b_s);
        if (occt_ms >= 0.0) {
            pcb_json_number(&json, "occt_read_ms", occt_ms);
            pcb_json_int(&json, "occt_faces", occt_faces);
            pcb_json_int(&json, "occt_wires", occt_wires);
        } else {
            pcb_json_null(&json, "occt_read_ms");
        }
        pcb_json_object_end(&json);
        free(cw.uv);
        projcurve_model_destroy(model);
        projcurve_context_destroy(ctx);
    }
    pcb_json_array_end(&json);
    pcb_json_object_end(&json);
    const pcb_series series[2] = {{"grid (projcurve_face_classify)", xs, grid_ns, n_plotted},
                                  {"every segment", xs, brute_ns, n_plotted}};
    const pcb_plot plot = {"classification of (u, v) points on the real models' faces",
                           "loop segments per face (mean)", "ns per point", 1, 1, series, 2};
    if (args->svg_path != NULL && pcb_svg_write(args->svg_path, &plot, 1) != 0)
        failed = 2;
    return pcb_json_close(&json) != 0 ? 2 : failed;
}
