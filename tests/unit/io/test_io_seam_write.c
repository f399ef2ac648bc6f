/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Writing branches joined across seams (docs/seams.md, "Writing across
 * seams"): a line projected around a full cylinder (one jump in u) and a
 * torus (jumps in u and v; tests/support/shapes.c, exact rational NURBS),
 * written as IGES (142 per segment; the compact forms and the pieces) and
 * STEP (SURFACE_CURVE per segment)
 * and read back with the library's own reader. Oracles: every pcurve
 * inside the surface's domain at dense t; S composed with each pcurve
 * within the two forms' fit bounds of its 3D curve; one segment per jump
 * plus one per branch, the segments' t ranges meeting at the recorded
 * jumps and their 3D curves meeting there. The unwrapped pcurve written as
 * one curve fails the first check by the part past the seam.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "common/arena.h"
#include "io/iges.h"
#include "io/step.h"
#include "io/step_geom.h"
#include "projcurve.h"
#include "shapes.h"
#include "trace/result.h"

/* A pcurve inside the domain: its ends are put on the edge to the last
 * ulps, its interior lies inside (a pcurve on one side of the seam). */
#define DOMAIN_TOL 1e-12
/* Samples per segment: dense enough to see a pcurve leave the domain. */
#define SAMPLES 400

static projcurve_context *ctx;
static char path[256];

typedef struct segment {
    projcurve_curve *pcurve, *curve;
} segment;

#define MAX_SEGMENTS 16

static projcurve_curve *handle_of(const pc_io_curve *c)
{
    projcurve_curve *h = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, c->degree, c->n_ctrl, c->ctrl, c->weights,
                                          c->knots, &h));
    return h;
}

/* The 142s of the written IGES file, in order. */
static size_t iges_segments(const char *text, segment *seg)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t work = 0, n = 0;
    const size_t len = strlen(text);
    pc_iges_file f = {.ctx = ctx, .arena = &arena, .work_done = &work, .work_limit = 64 * len};
    CHECK_OK(pc_iges_split(&f, text, len));
    CHECK_OK(pc_iges_read_global(&f));
    CHECK_OK(pc_iges_read_directory(&f));
    for (size_t i = 0; i < f.n_entries && n < MAX_SEGMENTS; ++i) {
        if (f.entries[i].type != 142)
            continue;
        pc_iges_params p;
        long bptr = 0, cptr = 0;
        CHECK_OK(pc_iges_params_of(&f, 2 * i + 1, &p));
        CHECK_OK(pc_iges_int(&p, 3, &bptr));
        CHECK_OK(pc_iges_int(&p, 4, &cptr));
        pc_io_curve b, c;
        const char *reason = NULL;
        CHECK_OK(pc_iges_curve(&f, (size_t)bptr, &b, &reason));
        CHECK_OK(pc_iges_curve(&f, (size_t)cptr, &c, &reason));
        seg[n].pcurve = handle_of(&b);
        seg[n].curve = handle_of(&c);
        ++n;
    }
    pc_arena_release(&arena);
    return n;
}

/* The SURFACE_CURVEs of the written STEP file, in order: the 3D curve and
 * the one PCURVE's 2D curve. */
static size_t step_segments(char *text, size_t len, segment *seg)
{
    size_t work = 0, n = 0;
    pc_step_file f = {.ctx = ctx, .text = text, .len = len, .work_done = &work,
                      .work_limit = (size_t)-1, .radians_per_angle_unit = 1.0};
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    CHECK_OK(pc_step_index(&f));
    char name[PC_STEP_MAX_NAME];
    for (size_t i = 0; i < f.n_instances && n < MAX_SEGMENTS; ++i) {
        const pc_step_instance *inst = &f.instances[i];
        pc_step_name(&f, inst, name);
        if (strcmp(name, "SURFACE_CURVE") != 0)
            continue;
        pc_step_node *sc = NULL;
        CHECK_OK(pc_step_parse(&f, inst, &arena, &sc));
        const pc_step_node *list = sc ? pc_step_child(sc, 2) : NULL;
        CHECK(list != NULL && list->n_children == 1);
        if (list == NULL || list->n_children != 1)
            continue;
        pc_step_located c3, pc, rep, c2;
        const char *skip = NULL;
        pc_io_curve q, c;
        CHECK_OK(pc_step_resolve(&f, &arena, inst, pc_step_child(sc, 1), &c3));
        CHECK_OK(pc_step_curve(&f, &arena, &c3, &c, NULL, &skip));
        CHECK_OK(pc_step_resolve(&f, &arena, inst, list->first, &pc));
        CHECK_OK(pc_step_resolve(&f, &arena, pc.inst, pc_step_child(pc.node, 2), &rep));
        CHECK_OK(pc_step_resolve(&f, &arena, rep.inst, pc_step_child(rep.node, 1)->first, &c2));
        CHECK_OK(pc_step_curve(&f, &arena, &c2, &q, NULL, &skip));
        seg[n].pcurve = handle_of(&q);
        seg[n].curve = handle_of(&c);
        ++n;
    }
    pc_step_index_free(&f);
    pc_arena_release(&arena);
    return n;
}

