/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Faces of the real models: face and loop counts equal to Open CASCADE's
 * reading of the same files (STEPControl_Reader / IGESControl_Reader,
 * TopExp faces and wires), every loop closed in (u, v) and in 3D, and
 * every face's classification against brute force: its pieces sampled
 * densely by the test's own de Boor evaluation (tests/support/deboor.c),
 * an even-odd count over that polyline, on a grid over the face's box.
 * Points nearer the sampled loops than the sampling error plus twice the
 * face's ON tolerance are not judged; every other one must agree.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "deboor.h"
#include "projcurve.h"

#define SAMPLES_PER_PIECE 48
/* Grid intervals per direction of the classification check. The brute
 * force costs grid points times loop samples on each of ~300 faces, most of
 * this test's time: the slow builds (sanitizers, coverage) judge a coarser
 * grid, which still reaches every face and every branch of the classifier. */
#if PC_TEST_SLOWDOWN > 1
#define GRID 14
#else
#define GRID 40
#endif

typedef struct expected {
    const char *file;
    size_t faces, loops;
    /* faces that are not built: counted with the faces, their loops not */
    size_t unbuilt;
    size_t shared; /* edges used by two pieces at least (read, or sewn for IGES) */
    size_t max_poles; /* of all loop pieces (0: not checked) */
} expected;

/* Open CASCADE 7.x: faces / wires of each file (the table). */
static const expected models[] = {
    {"real/sunglasses_lens.igs", 9, 9, 0, 0, 0},
    {"real/bearing.iges", 213, 213, 0, 450, 0},
    {"real/bladex_upper.iges", 1, 1, 0, 0, 0},
    {"real/hammer.iges", 45, 48, 0, 104, 0},
    {"real/test-joinsurf_01.stp", 2, 2, 0, 0, 0},
    {"real/test-joinsurf_04.stp", 2, 2, 0, 0, 0},
    {"real/test_pipe_out_true.step", 6, 6, 0, 0, 0},
    /* linkrods: 85 pcurves mapped onto tori and cylinders, refitted as
     * cubics (24,158 poles as polylines) */
    {"real/linkrods.step", 37, 42, 0, 82, 5000},
};

typedef struct sampled {
    double *xy; /* polyline of all loops, 2 per point */
    size_t *loop_end;
    size_t n_loops, n;
    double err; /* the largest distance of a piece's mid-sample from its chord */
} sampled;

static void piece_point(const projcurve_face *f, size_t l, size_t k, double s, double out[2])
{
    int degree = 0, sense = 1;
    size_t n_ctrl = 0;
    const double *ctrl = NULL, *weights = NULL, *knots = NULL;
    projcurve_face_piece_curve(NULL, f, l, k, &degree, &n_ctrl, &ctrl, &weights, &knots, &sense);
    double *c3 = malloc(3 * n_ctrl * sizeof *c3);
    for (size_t i = 0; i < n_ctrl; ++i)
        c3[3 * i] = ctrl[2 * i], c3[3 * i + 1] = ctrl[2 * i + 1], c3[3 * i + 2] = 0.0;
    const pc_shape_curve c = {degree, n_ctrl, c3, (double *)weights, (double *)knots};
    const double t0 = knots[degree], t1 = knots[n_ctrl];
    const double t = sense > 0 ? t0 + s * (t1 - t0) : t1 - s * (t1 - t0);
    double p[3];
    pc_deboor_curve(&c, t, p);
    out[0] = p[0], out[1] = p[1];
    free(c3);
}

static void sample_face(const projcurve_face *f, sampled *out)
{
    size_t total = 0;
    const size_t n_loops = projcurve_face_loop_count(f);
    for (size_t l = 0; l < n_loops; ++l) {
        size_t n = 0;
        projcurve_face_loop_piece_count(NULL, f, l, &n);
        total += n * SAMPLES_PER_PIECE;
    }
    out->xy = malloc(2 * total * sizeof *out->xy);
    out->loop_end = malloc(n_loops * sizeof *out->loop_end);
    out->n_loops = n_loops;
    out->n = 0;
    out->err = 0.0;
    for (size_t l = 0; l < n_loops; ++l) {
        size_t n = 0;
        projcurve_face_loop_piece_count(NULL, f, l, &n);
        for (size_t k = 0; k < n; ++k)
            for (int j = 0; j < SAMPLES_PER_PIECE; ++j) {
                double a[2], b[2], m[2];
                piece_point(f, l, k, (double)j / SAMPLES_PER_PIECE, a);
                piece_point(f, l, k, (j + 1.0) / SAMPLES_PER_PIECE, b);
                piece_point(f, l, k, (j + 0.5) / SAMPLES_PER_PIECE, m);
                out->err = fmax(out->err, hypot(m[0] - 0.5 * (a[0] + b[0]), m[1] - 0.5 * (a[1] + b[1])));
                out->xy[2 * out->n] = a[0], out->xy[2 * out->n + 1] = a[1];
                ++out->n;
            }
        out->loop_end[l] = out->n;
    }
}

