/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP writer round trips through the library's own STEP reader.
 *
 * Surfaces and curves written and read back have the same knots and
 * weights bit for bit, and the same Cartesian control points to 1 ulp:
 * the writer divides the stored homogeneous point by its weight once, the
 * reader's handle multiplies by it again and the comparison divides once
 * more, each rounding to nearest (exact where the weights are 1, which is
 * checked bit for bit). A projection result comes back as one 3D curve per
 * branch equal bit for bit to its compact curve (both handles are made from
 * the same Cartesian poles and weights), and each SURFACE_CURVE's PCURVE,
 * followed through its DEFINITIONAL_REPRESENTATION, is the compact pcurve
 * bit for bit, on the surface the file names. Units and uncertainty come
 * back as set; every real in the file has a decimal point and reads back
 * as the double written; bad input gives its status and leaves the writer
 * as it was.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "shapes.h"
#include "common/arena.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "io/step.h"
#include "io/step_geom.h"
#include "io/step_write.h"
#include "io/text_buf.h"
#include "projcurve.h"
#include "trace/result.h"

static projcurve_context *ctx;
static char path_a[256], path_b[256];

/* a and b are within n ulps of each other (bit for bit when n is 0). */
static int within_ulps(double a, double b, int n)
{
    double x = a;
    for (int i = 0; i < n && x < b; ++i)
        x = nextafter(x, b);
    for (int i = 0; i < n && x > b; ++i)
        x = nextafter(x, b);
    return memcmp(&x, &b, sizeof x) == 0;
}

static void same_doubles(const double *a, const double *b, size_t n, int ulps, const char *what)
{
    for (size_t i = 0; i < n; ++i)
        if (!within_ulps(a[i], b[i], ulps)) {
            pc_test_fail_at(__FILE__, __LINE__, "%s[%zu]: %.17g vs %.17g (%d ulp allowed)", what,
                            i, a[i], b[i], ulps);
            return;
        }
    ++pc_test_checks;
}

static projcurve_model *read_back(const char *path)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    return m;
}

static void same_surface(const projcurve_surface *a, const projcurve_surface *b)
{
    int da[2], db[2], ra, rb;
    size_t na[2], nb[2];
    CHECK_OK(projcurve_surface_info(ctx, a, &da[0], &da[1], &na[0], &na[1], NULL, NULL, &ra));
    CHECK_OK(projcurve_surface_info(ctx, b, &db[0], &db[1], &nb[0], &nb[1], NULL, NULL, &rb));
    CHECK(da[0] == db[0] && da[1] == db[1] && na[0] == nb[0] && na[1] == nb[1] && ra == rb);
    if (!(da[0] == db[0] && da[1] == db[1] && na[0] == nb[0] && na[1] == nb[1]))
        return;
    const size_t n = na[0] * na[1], ku = na[0] + (size_t)da[0] + 1, kv = na[1] + (size_t)da[1] + 1;
    double *x = malloc((4 * n + ku + kv) * sizeof *x), *y = malloc((4 * n + ku + kv) * sizeof *y);
    CHECK_OK(projcurve_surface_nurbs_data(ctx, a, x, x + 3 * n, x + 4 * n, x + 4 * n + ku));
    CHECK_OK(projcurve_surface_nurbs_data(ctx, b, y, y + 3 * n, y + 4 * n, y + 4 * n + ku));
    same_doubles(x, y, 3 * n, ra ? 1 : 0, "surface control points");
    same_doubles(x + 3 * n, y + 3 * n, n + ku + kv, 0, "surface weights and knots");
    free(x);
    free(y);
}

static void same_curve(const projcurve_curve *a, const projcurve_curve *b, int ulps)
{
    int da, db, ra, rb;
    size_t na, nb;
    CHECK_OK(projcurve_curve_nurbs_info(ctx, a, &da, &na, NULL, &ra));
    CHECK_OK(projcurve_curve_nurbs_info(ctx, b, &db, &nb, NULL, &rb));
    CHECK(da == db && na == nb && ra == rb);
    if (!(da == db && na == nb))
        return;
    const size_t nk = na + (size_t)da + 1;
    double *x = malloc((4 * na + nk) * sizeof *x), *y = malloc((4 * na + nk) * sizeof *y);
    CHECK_OK(projcurve_curve_nurbs_data(ctx, a, x, x + 3 * na, x + 4 * na));
    CHECK_OK(projcurve_curve_nurbs_data(ctx, b, y, y + 3 * na, y + 4 * na));
    same_doubles(x, y, 3 * na, ra ? ulps : 0, "curve control points");
    same_doubles(x + 3 * na, y + 3 * na, na + nk, 0, "curve weights and knots");
    free(x);
    free(y);
}

