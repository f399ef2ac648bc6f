/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES writer round trips: surfaces, curves and a projection result written
 * and read back give the same knots, weights and control points (17
 * significant digits reproduce every double, so the comparison is to 1e-12
 * relative only to allow the x = (w x) / w division of the storage), and
 * the same points on dense samples. Writing what was read gives the same
 * text again. A written curve on surface (142) is one curve: S composed
 * with its pcurve is its 3D curve.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "io/iges.h"
#include "io/iges_write.h"
#include "projcurve.h"
#include "trace/result.h"

#define ROUND_TRIP_REL 1e-12

static projcurve_context *ctx;
static char path_a[256], path_b[256];

static double rel_tol(double scale)
{
    return ROUND_TRIP_REL * (fabs(scale) > 1.0 ? fabs(scale) : 1.0);
}

static void same_doubles(const double *a, const double *b, size_t n, const char *what)
{
    for (size_t i = 0; i < n; ++i)
        if (!(fabs(a[i] - b[i]) <= rel_tol(a[i]))) {
            pc_test_fail_at(__FILE__, __LINE__, "%s[%zu]: %.17g vs %.17g", what, i, a[i], b[i]);
            return;
        }
    ++pc_test_checks;
}

static void same_surface(const projcurve_surface *a, const projcurve_surface *b)
{
    const pc_nurbs_surface *x = &a->nurbs, *y = &b->nurbs;
    CHECK(x->deg_u == y->deg_u && x->deg_v == y->deg_v && x->n_u == y->n_u && x->n_v == y->n_v);
    CHECK(x->rational == y->rational);
    if (!(x->deg_u == y->deg_u && x->deg_v == y->deg_v && x->n_u == y->n_u && x->n_v == y->n_v))
        return;
    same_doubles(x->knots_u, y->knots_u, x->n_u + (size_t)x->deg_u + 1, "knots_u");
    same_doubles(x->knots_v, y->knots_v, x->n_v + (size_t)x->deg_v + 1, "knots_v");
    same_doubles(x->cw, y->cw, 4 * x->n_u * x->n_v, "homogeneous points");
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
            const double u = x->domain[0] + (x->domain[1] - x->domain[0]) * i / 10.0;
            const double v = x->domain[2] + (x->domain[3] - x->domain[2]) * j / 10.0;
            double p[3], q[3];
            CHECK_OK(projcurve_surface_eval(ctx, a, u, v, 0, p));
            CHECK_OK(projcurve_surface_eval(ctx, b, u, v, 0, q));
            for (int k = 0; k < 3; ++k)
                CHECK_NEAR(q[k], p[k], rel_tol(a->size));
        }
}

static void same_curve(const projcurve_curve *a, const projcurve_curve *b)
{
    const pc_nurbs_curve *x = &a->nurbs, *y = &b->nurbs;
    CHECK(x->degree == y->degree && x->n_ctrl == y->n_ctrl && x->rational == y->rational);
    if (!(x->degree == y->degree && x->n_ctrl == y->n_ctrl))
        return;
    same_doubles(x->knots, y->knots, x->n_ctrl + (size_t)x->degree + 1, "knots");
    same_doubles(x->cw, y->cw, 4 * x->n_ctrl, "homogeneous points");
    for (int i = 0; i <= 50; ++i) {
        const double t = x->t0 + (x->t1 - x->t0) * i / 50.0;
        double p[3], q[3];
        CHECK_OK(projcurve_curve_eval(ctx, a, t, 0, p));
        CHECK_OK(projcurve_curve_eval(ctx, b, t, 0, q));
        for (int k = 0; k < 3; ++k)
            CHECK_NEAR(q[k], p[k], rel_tol(p[k]));
    }
}

static projcurve_model *read_back(const char *path)
{
    projcurve_model *m = NULL;
    const projcurve_status st = projcurve_model_read_file(ctx, path, &m);
    if (st != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "reading %s back: %s", path,
                        projcurve_context_message(ctx));
    return m;
}

