/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The whole-shape writers (projcurve_iges_writer_add_shape_result,
 * projcurve_step_writer_add_shape_result) on the 2x2 shell of
 * tests/data/cases-brep (four bicubic faces of one sheet, sewn): the U
 * curve of shell_2x2_bspline_oblique (one open connected curve of four face
 * pieces) and a circle around the shell's centre (one closed connected
 * curve of five), both along Dir (0.2, -0.1, -1). Written and read back
 * with the library's readers:
 *   - IGES: one 102 per connected curve, as many members as pieces, each
 *     member (read by the reader's own curve entity code) the piece's 3D
 *     curve at 41 samples to 1e-12 of the model size; the public reader
 *     gives one curve per 102 (its members joined) from the first piece's
 *     start to the last piece's end;
 *   - STEP: one COMPOSITE_CURVE per connected curve, as many segments as
 *     pieces over the B-splines in chain order (the public reader gives
 *     those B-splines as its curves, each equal to its piece at 41 samples
 *     to 1e-12), the transitions from the pieces' ends and the chaining
 *     tolerance, measured here, the open curve's last one discontinuous;
 *   - a connected curve run against its pieces' parameter (the U's chain
 *     turned round: its pieces in the other order, each entered at its t1
 *     end): every IGES member is its piece run backwards, every STEP
 *     segment says .F. over the piece's own B-spline. projcurve_project_shape
 *     gives no such result (the tracer runs every branch with t increasing,
 *     a branch born in mid-curve traced back and turned, and the chain
 *     enters every piece at its start), so the test turns the result round
 *     itself, in its internal form;
 *   - a result without connected curves adds nothing; NULL arguments.
 * The oracle of each piece is its 3D curve from the public result API
 * (the compact curve, else the pieces joined), evaluated by the library's
 * curve evaluator on the handle the test made, not on the file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "io/iges.h"
#include "io/step.h"
#include "projcurve.h"
#include "shapeproj/shape_result.h"

#define N_SAMPLES 41     /* per member: more than the 20 the checks ask for */
#define REL_TOL 1e-12    /* of the model size: the files hold 17 digits */
#define MODEL_SIZE 30.0  /* the shell spans 20 x 20 x 2.5; its diagonal ~28 */
#define MAX_MEMBERS 16

static char path_igs[256], path_step[256];

/* The test's own view of one connected curve: the pieces' 3D curves, the
 * sense the chain runs along them, whether it is closed. */
typedef struct expected_curve {
    size_t n;
    projcurve_curve *piece[MAX_MEMBERS];
    int forward[MAX_MEMBERS];
    int closed;
    double chain_tol;
} expected_curve;

static projcurve_curve *piece_curve(const projcurve_result *r, size_t branch)
{
    projcurve_curve *c = NULL;
    if (projcurve_result_branch_compact_curve(NULL, r, branch, &c) == PROJCURVE_OK)
        return c;
    CHECK_OK(projcurve_result_branch_curve(NULL, r, branch, &c));
    return c;
}

static size_t expect_all(const projcurve_shape_result *sr, expected_curve *out, size_t room)
{
    const size_t n = projcurve_shape_result_curve_count(sr);
    for (size_t c = 0; c < n && c < room; ++c) {
        expected_curve *e = &out[c];
        memset(e, 0, sizeof *e);
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, c, &e->n, NULL, &e->closed));
        CHECK(e->n <= MAX_MEMBERS);
        e->chain_tol = projcurve_shape_result_chain_tolerance(sr);
        for (size_t k = 0; k < e->n && k < MAX_MEMBERS; ++k) {
            const projcurve_result *fr = NULL;
            size_t b = 0;
            double t[2];
            CHECK_OK(projcurve_shape_result_piece(NULL, sr, c, k, NULL, &fr, &b, t, NULL, NULL));
            e->piece[k] = piece_curve(fr, b);
            e->forward[k] = !(t[0] > t[1]);
        }
    }
    return n < room ? n : room;
}

static void free_expected(expected_curve *e, size_t n)
{
    for (size_t c = 0; c < n; ++c)
        for (size_t k = 0; k < e[c].n && k < MAX_MEMBERS; ++k)
            projcurve_curve_destroy(e[c].piece[k]);
}

static double dist3(const double *a, const double *b)
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* got runs as want (reversed: got(s) = want(t0 + t1 - s)) over the same
 * domain, to REL_TOL of the model at N_SAMPLES parameters. */