static projcurve_surface *wavy_sheet(void)
{
    /* bicubic 5 x 4, an interior knot in u, reals that need 17 digits */
    double ctrl[5 * 4 * 3];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) {
            double *p = ctrl + 3 * (j * 5 + i);
            p[0] = i * 0.1 + 1e-17 * j;
            p[1] = j / 3.0;
            p[2] = sin(i + 2.0 * j) * 1e5;
        }
    const double ku[] = {0, 0, 0, 0, 0.3, 1, 1, 1, 1}, kv[] = {-1, -1, -1, -1, 2, 2, 2, 2};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 3, 3, 5, 4, ctrl, NULL, ku, kv, &s));
    return s;
}

static projcurve_surface *quarter_cylinder(void)
{
    const double w = 0.70710678118654752;
    const double ctrl[] = {3, 0, 0, 3, 0, 3, 0, 0, 3, 3, 5, 0, 3, 5, 3, 0, 5, 3};
    const double weights[] = {1, w, 1, 1, w, 1};
    const double ku[] = {0, 0, 0, 1, 1, 1}, kv[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 2, 1, 3, 2, ctrl, weights, ku, kv, &s));
    return s;
}

static projcurve_curve *half_circle(void)
{
    /* rational quadratic, 3 arcs of 60 degrees: weights cos 60 = 0.5 */
    const double ctrl[] = {1, 0, 0.5, 1, 1.7320508075688772, 0.5, 0, 1.1547005383792515, 0.5,
                           -1, 1.7320508075688772, 0.5, -1, 0, 0.5};
    const double weights[] = {1, 0.5, 1, 0.5, 1};
    const double knots[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 2, 5, ctrl, weights, knots, &c));
    return c;
}

static projcurve_curve *cubic(void)
{
    const double ctrl[] = {0, 0, 5, 3, 4, 6, 6, -1, 5, 9, 2, 7, 1e-300, -30000000.000000004, 0.1};
    const double knots[] = {0, 0, 0, 0, 0.25, 1, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 3, 5, ctrl, NULL, knots, &c));
    return c;
}

static void geometry_round_trip(void)
{
    projcurve_surface *s1 = wavy_sheet(), *s2 = quarter_cylinder();
    projcurve_curve *c1 = cubic(), *c2 = half_circle();
    projcurve_step_writer *w = NULL;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s1));
    CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s2));
    CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s1)); /* written once */
    CHECK_OK(projcurve_step_writer_add_curve(ctx, w, c1));
    CHECK_OK(projcurve_step_writer_add_curve(ctx, w, c2));
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_a));
    projcurve_step_writer_destroy(w);
    projcurve_model *m = read_back(path_a);
    if (m != NULL) {
        CHECK(projcurve_model_surface_count(m) == 2);
        CHECK(projcurve_model_curve_count(m) == 2);
        CHECK(projcurve_model_skipped_count(m) == 0);
        if (projcurve_model_surface_count(m) == 2 && projcurve_model_curve_count(m) == 2) {
            same_surface(s1, projcurve_model_surface(m, 0));
            same_surface(s2, projcurve_model_surface(m, 1));
            same_curve(c1, projcurve_model_curve(m, 0), 0);
            same_curve(c2, projcurve_model_curve(m, 1), 1);
        }
        double unit = 0.0, precision = 0.0;
        CHECK(projcurve_model_length_unit(m, &unit) && unit == 1e-3);
        CHECK(projcurve_model_precision(m, &precision) && precision == 1e-7);
    }
    projcurve_model_destroy(m);
    /* the rational forms are the complex entities, the others simple */
    char *text = pc_test_read_file(path_a, NULL);
    CHECK(text != NULL && strstr(text, "RATIONAL_B_SPLINE_SURFACE(") != NULL &&
          strstr(text, "RATIONAL_B_SPLINE_CURVE(") != NULL &&
          strstr(text, "=B_SPLINE_SURFACE_WITH_KNOTS('',3,3,") != NULL &&
          strstr(text, "=B_SPLINE_CURVE_WITH_KNOTS('',3,") != NULL &&
          strstr(text, "FILE_SCHEMA(('AUTOMOTIVE_DESIGN") != NULL);
    free(text);
    projcurve_curve_destroy(c1);
    projcurve_curve_destroy(c2);
    projcurve_surface_destroy(s1);
    projcurve_surface_destroy(s2);
}