/* An exact quarter cylinder (rational, u) x a cubic in v with uneven knots,
 * at a large offset so that digits matter. */
static projcurve_surface *rational_surface(void)
{
    const double w = sqrt(0.5);
    double ctrl[3 * 3 * 5], weights[3 * 5];
    for (int j = 0; j < 5; ++j) {
        const double y = 1e4 + 0.37 * j * j, lift = 0.1 * sin(j);
        const double px[3] = {3.0, 3.0, 0.0}, pz[3] = {0.0, 3.0, 3.0}, pw[3] = {1.0, w, 1.0};
        for (int i = 0; i < 3; ++i) {
            ctrl[3 * (j * 3 + i)] = -2e4 + px[i];
            ctrl[3 * (j * 3 + i) + 1] = y;
            ctrl[3 * (j * 3 + i) + 2] = pz[i] + lift;
            weights[j * 3 + i] = pw[i];
        }
    }
    const double ku[] = {0, 0, 0, 1, 1, 1};
    const double kv[] = {0, 0, 0, 0, 0.1234567890123, 1.0 / 3.0, 1, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 2, 3, 3, 5, ctrl, weights, ku, kv, &s));
    return s;
}

static projcurve_surface *plane_surface(void)
{
    const double ctrl[] = {0, 0, 0, 10, 0, 0, 0, 10, 0, 10, 10, 0};
    const double k[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, ctrl, NULL, k, k, &s));
    return s;
}

static projcurve_curve *test_curve(int rational)
{
    const double ctrl[] = {1e-7, 2.0, 3.0, 4.5, -1.25, 1e5, 7.0, 7.0, 7.0, 0.1, 0.2, 0.3};
    const double weights[] = {1.0, 0.3, 2.5, 1.0};
    /* Unclamped input: creation clamps it exactly. */
    const double knots[] = {-1.0, -0.5, 0.0, 0.7, 1.0, 1.5, 2.25};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 2, 4, ctrl, rational ? weights : NULL, knots, &c));
    return c;
}

static void surfaces_and_curves(void)
{
    projcurve_surface *s1 = rational_surface(), *s2 = plane_surface();
    projcurve_curve *c1 = test_curve(0), *c2 = test_curve(1);
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, s1));
    CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, s2));
    CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, s1)); /* written once */
    CHECK_OK(projcurve_iges_writer_add_curve(ctx, w, c1));
    CHECK_OK(projcurve_iges_writer_add_curve(ctx, w, c2));
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path_a));
    projcurve_iges_writer_destroy(w);

    projcurve_model *m = read_back(path_a);
    if (m) {
        CHECK(projcurve_model_surface_count(m) == 2);
        CHECK(projcurve_model_curve_count(m) == 2);
        CHECK(projcurve_model_skipped_count(m) == 0);
        if (projcurve_model_surface_count(m) == 2 && projcurve_model_curve_count(m) == 2) {
            same_surface(s1, projcurve_model_surface(m, 0));
            same_surface(s2, projcurve_model_surface(m, 1));
            same_curve(c1, projcurve_model_curve(m, 0));
            same_curve(c2, projcurve_model_curve(m, 1));
        }
        /* Writing what was read gives the same file. */
        CHECK_OK(projcurve_iges_writer_create(ctx, &w));
        for (size_t i = 0; i < projcurve_model_surface_count(m); ++i)
            CHECK_OK(projcurve_iges_writer_add_surface(ctx, w, projcurve_model_surface(m, i)));
        for (size_t i = 0; i < projcurve_model_curve_count(m); ++i)
            CHECK_OK(projcurve_iges_writer_add_curve(ctx, w, projcurve_model_curve(m, i)));
        CHECK_OK(projcurve_iges_writer_write(ctx, w, path_b));
        projcurve_iges_writer_destroy(w);
        char *a = pc_test_read_file(path_a, NULL), *b = pc_test_read_file(path_b, NULL);
        CHECK(a != NULL && b != NULL && strcmp(a, b) == 0);
        /* Every record is 80 columns. */
        size_t col = 0, bad = 0;
        for (const char *q = a; q && *q; ++q) {
            if (*q == '\n') {
                bad += (col != 80);
                col = 0;
            } else {
                ++col;
            }
        }
        CHECK(bad == 0);
        free(a);
        free(b);
        projcurve_model_destroy(m);
    }
    projcurve_surface_destroy(s1);
    projcurve_surface_destroy(s2);
    projcurve_curve_destroy(c1);
    projcurve_curve_destroy(c2);
}