static void check_same_curve(const projcurve_curve *got, const projcurve_curve *want,
                             int reversed, const char *what, size_t curve, size_t member)
{
    double a0, a1, b0, b1;
    CHECK_OK(projcurve_curve_domain(NULL, got, &a0, &a1));
    CHECK_OK(projcurve_curve_domain(NULL, want, &b0, &b1));
    CHECK_NEAR(a0, b0, REL_TOL * fabs(b1 - b0));
    CHECK_NEAR(a1, b1, REL_TOL * fabs(b1 - b0));
    double worst = 0.0;
    for (int i = 0; i < N_SAMPLES; ++i) {
        const double s = b0 + (b1 - b0) * i / (N_SAMPLES - 1.0);
        double p[3], q[3];
        CHECK_OK(projcurve_curve_eval(NULL, got, fmin(fmax(s, a0), a1), 0, p));
        /* b0 + b1 - s may round past an end of the domain */
        const double r = fmin(fmax(b0 + b1 - s, fmin(b0, b1)), fmax(b0, b1));
        CHECK_OK(projcurve_curve_eval(NULL, want, reversed ? r : s, 0, q));
        worst = fmax(worst, dist3(p, q));
    }
    if (worst > REL_TOL * MODEL_SIZE)
        pc_test_fail_at(__FILE__, __LINE__, "%s: curve %zu member %zu differs by %.3g", what,
                        curve, member, worst);
    ++pc_test_checks;
}

static projcurve_curve *handle_of_io(const pc_io_curve *c)
{
    projcurve_curve *h = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, c->degree, c->n_ctrl, c->ctrl, c->weights,
                                          c->knots, &h));
    return h;
}

/* The 102s of the file in directory order, each member read by the IGES
 * reader's curve code (pc_iges_curve) and compared with its piece. */
static void check_iges_members(const char *text, size_t len, const expected_curve *e, size_t n)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t work = 0;
    pc_iges_file f;
    memset(&f, 0, sizeof f);
    f.arena = &arena;
    f.work_done = &work;
    f.work_limit = 64 * len + (1u << 20);
    CHECK_OK(pc_iges_split(&f, text, len));
    CHECK_OK(pc_iges_read_global(&f));
    CHECK_OK(pc_iges_read_directory(&f));
    size_t composites = 0;
    for (size_t i = 0; i < f.n_entries; ++i) {
        if (f.entries[i].type != 102)
            continue;
        const size_t c = composites++;
        pc_iges_params p;
        long members = 0;
        CHECK_OK(pc_iges_params_of(&f, 2 * i + 1, &p));
        CHECK_OK(pc_iges_int(&p, 1, &members));
        if (c >= n || (size_t)members != e[c].n) {
            pc_test_fail_at(__FILE__, __LINE__, "102 number %zu has %ld members, expected %zu",
                            c, members, c < n ? e[c].n : 0);
            continue;
        }
        ++pc_test_checks;
        for (size_t k = 0; k < e[c].n; ++k) {
            long de = 0;
            CHECK_OK(pc_iges_int(&p, 2 + k, &de));
            pc_io_curve m;
            const char *skip = NULL;
            CHECK_OK(pc_iges_curve(&f, (size_t)de, &m, &skip));
            CHECK(skip == NULL);
            if (skip != NULL)
                continue;
            projcurve_curve *h = handle_of_io(&m);
            check_same_curve(h, e[c].piece[k], !e[c].forward[k], "IGES member", c, k);
            projcurve_curve_destroy(h);
        }
    }
    CHECK(composites == n);
    pc_arena_release(&arena);
}

/* The public reader: one curve per 102 (the members joined), from the
 * first member's start to the last member's end. */
static void check_iges_model(const expected_curve *e, size_t n)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, path_igs, &m));
    CHECK(projcurve_model_curve_count(m) == n);
    for (size_t c = 0; c < n && c < projcurve_model_curve_count(m); ++c) {
        const projcurve_curve *got = projcurve_model_curve(m, c);
        const projcurve_curve *first = e[c].piece[0], *last = e[c].piece[e[c].n - 1];
        double g0, g1, f0, f1, l0, l1, p[3], q[3];
        CHECK_OK(projcurve_curve_domain(NULL, got, &g0, &g1));
        CHECK_OK(projcurve_curve_domain(NULL, first, &f0, &f1));
        CHECK_OK(projcurve_curve_domain(NULL, last, &l0, &l1));
        CHECK_OK(projcurve_curve_eval(NULL, got, g0, 0, p));
        CHECK_OK(projcurve_curve_eval(NULL, first, e[c].forward[0] ? f0 : f1, 0, q));
        CHECK_NEAR(dist3(p, q), 0.0, REL_TOL * MODEL_SIZE);
        CHECK_OK(projcurve_curve_eval(NULL, got, g1, 0, p));
        CHECK_OK(projcurve_curve_eval(NULL, last, e[c].forward[e[c].n - 1] ? l1 : l0, 0, q));
        CHECK_NEAR(dist3(p, q), 0.0, REL_TOL * MODEL_SIZE);
    }
    projcurve_model_destroy(m);
}