static void brute(const sampled *s, double x, double y, int *inside, double *dist)
{
    int in = 0;
    double d = INFINITY;
    size_t begin = 0;
    for (size_t l = 0; l < s->n_loops; ++l) {
        const size_t end = s->loop_end[l];
        for (size_t i = begin; i < end; ++i) {
            const size_t j = i + 1 < end ? i + 1 : begin;
            const double *p = s->xy + 2 * i, *q = s->xy + 2 * j;
            if ((p[1] > y) != (q[1] > y) && x < (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]) + p[0])
                in = !in;
            const double ex = q[0] - p[0], ey = q[1] - p[1], len2 = ex * ex + ey * ey;
            double t = len2 > 0 ? ((x - p[0]) * ex + (y - p[1]) * ey) / len2 : 0.0;
            t = fmin(fmax(t, 0.0), 1.0);
            d = fmin(d, hypot(x - p[0] - t * ex, y - p[1] - t * ey));
        }
        begin = end;
    }
    *inside = in;
    *dist = d;
}

/* Consecutive pieces meet within 10 tol_uv in (u, v), and their surface
 * points within 10 times the model precision. */
static void check_closed(const projcurve_face *f, const char *file, size_t face)
{
    double tol_uv = 0, tol_model = 0;
    projcurve_face_tolerance(NULL, f, &tol_uv, &tol_model);
    const projcurve_surface *s = projcurve_face_surface(f);
    for (size_t l = 0; l < projcurve_face_loop_count(f); ++l) {
        size_t n = 0;
        projcurve_face_loop_piece_count(NULL, f, l, &n);
        for (size_t k = 0; k < n; ++k) {
            double e[2], b[2], pe[3], pb[3];
            piece_point(f, l, k, 1.0, e);
            piece_point(f, l, (k + 1) % n, 0.0, b);
            const double gap = hypot(e[0] - b[0], e[1] - b[1]);
            double d[4];
            projcurve_surface_domain(NULL, s, d);
            projcurve_surface_eval(NULL, s, fmin(fmax(e[0], d[0]), d[1]), fmin(fmax(e[1], d[2]), d[3]), 0, pe);
            projcurve_surface_eval(NULL, s, fmin(fmax(b[0], d[0]), d[1]), fmin(fmax(b[1], d[2]), d[3]), 0, pb);
            const double gap3 = hypot(hypot(pe[0] - pb[0], pe[1] - pb[1]), pe[2] - pb[2]);
            ++pc_test_checks;
            if (!(gap <= 10 * tol_uv) || !(gap3 <= 10 * tol_model))
                pc_test_fail_at(__FILE__, __LINE__, "%s face %zu loop %zu: pieces %zu, %zu apart by %g in (u, v) (tol %g), %g in 3D (tol %g)",
                                file, face, l, k, (k + 1) % n, gap, tol_uv, gap3, tol_model);
        }
    }
}

static size_t loop_poles(const projcurve_face *f)
{
    size_t total = 0;
    for (size_t l = 0; l < projcurve_face_loop_count(f); ++l) {
        size_t n = 0;
        projcurve_face_loop_piece_count(NULL, f, l, &n);
        for (size_t k = 0; k < n; ++k) {
            size_t n_ctrl = 0;
            projcurve_face_piece_curve(NULL, f, l, k, NULL, &n_ctrl, NULL, NULL, NULL, NULL);
            total += n_ctrl;
        }
    }
    return total;
}