/* A hand-made result on the plane S(u, v) = (10u, 10v, 0): one branch along
 * v = 0.5 from u = 0.1 to 0.9, composed as one line piece. */
static projcurve_result *line_result(void)
{
    projcurve_result *r = NULL;
    pc_branch *b = NULL;
    CHECK_OK(pc_result_create(ctx, 3, &r));
    if (r == NULL)
        return NULL;
    CHECK_OK(pc_result_add_branch(ctx, r, &b));
    for (int i = 0; i <= 8; ++i) {
        const double t = i / 8.0, p[3] = {t, 0.1 + 0.8 * t, 0.5};
        CHECK_OK(pc_branch_add_point(ctx, b, 3, p));
    }
    const double uv[4] = {0.1, 0.5, 0.9, 0.5}, ctrl[6] = {1, 5, 0, 9, 5, 0};
    CHECK_OK(pc_branch_add_piece(ctx, b, 1, 0.0, 1.0, uv, ctrl, NULL));
    return r;
}

static void result_round_trip(void)
{
    projcurve_surface *s = plane_surface();
    projcurve_result *r = line_result();
    if (r == NULL) {
        projcurve_surface_destroy(s);
        return;
    }
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, w, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path_a));
    projcurve_iges_writer_destroy(w);
    char *text = pc_test_read_file(path_a, NULL);
    /* 128, 126 (pcurve), 126 (3D), 142 in the directory. */
    CHECK(text != NULL && strstr(text, "     128       1") != NULL);
    CHECK(text != NULL && strstr(text, "     142") != NULL);
    free(text);
    projcurve_model *m = read_back(path_a);
    if (m) {
        CHECK(projcurve_model_surface_count(m) == 1);
        CHECK(projcurve_model_curve_count(m) == 1); /* the 142's 3D curve */
        CHECK(projcurve_model_skipped_count(m) == 0);
        const projcurve_curve *c = projcurve_model_curve(m, 0);
        if (c) {
            double t0, t1, p[3];
            CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
            CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
            CHECK_NEAR(p[0], 1.0, 1e-14);
            CHECK_NEAR(p[1], 5.0, 1e-14);
            CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
            CHECK_NEAR(p[0], 9.0, 1e-14);
            CHECK_NEAR(p[1], 5.0, 1e-14);
        }
        projcurve_model_destroy(m);
    }
    projcurve_result_destroy(r);
    projcurve_surface_destroy(s);
}

/* [SY13] Example 1 projected along (-1, 0, 0): the written branch, read
 * back through its 142, is the composed branch curve. */
static void projected_round_trip(void)
{
    projcurve_model *in = NULL;
    if (projcurve_model_read_file(ctx, pc_test_data_path("cases/song_yong_example1.igs"), &in) !=
        PROJCURVE_OK)
        return; /* the case files are checked elsewhere */
    const double dir[3] = {-1.0, 0.0, 0.0};
    projcurve_result *r = NULL;
    const projcurve_surface *s = projcurve_model_surface(in, 0);
    CHECK_OK(projcurve_project_directional(ctx, s, projcurve_model_curve(in, 0), dir, NULL, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, w, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path_a));
    projcurve_iges_writer_destroy(w);
    projcurve_model *m = read_back(path_a);
    projcurve_curve *branch = NULL;
    if (r != NULL && projcurve_result_branch_count(r) == 1)
        CHECK_OK(projcurve_result_branch_curve(ctx, r, 0, &branch));
    if (m != NULL && branch != NULL) {
        CHECK(projcurve_model_surface_count(m) == 1);
        CHECK(projcurve_model_curve_count(m) == 1);
        same_surface(s, projcurve_model_surface(m, 0));
        if (projcurve_model_curve_count(m) == 1)
            same_curve(branch, projcurve_model_curve(m, 0));
    }
    projcurve_curve_destroy(branch);
    projcurve_model_destroy(m);
    projcurve_result_destroy(r);
    projcurve_model_destroy(in);
}