static void check_iges(const expected_curve *e, size_t n)
{
    size_t len = 0;
    char *text = pc_test_read_file(path_igs, &len);
    CHECK(text != NULL);
    if (text == NULL)
        return;
    check_iges_members(text, len, e, n);
    free(text);
    check_iges_model(e, n);
}

/* The end of piece k where the chain leaves it (at_end) or enters it. */
static void chain_end(const expected_curve *e, size_t k, int at_end, double x[3])
{
    double t0, t1;
    CHECK_OK(projcurve_curve_domain(NULL, e->piece[k], &t0, &t1));
    const int upper = at_end == e->forward[k];
    CHECK_OK(projcurve_curve_eval(NULL, e->piece[k], upper ? t1 : t0, 0, x));
}

/* The transition segment k should have: continuous where its end and the
 * next piece's start are within the chaining tolerance (the last of an
 * open curve never). */
static int expect_continuous(const expected_curve *e, size_t k)
{
    if (k + 1 == e->n && !e->closed)
        return 0;
    double a[3], b[3];
    chain_end(e, k, 1, a);
    chain_end(e, (k + 1) % e->n, 0, b);
    return dist3(a, b) <= e->chain_tol;
}

static int enum_is(const pc_step_node *n, const char *text)
{
    return n != NULL && n->kind == PC_STEP_ENUM && n->len == strlen(text) &&
           strncmp(n->text, text, n->len) == 0;
}

/* One COMPOSITE_CURVE: its segments' count, transitions, senses, and
 * their parent curves in increasing instance order (the order the public
 * reader gives the B-splines in, checked against the pieces there). */
static void check_step_composite(const pc_step_file *f, pc_arena *arena, const pc_step_node *cc,
                                 const expected_curve *e, size_t c, long *last_parent)
{
    const pc_step_node *segs = pc_step_child(cc, 1);
    CHECK(segs != NULL && segs->kind == PC_STEP_LIST);
    if (segs == NULL || segs->n_children != e->n) {
        pc_test_fail_at(__FILE__, __LINE__, "COMPOSITE_CURVE %zu has %zu segments, expected %zu",
                        c, segs ? segs->n_children : 0, e->n);
        return;
    }
    ++pc_test_checks;
    size_t k = 0;
    for (const pc_step_node *s = segs->first; s != NULL; s = s->next, ++k) {
        pc_step_node *seg = NULL;
        const pc_step_instance *inst = pc_step_find(f, s->ref);
        CHECK(inst != NULL);
        if (inst == NULL)
            continue;
        CHECK_OK(pc_step_parse(f, inst, arena, &seg));
        CHECK(pc_step_is(seg, "COMPOSITE_CURVE_SEGMENT"));
        const int continuous = expect_continuous(e, k);
        CHECK(enum_is(pc_step_child(seg, 0), continuous ? "CONTINUOUS" : "DISCONTINUOUS"));
        CHECK(enum_is(pc_step_child(seg, 1), e->forward[k] ? "T" : "F"));
        const pc_step_node *parent = pc_step_child(seg, 2);
        CHECK(parent != NULL && parent->kind == PC_STEP_REF && parent->ref > *last_parent);
        if (parent != NULL)
            *last_parent = parent->ref;
    }
}

/* The composites of the STEP file, in instance order. */
static void check_step_composites(const char *text, size_t len, const expected_curve *e,
                                  size_t n)
{
    size_t work = 0;
    pc_step_file f = {.text = text, .len = len, .work_done = &work,
                      .work_limit = 64 * len + (1u << 20), .radians_per_angle_unit = 1.0};
    CHECK_OK(pc_step_index(&f));
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t composites = 0;
    long last_parent = 0;
    for (size_t i = 0; i < f.n_instances; ++i) {
        pc_step_node *node = NULL;
        if (pc_step_parse(&f, &f.instances[i], &arena, &node) != PROJCURVE_OK ||
            !pc_step_is(node, "COMPOSITE_CURVE"))
            continue;
        if (composites < n)
            check_step_composite(&f, &arena, node, &e[composites], composites,
                                 &last_parent);
        ++composites;
    }
    CHECK(composites == n);
    pc_arena_release(&arena);
    pc_step_index_free(&f);
}