/* q(t) into uv and S there into x (at the nearest point of the domain
 * when q leaves it, which the caller reports). */
static void eval_on_surface(const projcurve_surface *s, const double dom[4],
                            const projcurve_curve *q, double t, double uv[3], double x[3])
{
    CHECK_OK(projcurve_curve_eval(ctx, q, t, 0, uv));
    CHECK_OK(projcurve_surface_eval(ctx, s, fmin(fmax(uv[0], dom[0]), dom[1]),
                                    fmin(fmax(uv[1], dom[2]), dom[3]), 0, x));
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* One segment: in the domain, S o q near the 3D curve over the same t. */
static void check_segment(const char *what, const projcurve_surface *s, const double dom[4],
                          const segment *g, double gap)
{
    double t0, t1, c0, c1;
    CHECK_OK(projcurve_curve_domain(ctx, g->pcurve, &t0, &t1));
    CHECK_OK(projcurve_curve_domain(ctx, g->curve, &c0, &c1));
    /* the same t range; the pieces' pcurves joined end where the last
     * piece's range rounds to (1.1e-12 past 1 here) */
    CHECK_NEAR(t0, c0, 1e-9);
    CHECK_NEAR(t1, c1, 1e-9);
    double outside = 0.0, worst = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        const double t = t0 + (t1 - t0) * i / SAMPLES;
        double uv[3], on_s[3], x[3];
        eval_on_surface(s, dom, g->pcurve, t, uv, on_s);
        CHECK_OK(projcurve_curve_eval(ctx, g->curve, fmin(fmax(t, c0), c1), 0, x));
        outside = fmax(outside, fmax(fmax(dom[0] - uv[0], uv[0] - dom[1]),
                                     fmax(dom[2] - uv[1], uv[1] - dom[3])));
        worst = fmax(worst, dist3(on_s, x));
    }
    if (!(outside <= DOMAIN_TOL))
        pc_test_fail_at(__FILE__, __LINE__, "%s: a pcurve leaves the domain by %g", what,
                        outside);
    if (!(worst <= gap))
        pc_test_fail_at(__FILE__, __LINE__, "%s: S(pcurve(t)) is %g from the 3D curve (%g)",
                        what, worst, gap);
    pc_test_checks += 2;
}

/* The segments of r's branches, in order: per branch one more than its
 * jumps, meeting at the jumps' t in 3D. */