/* Reads entity 142 at DE `cos` of an IGES text with the reader's own
 * pieces (the model reader does not keep pcurves) and checks that S
 * composed with the pcurve is the 3D curve at every t, as a curve on
 * surface states; *pcurve_degree gets the pcurve's degree. */
static void check_curve_on_surface(const char *text, size_t cos, int *pcurve_degree)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t work = 0;
    const size_t len = strlen(text);
    pc_iges_file f = {.ctx = ctx, .arena = &arena, .work_done = &work, .work_limit = 64 * len};
    pc_iges_params p;
    long sptr = 0, bptr = 0, cptr = 0;
    CHECK_OK(pc_iges_split(&f, text, len));
    CHECK_OK(pc_iges_read_global(&f));
    CHECK_OK(pc_iges_read_directory(&f));
    CHECK_OK(pc_iges_params_of(&f, cos, &p));
    CHECK_OK(pc_iges_int(&p, 2, &sptr));
    CHECK_OK(pc_iges_int(&p, 3, &bptr));
    CHECK_OK(pc_iges_int(&p, 4, &cptr));
    pc_io_surface raw_s;
    pc_io_curve raw_b, raw_c;
    const char *reason = NULL;
    CHECK_OK(pc_iges_surface(&f, (size_t)sptr, &raw_s));
    CHECK_OK(pc_iges_curve(&f, (size_t)bptr, &raw_b, &reason));
    CHECK_OK(pc_iges_curve(&f, (size_t)cptr, &raw_c, &reason));
    projcurve_surface *s = NULL;
    projcurve_curve *b = NULL, *c = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, raw_s.deg_u, raw_s.deg_v, raw_s.n_u, raw_s.n_v,
                                            raw_s.ctrl, raw_s.weights, raw_s.knots_u,
                                            raw_s.knots_v, &s));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, raw_b.degree, raw_b.n_ctrl, raw_b.ctrl,
                                          raw_b.weights, raw_b.knots, &b));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, raw_c.degree, raw_c.n_ctrl, raw_c.ctrl,
                                          raw_c.weights, raw_c.knots, &c));
    *pcurve_degree = raw_b.degree;
    double t0 = 0, t1 = 0, c0 = 0, c1 = 0, box[6] = {0};
    if (s && b && c) {
        CHECK_OK(projcurve_curve_domain(ctx, b, &t0, &t1));
        CHECK_OK(projcurve_curve_domain(ctx, c, &c0, &c1));
        CHECK_NEAR(t0, c0, 1e-12);
        CHECK_NEAR(t1, c1, 1e-12);
        CHECK_OK(projcurve_surface_bounds(ctx, s, box));
        const double size = fmax(fmax(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
        double worst = 0.0;
        for (int i = 0; i <= 2000; ++i) {
            const double t = t0 + (t1 - t0) * i / 2000.0;
            double uv[3], on_s[3], q[3];
            CHECK_OK(projcurve_curve_eval(ctx, b, t, 0, uv));
            CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, on_s));
            CHECK_OK(projcurve_curve_eval(ctx, c, fmin(fmax(t, c0), c1), 0, q));
            for (int k = 0; k < 3; ++k)
                worst = fmax(worst, fabs(on_s[k] - q[k]));
        }
        if (!(worst <= ROUND_TRIP_REL * size))
            pc_test_fail_at(__FILE__, __LINE__, "S(pcurve(t)) is %g from the 3D curve", worst);
        ++pc_test_checks;
    }
    projcurve_surface_destroy(s);
    projcurve_curve_destroy(b);
    projcurve_curve_destroy(c);
    pc_arena_release(&arena);
}