/* The public reader: the B-splines in chain order, each its piece; one
 * COMPOSITE_CURVE listed as skipped per connected curve. */
static void check_step_model(const expected_curve *e, size_t n)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, path_step, &m));
    size_t total = 0, composites = 0;
    for (size_t c = 0; c < n; ++c)
        total += e[c].n;
    CHECK(projcurve_model_curve_count(m) == total);
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i)
        composites += strstr(projcurve_model_skipped(m, i), "COMPOSITE_CURVE") != NULL &&
                      strstr(projcurve_model_skipped(m, i), "_SEGMENT") == NULL;
    CHECK(composites == n);
    size_t index = 0;
    for (size_t c = 0; c < n; ++c)
        for (size_t k = 0; k < e[c].n && index < projcurve_model_curve_count(m); ++k, ++index)
            check_same_curve(projcurve_model_curve(m, index), e[c].piece[k], 0, "STEP member",
                             c, k);
    projcurve_model_destroy(m);
}

static void check_step(const expected_curve *e, size_t n)
{
    size_t len = 0;
    char *text = pc_test_read_file(path_step, &len);
    CHECK(text != NULL);
    if (text == NULL)
        return;
    check_step_composites(text, len, e, n);
    free(text);
    check_step_model(e, n);
}

static projcurve_curve *circle(void)
{
    const double cx = 10.5, cy = 9.3, r = 5.0, z = 10.0, h = sqrt(0.5);
    const double d[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                            {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    double ctrl[27], w[9];
    for (int i = 0; i < 9; ++i) {
        ctrl[3 * i] = cx + r * d[i][0];
        ctrl[3 * i + 1] = cy + r * d[i][1];
        ctrl[3 * i + 2] = z;
        w[i] = i % 2 ? h : 1.0;
    }
    static const double knots[] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 9, ctrl, w, knots, &c));
    return c;
}

/* Connected curve c of sr run the other way: its pieces in reverse order,
 * each piece's trim ends swapped, so that the chain enters every piece at
 * its t1 end and leaves it at its t0 end (the pieces still meet). */
static void turn_round(projcurve_shape_result *sr, size_t c)
{
    const pc_connected *cc = &sr->curves[c];
    pc_piece_ref *refs = sr->refs + cc->first;
    for (size_t i = 0, k = cc->count - 1; i < k; ++i, --k) {
        const pc_piece_ref x = refs[i];
        refs[i] = refs[k];
        refs[k] = x;
    }
    for (size_t i = 0; i < cc->count; ++i) {
        pc_branch_trim *tr = &sr->parts[refs[i].part].trims[refs[i].branch];
        const pc_trim_end x = tr->start;
        tr->start = tr->end;
        tr->end = x;
    }
}

/* The U turned round, written alone: every member reversed. */
static void check_turned_round(projcurve_shape_result *u)
{
    turn_round(u, 0);
    expected_curve e[1];
    const size_t n = expect_all(u, e, 1);
    CHECK(n == 1 && e[0].n == 4 && !e[0].closed);
    for (size_t k = 0; k < e[0].n; ++k)
        CHECK(!e[0].forward[k]);
    projcurve_iges_writer *iw = NULL;
    projcurve_step_writer *sw = NULL;
    CHECK_OK(projcurve_iges_writer_create(NULL, &iw));
    CHECK_OK(projcurve_step_writer_create(NULL, &sw));
    CHECK_OK(projcurve_iges_writer_add_shape_result(NULL, iw, u));
    CHECK_OK(projcurve_step_writer_add_shape_result(NULL, sw, u));
    CHECK_OK(projcurve_iges_writer_write(NULL, iw, path_igs));
    CHECK_OK(projcurve_step_writer_write(NULL, sw, path_step));
    projcurve_iges_writer_destroy(iw);
    projcurve_step_writer_destroy(sw);
    check_iges(e, n);
    check_step(e, n);
    free_expected(e, n);
    turn_round(u, 0); /* as projected again */
}

/* A result without connected curves (the curve far beside the shell)
 * adds nothing; NULL arguments are refused with a message. */