static void check_classification(const projcurve_face *f, const char *file, size_t face,
                                 size_t *judged)
{
    sampled s;
    sample_face(f, &s);
    double box[4], tol_uv = 0;
    projcurve_face_bounds(NULL, f, box, NULL);
    projcurve_face_tolerance(NULL, f, &tol_uv, NULL);
    const double margin = s.err + 2.0 * tol_uv;
    const double wu = box[1] - box[0], wv = box[3] - box[2];
    int wrong = 0;
    for (int i = 0; i <= GRID; ++i)
        for (int j = 0; j <= GRID; ++j) {
            const double u = box[0] - 0.05 * wu + 1.1 * wu * (i + 0.37) / GRID;
            const double v = box[2] - 0.05 * wv + 1.1 * wv * (j + 0.61) / GRID;
            int in;
            double d;
            brute(&s, u, v, &in, &d);
            projcurve_where w;
            CHECK_OK(projcurve_face_classify(NULL, f, u, v, &w));
            if (d <= margin)
                continue;
            ++*judged;
            if (w != (in ? PROJCURVE_IN : PROJCURVE_OUT) && wrong++ < 3)
                pc_test_fail_at(__FILE__, __LINE__, "%s face %zu: (%.17g, %.17g), %g from the loops, is %d, brute force says %s",
                                file, face, u, v, d, (int)w, in ? "in" : "out");
        }
    CHECK(wrong == 0);
    free(s.xy);
    free(s.loop_end);
}

static double dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* The 3D point of a piece at fraction a along its edge's direction. */
static void edge_point(const projcurve_face *f, size_t l, size_t k, double a, double p[3])
{
    int edge_sense = 1, sense = 1;
    projcurve_face_piece_edge(NULL, f, l, k, NULL, &edge_sense, NULL);
    projcurve_face_piece_curve(NULL, f, l, k, NULL, NULL, NULL, NULL, NULL, &sense);
    /* piece_point runs in the loop's direction; the loop runs along the
     * edge when sense * edge_sense > 0 */
    double uv[2], d[4];
    piece_point(f, l, k, sense * edge_sense > 0 ? a : 1.0 - a, uv);
    const projcurve_surface *s = projcurve_face_surface(f);
    projcurve_surface_domain(NULL, s, d);
    projcurve_surface_eval(NULL, s, fmin(fmax(uv[0], d[0]), d[1]), fmin(fmax(uv[1], d[2]), d[3]), 0, p);
}

/* 1 when the model lists the edge as disagreeing with its pcurve. */
static int reported(const projcurve_model *m, long id)
{
    char text[64];
    snprintf(text, sizeof text, "STEP #%ld EDGE_CURVE", id);
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i)
        if (strstr(projcurve_model_skipped(m, i), text) != NULL)
            return 1;
    return 0;
}

/* The 3D polyline of a use of an edge, 65 points along the edge, and its
 * length and longest chord. */
typedef struct edge_line {
    double p[65][3];
    double length, chord;
} edge_line;

static void edge_line_of(const projcurve_shape *shape, size_t e, size_t use, edge_line *out)
{
    size_t f, l, k;
    projcurve_shape_edge_use(NULL, shape, e, use, &f, &l, &k, NULL);
    const projcurve_face *face = projcurve_shape_face(shape, f);
    out->length = out->chord = 0.0;
    for (int i = 0; i <= 64; ++i) {
        edge_point(face, l, k, i / 64.0, out->p[i]);
        if (i > 0) {
            const double c = dist3(out->p[i - 1], out->p[i]);
            out->length += c;
            out->chord = fmax(out->chord, c);
        }
    }
}

/* The farthest of 9 points of b from a's polyline. */
static double farthest_from(const edge_line *b, const edge_line *a)
{
    double worst = 0.0;
    for (int i = 0; i <= 64; i += 8) {
        double best = INFINITY;
        for (int j = 0; j <= 64; ++j)
            best = fmin(best, dist3(b->p[i], a->p[j]));
        worst = fmax(worst, best);
    }
    return worst;
}

/* Every edge shared by two pieces or more (read or sewn): 9 points of each
 * piece lie within 2 tol (+ the chord error) of a 64-point polyline of the
 * longest one, and two pieces of one length start and end together along
 * the edge; tol is the sewing tolerance, or for a read edge the 100
 * precisions beyond which the reader reports a pcurve off its edge (and a
 * reported edge is not judged). An edge of three uses or more is one that
 * a face splits where its neighbour does not. */