/* A composed branch's 142 states S(pcurve(t)) = C(t): with straight and
 * with cubic pcurve pieces (PROJCURVE_OPT_PCURVE_DEGREE 3), the written
 * pcurve is the pieces' pcurves joined, not the traced polyline. */
static void curve_on_surface_pcurves(void)
{
    projcurve_model *in = NULL;
    if (projcurve_model_read_file(ctx, pc_test_data_path("cases/bumpy_bicubic_8x8_down.igs"),
                                  &in) != PROJCURVE_OK)
        return; /* the case files are checked elsewhere */
    const double dir[3] = {0.0, 0.0, -1.0};
    for (int degree = 1; degree <= 3; degree += 2) {
        projcurve_options *o = NULL;
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_options_create(ctx, &o));
        CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, degree));
        CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-3));
        CHECK_OK(projcurve_project_directional(ctx, projcurve_model_surface(in, 0),
                                               projcurve_model_curve(in, 0), dir, o, &r));
        CHECK(projcurve_result_branch_count(r) == 1);
        projcurve_iges_writer *w = NULL;
        CHECK_OK(projcurve_iges_writer_create(ctx, &w));
        CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, w, projcurve_model_surface(in, 0), r));
        CHECK_OK(projcurve_iges_writer_write(ctx, w, path_a));
        projcurve_iges_writer_destroy(w);
        char *text = pc_test_read_file(path_a, NULL);
        int pcurve_degree = 0;
        if (text != NULL)
            check_curve_on_surface(text, 7, &pcurve_degree); /* 128, 126, 126, 142 */
        CHECK(pcurve_degree == degree);
        free(text);
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
    }
    projcurve_model_destroy(in);
}

static int call_back(void *user, double t, double out[9])
{
    (void)user;
    memset(out, 0, 9 * sizeof *out);
    out[0] = t;
    out[3] = 1.0;
    return 0;
}

static void misuse(void)
{
    projcurve_iges_writer *w = NULL;
    CHECK_STATUS(projcurve_iges_writer_create(ctx, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_STATUS(projcurve_iges_writer_add_surface(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_iges_writer_add_curve(ctx, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_iges_writer_add_result(ctx, w, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_curve *cb = NULL;
    CHECK_OK(projcurve_curve_create_callback(ctx, call_back, NULL, 0.0, 1.0, &cb));
    CHECK_STATUS(projcurve_iges_writer_add_curve(ctx, w, cb), PROJCURVE_ERR_WRONG_KIND);
    projcurve_curve_destroy(cb);
    CHECK_STATUS(projcurve_iges_writer_write(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_iges_writer_write(ctx, w, "/nonexistent-dir/x.igs"), PROJCURVE_ERR_IO);
    CHECK(strstr(projcurve_context_message(ctx), "/nonexistent-dir/x.igs") != NULL);
    /* An empty writer still makes a valid (empty) file. */
    CHECK_OK(projcurve_iges_writer_write(ctx, w, path_b));
    projcurve_model *m = read_back(path_b);
    CHECK(m != NULL && projcurve_model_surface_count(m) == 0);
    projcurve_model_destroy(m);
    projcurve_iges_writer_destroy(w);
    projcurve_iges_writer_destroy(NULL);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const char *tmp = getenv("TMPDIR");
    snprintf(path_a, sizeof path_a, "%s/projcurve_rt_%ld_a.igs", tmp ? tmp : "/tmp", (long)getpid());
    snprintf(path_b, sizeof path_b, "%s/projcurve_rt_%ld_b.igs", tmp ? tmp : "/tmp", (long)getpid());
    surfaces_and_curves();
    result_round_trip();
    projected_round_trip();
    curve_on_surface_pcurves();
    misuse();
    remove(path_a);
    remove(path_b);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_iges_roundtrip");
}