static void check_empty_and_null(const projcurve_shape *shape, const double dir[3])
{
    const double ctrl[] = {100, 100, 10, 110, 100, 10};
    static const double knots[] = {0, 0, 1, 1};
    projcurve_curve *far = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &far));
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, far, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 0);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_iges_writer *iw = NULL;
    projcurve_step_writer *sw = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &iw));
    CHECK_OK(projcurve_step_writer_create(ctx, &sw));
    CHECK_OK(projcurve_iges_writer_add_shape_result(ctx, iw, sr));
    CHECK_OK(projcurve_step_writer_add_shape_result(ctx, sw, sr));
    CHECK_OK(projcurve_iges_writer_write(ctx, iw, path_igs));
    CHECK_OK(projcurve_step_writer_write(ctx, sw, path_step));
    for (int k = 0; k < 2; ++k) {
        projcurve_model *m = NULL;
        CHECK_OK(projcurve_model_read_file(ctx, k ? path_step : path_igs, &m));
        CHECK(projcurve_model_curve_count(m) == 0 && projcurve_model_skipped_count(m) == 0);
        projcurve_model_destroy(m);
    }
    CHECK_STATUS(projcurve_iges_writer_add_shape_result(ctx, NULL, sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "writer") != NULL);
    CHECK_STATUS(projcurve_iges_writer_add_shape_result(ctx, iw, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "shape result") != NULL);
    CHECK_STATUS(projcurve_step_writer_add_shape_result(ctx, NULL, sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_add_shape_result(ctx, sw, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "shape result") != NULL);
    projcurve_iges_writer_destroy(iw);
    projcurve_step_writer_destroy(sw);
    projcurve_context_destroy(ctx);
    projcurve_shape_result_destroy(sr);
    projcurve_curve_destroy(far);
}

int main(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(path_igs, sizeof path_igs, "%s/projcurve_shw_%ld.igs", tmp ? tmp : "/tmp",
             (long)getpid());
    snprintf(path_step, sizeof path_step, "%s/projcurve_shw_%ld.step", tmp ? tmp : "/tmp",
             (long)getpid());
    projcurve_model *shell = NULL, *curves = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path("cases-brep/shell_2x2.step"),
                                       &shell));
    CHECK_OK(projcurve_model_read_file(
        NULL, pc_test_data_path("cases-brep/shell_2x2_bspline_oblique.curves.igs"), &curves));
    if (shell == NULL || curves == NULL || projcurve_model_shape_count(shell) != 1 ||
        projcurve_model_curve_count(curves) != 1)
        return pc_test_finish("test_api_shape_writers");
    const projcurve_shape *shape = projcurve_model_shape(shell, 0);
    const double dir[3] = {0.2, -0.1, -1.0};
    projcurve_curve *ring = circle();
    projcurve_shape_result *u = NULL, *loop = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, projcurve_model_curve(curves, 0),
                                     PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL, &u));
    CHECK_OK(projcurve_project_shape(NULL, shape, ring, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &loop));
    expected_curve e[4];
    size_t n = expect_all(u, e, 4);
    n += expect_all(loop, e + n, 4 - n);
    /* the cases' MANIFEST: the U is 4 face pieces; the circle 5, closed */
    CHECK(n == 2 && e[0].n == 4 && !e[0].closed && e[1].n == 5 && e[1].closed);

    projcurve_iges_writer *iw = NULL;
    projcurve_step_writer *sw = NULL;
    CHECK_OK(projcurve_iges_writer_create(NULL, &iw));
    CHECK_OK(projcurve_step_writer_create(NULL, &sw));
    CHECK_OK(projcurve_iges_writer_add_shape_result(NULL, iw, u));
    CHECK_OK(projcurve_iges_writer_add_shape_result(NULL, iw, loop));
    CHECK_OK(projcurve_step_writer_add_shape_result(NULL, sw, u));
    CHECK_OK(projcurve_step_writer_add_shape_result(NULL, sw, loop));
    CHECK_OK(projcurve_iges_writer_write(NULL, iw, path_igs));
    CHECK_OK(projcurve_step_writer_write(NULL, sw, path_step));
    projcurve_iges_writer_destroy(iw);
    projcurve_step_writer_destroy(sw);
    check_iges(e, n);
    check_step(e, n);
    check_turned_round(u);
    check_empty_and_null(shape, dir);

    free_expected(e, n);
    projcurve_shape_result_destroy(u);
    projcurve_shape_result_destroy(loop);
    projcurve_curve_destroy(ring);
    projcurve_model_destroy(shell);
    projcurve_model_destroy(curves);
    remove(path_igs);
    remove(path_step);
    return pc_test_finish("test_api_shape_writers");
}