static void check_segments(const char *what, const projcurve_surface *s,
                           const projcurve_result *r, segment *seg, size_t n)
{
    double dom[4], box[6];
    CHECK_OK(projcurve_surface_domain(ctx, s, dom));
    CHECK_OK(projcurve_surface_bounds(ctx, s, box));
    const double size = fmax(fmax(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
    size_t k = 0;
    for (size_t b = 0; b < r->n_branches; ++b) {
        const pc_branch *br = &r->branches[b];
        /* each compact form is within eps_D of the exact projection (fit/
         * accepts a fit within 0.8 eps_D at its check samples, docs/fit.md;
         * the recorded errors are those samples' maxima, which dense
         * samples exceed by a few percent), so S o q and the 3D curve are
         * within 2 eps_D; splitting adds only rounding */
        const double gap = 2.0 * r->stats.tol_distance + 1e-12 * size;
        CHECK(br->compact_pcurve_error + br->compact_curve_error <= gap);
        for (size_t j = 0; j <= br->n_seams; ++j, ++k) {
            if (k >= n) {
                pc_test_fail_at(__FILE__, __LINE__, "%s: %zu segments, more expected", what,
                                n);
                return;
            }
            check_segment(what, s, dom, &seg[k], gap);
            if (j == br->n_seams)
                continue;
            double t0, t1, u0, u1, a[3], c[3];
            CHECK_OK(projcurve_curve_domain(ctx, seg[k].curve, &t0, &t1));
            CHECK_OK(projcurve_curve_domain(ctx, seg[k + 1 < n ? k + 1 : k].curve, &u0, &u1));
            /* the segments meet at the jump, one pole shared: to rounding */
            CHECK_NEAR(t1, br->seams[j].t, 1e-12);
            CHECK_NEAR(u0, br->seams[j].t, 1e-12);
            if (k + 1 < n) {
                CHECK_OK(projcurve_curve_eval(ctx, seg[k].curve, t1, 0, a));
                CHECK_OK(projcurve_curve_eval(ctx, seg[k + 1].curve, u0, 0, c));
                CHECK(dist3(a, c) <= 1e-12 * size);
            }
        }
    }
    CHECK(k == n);
}

static void free_segments(segment *seg, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        projcurve_curve_destroy(seg[i].pcurve);
        projcurve_curve_destroy(seg[i].curve);
    }
}

static size_t jumps_of(const projcurve_result *r)
{
    size_t total = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_seam_count(ctx, r, b, &n));
        total += n;
    }
    return total;
}

static void write_and_check(const char *what, const projcurve_surface *s,
                            const projcurve_result *r, size_t expected_jumps)
{
    const size_t n_branches = projcurve_result_branch_count(r);
    CHECK(jumps_of(r) == expected_jumps);
    segment seg[MAX_SEGMENTS];
    char label[128];

    projcurve_iges_writer *iw = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &iw));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, iw, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, iw, path));
    projcurve_iges_writer_destroy(iw);
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    CHECK(m && projcurve_model_curve_count(m) == n_branches + expected_jumps);
    char *text = pc_test_read_file(path, NULL);
    size_t n = text ? iges_segments(text, seg) : 0;
    CHECK(n == n_branches + expected_jumps);
    snprintf(label, sizeof label, "%s, IGES", what);
    if (m && projcurve_model_surface_count(m) == 1)
        check_segments(label, projcurve_model_surface(m, 0), r, seg, n);
    free_segments(seg, n);
    free(text);
    projcurve_model_destroy(m);

    /* the pieces (their pcurves and 3D curves joined), split the same way */
    CHECK_OK(projcurve_iges_writer_create(ctx, &iw));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, iw, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, iw, path));
    projcurve_iges_writer_destroy(iw);
    m = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    text = pc_test_read_file(path, NULL);
    n = text ? iges_segments(text, seg) : 0;
    CHECK(n == n_branches + expected_jumps);
    snprintf(label, sizeof label, "%s, IGES pieces", what);
    if (m && projcurve_model_surface_count(m) == 1)
        check_segments(label, projcurve_model_surface(m, 0), r, seg, n);
    free_segments(seg, n);
    free(text);
    projcurve_model_destroy(m);

    projcurve_step_writer *sw = NULL;
    CHECK_OK(projcurve_step_writer_create(ctx, &sw));
    CHECK_OK(projcurve_step_writer_add_result(ctx, sw, s, r));
    CHECK_OK(projcurve_step_writer_write(ctx, sw, path));
    projcurve_step_writer_destroy(sw);
    m = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    CHECK(m && projcurve_model_curve_count(m) == n_branches + expected_jumps);
    size_t len = 0;
    text = pc_test_read_file(path, &len);
    n = text ? step_segments(text, len, seg) : 0;
    CHECK(n == n_branches + expected_jumps);
    snprintf(label, sizeof label, "%s, STEP", what);
    if (m && projcurve_model_surface_count(m) == 1)
        check_segments(label, projcurve_model_surface(m, 0), r, seg, n);
    free_segments(seg, n);
    free(text);
    projcurve_model_destroy(m);
}

/* Not composed (PROJCURVE_OPT_COMPOSE 0): the traced points, one polyline
 * and one 142 (CPTR 0) per run between jumps; no edge of a polyline jumps
 * across the domain (the seam's two sides are a period apart, an edge of
 * the trace a small step). */