/* The instances of a file, for following references. */
typedef struct step_text {
    char *text;
    size_t len, work;
    pc_step_file f;
    pc_arena arena;
} step_text;

static int open_step(step_text *t, const char *path)
{
    memset(t, 0, sizeof *t);
    t->text = pc_test_read_file(path, &t->len);
    if (t->text == NULL)
        return 0;
    t->f = (pc_step_file){.ctx = ctx, .text = t->text, .len = t->len, .work_done = &t->work,
                          .work_limit = (size_t)-1, .radians_per_angle_unit = 1.0};
    pc_arena_init(&t->arena, 1u << 16);
    return pc_step_index(&t->f) == PROJCURVE_OK;
}

static void close_step(step_text *t)
{
    pc_step_index_free(&t->f);
    pc_arena_release(&t->arena);
    free(t->text);
}

static const pc_step_node *follow(step_text *t, const pc_step_instance *from,
                                  const pc_step_node *ref, const char *type,
                                  pc_step_located *out)
{
    if (pc_step_resolve(&t->f, &t->arena, from, ref, out) != PROJCURVE_OK ||
        !pc_step_is(out->node, type))
        return NULL;
    return out->node;
}

/* Branch b's SURFACE_CURVE (the b-th in the file): its PCURVE is the
 * compact pcurve bit for bit and lies on the surface #surface_id. */
static void check_surface_curve(step_text *t, const pc_step_instance *inst,
                                const pc_branch *b, long surface_id)
{
    pc_step_node *sc = NULL;
    CHECK_OK(pc_step_parse(&t->f, inst, &t->arena, &sc));
    const pc_step_node *list = sc ? pc_step_child(sc, 2) : NULL;
    const pc_step_node *master = sc ? pc_step_child(sc, 3) : NULL;
    CHECK(list != NULL && list->kind == PC_STEP_LIST && list->n_children == 1);
    CHECK(master != NULL && master->kind == PC_STEP_ENUM && master->len >= 9 &&
          strstr(master->text, "PCURVE_S1") == master->text + (master->text[0] == '.'));
    if (list == NULL || list->n_children != 1)
        return;
    pc_step_located pc, rep, curve;
    const pc_step_node *pcurve = follow(t, inst, list->first, "PCURVE", &pc);
    CHECK(pcurve != NULL);
    if (pcurve == NULL)
        return;
    const pc_step_node *sref = pc_step_child(pcurve, 1);
    CHECK(sref != NULL && sref->kind == PC_STEP_REF && sref->ref == surface_id);
    const pc_step_node *dr =
        follow(t, pc.inst, pc_step_child(pcurve, 2), "DEFINITIONAL_REPRESENTATION", &rep);
    CHECK(dr != NULL);
    const pc_step_node *items = dr ? pc_step_child(dr, 1) : NULL;
    CHECK(items != NULL && items->n_children == 1);
    if (items == NULL || items->n_children != 1 ||
        pc_step_resolve(&t->f, &t->arena, rep.inst, items->first, &curve) != PROJCURVE_OK)
        return;
    pc_io_curve q;
    const char *skip = NULL;
    CHECK_OK(pc_step_curve(&t->f, &t->arena, &curve, &q, NULL, &skip));
    CHECK(skip == pc_step_planar_curve); /* 2D points */
    const pc_bspline *c = &b->compact_pcurve;
    CHECK(q.degree == c->degree && q.n_ctrl == c->n_poles);
    if (q.degree != c->degree || q.n_ctrl != c->n_poles)
        return;
    double *uv = malloc(2 * q.n_ctrl * sizeof *uv);
    for (size_t i = 0; i < q.n_ctrl; ++i) {
        uv[2 * i] = q.ctrl[3 * i];
        uv[2 * i + 1] = q.ctrl[3 * i + 1];
    }
    same_doubles(c->poles, uv, 2 * q.n_ctrl, 0, "pcurve poles");
    same_doubles(c->knots, q.knots, q.n_ctrl + (size_t)q.degree + 1, 0, "pcurve knots");
    CHECK((c->weights == NULL) == (q.weights == NULL));
    if (c->weights && q.weights)
        same_doubles(c->weights, q.weights, q.n_ctrl, 0, "pcurve weights");
    free(uv);
}