static void check_shared_edges(const projcurve_model *m, const char *file, size_t *shared)
{
    for (size_t sh = 0; sh < projcurve_model_shape_count(m); ++sh) {
        const projcurve_shape *shape = projcurve_model_shape(m, sh);
        double sew = 0.0;
        projcurve_shape_info(NULL, shape, NULL, &sew);
        for (size_t e = 0; e < projcurve_shape_edge_count(shape); ++e) {
            size_t uses = 0;
            long id = 0;
            projcurve_shape_edge(NULL, shape, e, &id, &uses);
            CHECK(uses <= 8);
            if (uses < 2 || uses > 8 || (sew == 0.0 && reported(m, id)))
                continue;
            ++*shared;
            size_t fa, la, ka;
            projcurve_shape_edge_use(NULL, shape, e, 0, &fa, &la, &ka, NULL);
            double tol_model = 0.0;
            projcurve_face_tolerance(NULL, projcurve_shape_face(shape, fa), NULL, &tol_model);
            const double tol = 2.0 * (sew > 0.0 ? sew : 100.0 * tol_model);
            edge_line line[8];
            size_t longest = 0;
            for (size_t u = 0; u < uses; ++u) {
                edge_line_of(shape, e, u, &line[u]);
                if (line[u].length > line[longest].length)
                    longest = u;
            }
            for (size_t u = 0; u < uses; ++u) {
                const edge_line *a = &line[longest], *b = &line[u];
                const double worst = farthest_from(b, a);
                const double ends = fmax(dist3(a->p[0], b->p[0]), dist3(a->p[64], b->p[64]));
                const int same_length = fabs(a->length - b->length) <= tol;
                ++pc_test_checks;
                if (!(worst <= tol + a->chord) || (same_length && !(ends <= tol)))
                    pc_test_fail_at(__FILE__, __LINE__, "%s edge %ld: use %zu is %g from the longest use (ends %g), tolerance %g",
                                    file, id, u, worst, ends, tol);
            }
        }
    }
}

int main(void)
{
    for (size_t m = 0; m < sizeof models / sizeof *models; ++m) {
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        projcurve_model *model = NULL;
        if (projcurve_model_read_file(ctx, pc_test_data_path(models[m].file), &model) != PROJCURVE_OK)
            pc_test_missing_data(models[m].file);
        const size_t n_faces = projcurve_model_face_count(model);
        size_t loops = 0, judged = 0, poles = 0;
        for (size_t i = 0; i < n_faces; ++i) {
            const projcurve_face *f = projcurve_model_face(model, i);
            loops += projcurve_face_loop_count(f);
            poles += loop_poles(f);
            check_closed(f, models[m].file, i);
            check_classification(f, models[m].file, i, &judged);
        }
        const size_t unbuilt = projcurve_model_unbuilt_face_count(model);
        if (n_faces + unbuilt != models[m].faces || loops != models[m].loops ||
            unbuilt != models[m].unbuilt)
            pc_test_fail_at(__FILE__, __LINE__, "%s: %zu faces (%zu unbuilt), %zu loops; expected %zu (%zu), %zu",
                            models[m].file, n_faces + unbuilt, unbuilt, loops, models[m].faces,
                            models[m].unbuilt, models[m].loops);
        ++pc_test_checks;
        for (size_t i = 0; i < projcurve_model_unbuilt_face_count(model); ++i)
            printf("%s: unbuilt: %s\n", models[m].file, projcurve_model_unbuilt_face(model, i));
        printf("%s: %zu faces, %zu loops of %zu poles, %zu points judged\n", models[m].file,
               n_faces, loops, poles, judged);
        CHECK(models[m].max_poles == 0 || poles <= models[m].max_poles);
        size_t shared = 0;
        check_shared_edges(model, models[m].file, &shared);
        printf("%s: %zu edges shared by two faces\n", models[m].file, shared);
        CHECK(shared >= models[m].shared);
        /* every built face is in a shape */
        size_t in_shapes = 0;
        for (size_t k = 0; k < projcurve_model_shape_count(model); ++k)
            in_shapes += projcurve_shape_face_count(projcurve_model_shape(model, k));
        CHECK(in_shapes == n_faces);
        /* most grid points are judged: 1000 of the 41 x 41 in the plain build */
        CHECK(judged * 41 * 41 > 1000 * (GRID + 1) * (GRID + 1) * n_faces);
        projcurve_model_destroy(model);
        projcurve_context_destroy(ctx);
    }
    return pc_test_finish("test_brep_real");
}