static void traced_runs(const projcurve_surface *s, const projcurve_curve *c, size_t jumps)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_COMPOSE, 0));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(ctx, s, c, o, &r));
    projcurve_options_destroy(o);
    if (r == NULL)
        return;
    CHECK(jumps_of(r) == jumps);
    projcurve_iges_writer *iw = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &iw));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, iw, s, r));
    CHECK_OK(projcurve_iges_writer_write(ctx, iw, path));
    projcurve_iges_writer_destroy(iw);
    char *text = pc_test_read_file(path, NULL);
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t work = 0, n_cos = 0;
    const size_t len = text ? strlen(text) : 0;
    pc_iges_file f = {.ctx = ctx, .arena = &arena, .work_done = &work, .work_limit = 64 * len};
    double dom[4];
    CHECK_OK(projcurve_surface_domain(ctx, s, dom));
    double widest = 0.0, outside = 0.0;
    if (text && pc_iges_split(&f, text, len) == PROJCURVE_OK &&
        pc_iges_read_global(&f) == PROJCURVE_OK && pc_iges_read_directory(&f) == PROJCURVE_OK)
        for (size_t i = 0; i < f.n_entries; ++i) {
            if (f.entries[i].type != 142)
                continue;
            ++n_cos;
            pc_iges_params p;
            long bptr = 0, cptr = -1;
            pc_io_curve q;
            const char *reason = NULL;
            CHECK_OK(pc_iges_params_of(&f, 2 * i + 1, &p));
            CHECK_OK(pc_iges_int(&p, 3, &bptr));
            CHECK_OK(pc_iges_int(&p, 4, &cptr));
            CHECK(cptr == 0);
            CHECK_OK(pc_iges_curve(&f, (size_t)bptr, &q, &reason));
            for (size_t k = 0; k < q.n_ctrl; ++k) {
                const double u = q.ctrl[3 * k], v = q.ctrl[3 * k + 1];
                outside = fmax(outside, fmax(fmax(dom[0] - u, u - dom[1]),
                                             fmax(dom[2] - v, v - dom[3])));
                if (k > 0)
                    widest = fmax(widest, fabs(u - q.ctrl[3 * (k - 1)]) / (dom[1] - dom[0]));
            }
        }
    CHECK(n_cos == r->n_branches + jumps);
    CHECK(outside <= 0.0);
    /* a traced step is far below half the domain's width */
    CHECK(widest < 0.5);
    pc_arena_release(&arena);
    free(text);
    projcurve_result_destroy(r);
}

static projcurve_curve *line(const double p0[3], const double p1[3])
{
    const double ctrl[6] = {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]};
    const double knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

/* u = 0 and u = 1 of these shapes lie on the half-plane y = 0, x > 0; the
 * torus's v = 0 and v = 1 on its outer equator (z = 0). */
static void run(const char *what, pc_shape_surface shape, const double p0[3],
                const double p1[3], const double *dir, size_t expected_jumps)
{
    projcurve_surface *s = pc_shape_surface_create(&shape);
    pc_shape_surface_free(&shape);
    projcurve_curve *c = line(p0, p1);
    projcurve_result *r = NULL;
    if (s && c)
        CHECK_OK(dir ? projcurve_project_directional(ctx, s, c, dir, NULL, &r)
                     : projcurve_project_orthogonal(ctx, s, c, NULL, &r));
    if (r)
        write_and_check(what, s, r, expected_jumps);
    if (r && dir == NULL && s && c)
        traced_runs(s, c, expected_jumps);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const char *tmp = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/projcurve_seam_write_%ld", tmp ? tmp : "/tmp",
             (long)getpid());
    const double minus_x[3] = {-1, 0, 0};
    /* the front hit crosses the seam at t = 1/2, the back one does not */
    run("cylinder, directional", pc_shape_cylinder(1.0, 2.0), (const double[3]){3, -0.8, 0.5},
        (const double[3]){3, 0.8, 1.5}, minus_x, 1);
    run("cylinder, orthogonal", pc_shape_cylinder(1.0, 2.0), (const double[3]){2, -1, 0.5},
        (const double[3]){2, 1, 1.5}, NULL, 1);
    /* the nearest foot crosses the u seam at t = 1/2 and the v seam at
     * t = 0.6: one branch, three segments */
    run("torus, orthogonal", pc_shape_torus(2.0, 0.5), (const double[3]){3, -1, -0.6},
        (const double[3]){3, 1, 0.4}, NULL, 2);
    remove(path);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_seam_write");
}