static void check_result_file(const char *path, const projcurve_surface *s,
                              const projcurve_result *r)
{
    const size_t n = projcurve_result_branch_count(r);
    projcurve_model *m = read_back(path);
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 1 && projcurve_model_curve_count(m) == n);
    if (projcurve_model_surface_count(m) == 1)
        same_surface(s, projcurve_model_surface(m, 0));
    for (size_t b = 0; b < n && b < projcurve_model_curve_count(m); ++b) {
        projcurve_curve *c = NULL;
        CHECK_OK(projcurve_result_branch_compact_curve(ctx, r, b, &c));
        if (c != NULL) {
            const projcurve_curve *back = projcurve_model_curve(m, b);
            CHECK(c->nurbs.n_ctrl == back->nurbs.n_ctrl);
            if (c->nurbs.n_ctrl == back->nurbs.n_ctrl)
                same_doubles(c->nurbs.cw, back->nurbs.cw, 4 * c->nurbs.n_ctrl, 0,
                             "compact curve (homogeneous)");
        }
        projcurve_curve_destroy(c);
    }
    projcurve_model_destroy(m);
    step_text t;
    CHECK(open_step(&t, path));
    long surface_id = -1;
    size_t b = 0;
    char name[PC_STEP_MAX_NAME];
    for (size_t i = 0; i < t.f.n_instances; ++i) {
        const pc_step_instance *inst = &t.f.instances[i];
        pc_step_name(&t.f, inst, name);
        if (strcmp(name, "B_SPLINE_SURFACE_WITH_KNOTS") == 0 || name[0] == '\0') {
            pc_step_node *node = NULL;
            if (pc_step_parse(&t.f, inst, &t.arena, &node) == PROJCURVE_OK &&
                (pc_step_is(node, "B_SPLINE_SURFACE_WITH_KNOTS") ||
                 pc_step_part(node, "B_SPLINE_SURFACE") != NULL))
                surface_id = inst->id;
        }
        if (strcmp(name, "SURFACE_CURVE") == 0 && b < n)
            check_surface_curve(&t, inst, &r->branches[b++], surface_id);
    }
    CHECK(b == n && surface_id > 0);
    close_step(&t);
}

static void result_round_trip(void)
{
    projcurve_model *in = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path("cases/fold_c_sheet_jump.igs"), &in));
    if (in == NULL)
        return;
    const projcurve_surface *s = projcurve_model_surface(in, 0);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(ctx, s, projcurve_model_curve(in, 0), dir, NULL, &r));
    CHECK(projcurve_result_branch_count(r) == 2);
    projcurve_step_writer *w = NULL;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_result(ctx, w, s, r));
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_a));
    check_result_file(path_a, s, r);
    /* the uncertainty covers the measured gap between the two forms */
    projcurve_model *m = read_back(path_a);
    double precision = 0.0, worst = 0.0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        double qe = 0.0, ce = 0.0;
        CHECK_OK(projcurve_result_branch_compact_info(ctx, r, b, NULL, &qe, &ce));
        worst = fmax(worst, qe + ce);
    }
    CHECK(m && projcurve_model_precision(m, &precision) && precision >= worst * (1 - 1e-15) &&
          precision >= 1e-7);
    projcurve_model_destroy(m);

    /* a failing addition (no compact forms) leaves the writer as it was */
    char *before = pc_test_read_file(path_a, NULL);
    projcurve_options *no_compose = NULL;
    CHECK_OK(projcurve_options_create(ctx, &no_compose));
    CHECK_OK(projcurve_options_set_int(ctx, no_compose, PROJCURVE_OPT_COMPOSE, 0));
    projcurve_result *bare = NULL;
    CHECK_OK(projcurve_project_directional(ctx, s, projcurve_model_curve(in, 0), dir, no_compose,
                                           &bare));
    projcurve_surface *other = quarter_cylinder(); /* would be new: rolled back too */
    CHECK_STATUS(projcurve_step_writer_add_result(ctx, w, other, bare),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    projcurve_surface_destroy(other);
    CHECK(strstr(projcurve_context_message(ctx), "compact") != NULL);
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_b));
    char *after = pc_test_read_file(path_b, NULL);
    CHECK(before && after && strcmp(before, after) == 0);
    free(before);
    free(after);
    projcurve_result_destroy(bare);
    projcurve_options_destroy(no_compose);
    projcurve_step_writer_destroy(w);
    projcurve_result_destroy(r);
    projcurve_model_destroy(in);
}

/* A circle above a plane projects in the circle's own rational space
 * (docs/fit.md): rational compact forms, the complex entities in 2D and
 * 3D, back bit for bit as well. */
static void rational_result_round_trip(void)
{
    pc_shape_surface plane = pc_shape_plane(3, 3, 4, 4); /* (2u - 1, 3v - 1, 0) */
    const double centre[3] = {0.1, 0.2, 0.7};
    pc_shape_curve circle = pc_shape_circle(centre, 0.6);
    projcurve_surface *s = pc_shape_surface_create(&plane);
    projcurve_curve *c = pc_shape_curve_create(&circle);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(ctx, s, c, dir, NULL, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    CHECK(r && r->n_branches == 1 && r->branches[0].compact_pcurve.weights != NULL &&
          r->branches[0].compact_curve.weights != NULL);
    projcurve_step_writer *w = NULL;
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_OK(projcurve_step_writer_add_result(ctx, w, s, r));
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_a));
    projcurve_step_writer_destroy(w);
    check_result_file(path_a, s, r);
    char *text = pc_test_read_file(path_a, NULL);
    const char *first = text ? strstr(text, "RATIONAL_B_SPLINE_CURVE(") : NULL;
    CHECK(first != NULL && strstr(first + 1, "RATIONAL_B_SPLINE_CURVE(") != NULL);
    free(text);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&plane);
    pc_shape_curve_free(&circle);
}

/* The unit and uncertainty come back as set: SI prefixes exactly (the
 * reader's factor), other sizes exactly (a conversion-based unit measured
 * in metres: value times 1); the uncertainty, given in model units and
 * read back as value * unit / unit, to 1 ulp. */
static void units_round_trip(void)
{
    const double units[] = {1e-3, 1.0, 1e-2, 0.0254, 0.3048, 1609.344, 0.1234567890123};
    for (size_t i = 0; i < sizeof units / sizeof *units; ++i) {
        projcurve_step_writer *w = NULL;
        projcurve_curve *c = cubic();
        CHECK_OK(projcurve_step_writer_create(ctx, &w));
        CHECK_OK(projcurve_step_writer_add_curve(ctx, w, c));
        CHECK_OK(projcurve_step_writer_set_length_unit(ctx, w, units[i]));
        CHECK_OK(projcurve_step_writer_set_uncertainty(ctx, w, 2.5e-6));
        CHECK_OK(projcurve_step_writer_write(ctx, w, path_a));
        projcurve_step_writer_destroy(w);
        projcurve_model *m = read_back(path_a);
        double unit = 0.0, precision = 0.0;
        CHECK(m && projcurve_model_length_unit(m, &unit));
        if (unit != units[i])
            pc_test_fail_at(__FILE__, __LINE__, "unit %.17g read back as %.17g", units[i], unit);
        CHECK(m && projcurve_model_precision(m, &precision) && within_ulps(precision, 2.5e-6, 1));
        CHECK(m && projcurve_model_curve_count(m) == 1);
        if (m && projcurve_model_curve_count(m) == 1)
            same_curve(c, projcurve_model_curve(m, 0), 0);
        projcurve_model_destroy(m);
        projcurve_curve_destroy(c);
    }
}

/* Reals as written: a decimal point always, the double back exactly. */
static void reals(void)
{
    const double v[] = {3.0, -0.0, 0.0, 1e-5, 1e22, -2.5e-300, 0.1, 1.0 / 3.0, 4.9e-324,
                        1.7976931348623157e308, 123456789012345678.0};
    for (size_t i = 0; i < sizeof v / sizeof *v; ++i) {
        pc_text_buf b = {0};
        pc_text_buf_real(&b, v[i]);
        CHECK(!b.failed && b.text != NULL && strchr(b.text, '.') != NULL);
        /* STEP REAL: sign? digit+ '.' digit* (E sign? digit+)? */
        const char *p = b.text ? b.text : "";
        p += (*p == '-');
        int ok = *p >= '0' && *p <= '9';
        while (*p >= '0' && *p <= '9')
            ++p;
        ok = ok && *p++ == '.';
        while (ok && *p >= '0' && *p <= '9')
            ++p;
        if (ok && *p == 'E') {
            ++p;
            p += (*p == '-' || *p == '+');
            ok = *p >= '0' && *p <= '9';
            while (*p >= '0' && *p <= '9')
                ++p;
        }
        CHECK(ok && *p == '\0');
        const double back = b.text ? strtod(b.text, NULL) : NAN;
        CHECK(memcmp(&back, &v[i], sizeof back) == 0);
        pc_text_buf_free(&b);
    }
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
    projcurve_step_writer *w = NULL;
    projcurve_surface *s = quarter_cylinder();
    CHECK_STATUS(projcurve_step_writer_create(ctx, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_STATUS(projcurve_step_writer_add_surface(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_add_surface(ctx, NULL, s), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_add_curve(ctx, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_add_result(ctx, w, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_add_result(ctx, w, s, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_curve *cb = NULL;
    CHECK_OK(projcurve_curve_create_callback(ctx, call_back, NULL, 0.0, 1.0, &cb));
    CHECK_STATUS(projcurve_step_writer_add_curve(ctx, w, cb), PROJCURVE_ERR_WRONG_KIND);
    projcurve_curve_destroy(cb);
    CHECK_STATUS(projcurve_step_writer_set_length_unit(ctx, NULL, 1.0), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_set_length_unit(ctx, w, NAN), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_step_writer_set_length_unit(ctx, w, INFINITY), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_step_writer_set_length_unit(ctx, w, 0.0), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_step_writer_set_length_unit(ctx, w, -1.0), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_step_writer_set_uncertainty(ctx, NULL, 1.0), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_set_uncertainty(ctx, w, NAN), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_step_writer_set_uncertainty(ctx, w, -INFINITY), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_step_writer_set_uncertainty(ctx, w, 0.0), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_step_writer_write(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_write(ctx, NULL, path_b), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_step_writer_write(ctx, w, "/nonexistent-dir/x.step"), PROJCURVE_ERR_IO);
    CHECK(strstr(projcurve_context_message(ctx), "/nonexistent-dir/x.step") != NULL);
    /* the failed settings left millimetres; an empty writer makes a file
     * the reader takes, and a writer stays usable after writing */
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_b));
    projcurve_model *m = read_back(path_b);
    double unit = 0.0;
    CHECK(m && projcurve_model_surface_count(m) == 0 && projcurve_model_length_unit(m, &unit) &&
          unit == 1e-3);
    projcurve_model_destroy(m);
    CHECK_OK(projcurve_step_writer_add_surface(ctx, w, s));
    CHECK_OK(projcurve_step_writer_write(ctx, w, path_b));
    m = read_back(path_b);
    CHECK(m && projcurve_model_surface_count(m) == 1);
    projcurve_model_destroy(m);
    projcurve_step_writer_destroy(w);
    projcurve_step_writer_destroy(NULL);
    projcurve_surface_destroy(s);
}

/* Non-finite geometry cannot come through the handles (their creation
 * refuses it); the formatter refuses it too, adding nothing. */
static void non_finite(void)
{
    pc_step_out out;
    pc_step_out_init(&out);
    const double poles[] = {0, 0, 0, 1, NAN, 0}, knots[] = {0, 0, 1, 1};
    const pc_step_spline c = {.degree = 1, .dim = 3, .n_poles = 2, .knots = knots, .poles = poles};
    const pc_step_mark mark = pc_step_out_mark(&out);
    long id = 0;
    CHECK_STATUS(pc_step_out_curve(ctx, &out, &c, &id), PROJCURVE_ERR_NOT_FINITE);
    CHECK(out.data.len == mark.len && out.next_id == mark.next_id);
    const double inf_knots[] = {0, 0, INFINITY, INFINITY}, fine[] = {0, 0, 0, 1, 1, 0};
    const pc_step_spline d = {.degree = 1, .dim = 3, .n_poles = 2, .knots = inf_knots, .poles = fine};
    CHECK_STATUS(pc_step_out_curve(ctx, &out, &d, &id), PROJCURVE_ERR_NOT_FINITE);
    pc_step_out_free(&out);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const char *tmp = getenv("TMPDIR");
    snprintf(path_a, sizeof path_a, "%s/projcurve_sw_%ld_a.step", tmp ? tmp : "/tmp", (long)getpid());
    snprintf(path_b, sizeof path_b, "%s/projcurve_sw_%ld_b.stp", tmp ? tmp : "/tmp", (long)getpid());
    geometry_round_trip();
    result_round_trip();
    rational_result_round_trip();
    units_round_trip();
    reals();
    misuse();
    non_finite();
    remove(path_a);
    remove(path_b);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_step_write");
}
