/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP analytic surfaces read as exact NURBS (src/io/step_analytic.c):
 *
 *  - linkrods.step: 6 planes, 4 cylinders, 9 tori and 18 B-spline
 *    surfaces (the counts Open CASCADE reads from its 37 faces), millimetres
 *    and a precision of 2e-5; every vertex point of every analytic face
 *    lies on the NURBS of the face's surface within the
 *    file's precision, by the library's closest point, and so do samples
 *    of every line and conic edge's NURBS between its vertices
 *    (pc_step_edge_curve), which starts and ends at them. The same for the
 *    analytic B-rep cases of tests/data/cases-brep.
 *  - small files written here: each kind against its Part 42 formula, the
 *    box of an unbounded surface covering its face's points, units (inch,
 *    degrees), refused values and unbounded surfaces without faces listed
 *    as skipped with the reason.
 *
 * Surfaces of the model: B-spline ones first in file order, then the
 * analytic ones in file order (io_model.h), which is how a face's surface
 * instance is matched to its model index here.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/step_analytic.h"
#include "io/step_geom.h"
#include "projcurve.h"

#define PI 3.14159265358979323846

static projcurve_context *ctx;

typedef struct indexed {
    char *text;
    size_t work;
    pc_step_file f;
    long *surface_ids; /* model index -> surface instance id */
    size_t n_surfaces;
} indexed;

static int is_bspline_surface(indexed *x, pc_arena *arena, const pc_step_instance *inst)
{
    pc_step_node *node = NULL;
    if (pc_step_parse(&x->f, inst, arena, &node) != PROJCURVE_OK)
        return 0;
    return pc_step_part(node, "B_SPLINE_SURFACE") != NULL ||
           pc_step_part(node, "B_SPLINE_SURFACE_WITH_KNOTS") != NULL;
}

/* The file indexed, with the instance id of every model surface in model
 * order: the B-spline surfaces by id, then the analytic ones by id. */
static int index_file(const char *text, size_t len, indexed *x)
{
    memset(x, 0, sizeof *x);
    x->text = malloc(len + 1);
    memcpy(x->text, text, len);
    x->text[len] = '\0';
    x->f = (pc_step_file){.ctx = ctx, .text = x->text, .len = len, .work_done = &x->work,
                          .work_limit = (size_t)-1, .radians_per_angle_unit = 1.0};
    if (pc_step_index(&x->f) != PROJCURVE_OK)
        return 0;
    x->surface_ids = calloc(x->f.n_instances + 1, sizeof *x->surface_ids);
    pc_arena arena;
    pc_arena_init(&arena, 1 << 16);
    for (int pass = 0; pass < 2; ++pass)
        for (size_t i = 0; i < x->f.n_instances; ++i) {
            const pc_step_instance *inst = &x->f.instances[i];
            char name[PC_STEP_MAX_NAME];
            pc_step_name(&x->f, inst, name);
            const int take = pass == 0 ? is_bspline_surface(x, &arena, inst)
                                       : pc_step_is_analytic_surface(name);
            if (take)
                x->surface_ids[x->n_surfaces++] = inst->id;
            pc_arena_release(&arena);
        }
    return 1;
}

static void index_free(indexed *x)
{
    pc_step_index_free(&x->f);
    free(x->surface_ids);
    free(x->text);
}

typedef struct on_surface_stats {
    size_t points, edges;
    double worst;
} on_surface_stats;

static void check_on(const projcurve_surface *s, const double p[3], double tol, long face,
                     on_surface_stats *stats)
{
    double uv[2], q[3], dist = HUGE_VAL;
    CHECK_OK(projcurve_surface_closest_point(ctx, s, p, uv, q, &dist));
    ++stats->points;
    stats->worst = fmax(stats->worst, dist);
    if (!(dist <= tol))
        pc_test_fail_at(__FILE__, __LINE__,
                        "face #%ld: point (%.9g, %.9g, %.9g) is %.3g from its surface (tolerance %.3g)",
                        face, p[0], p[1], p[2], dist, tol);
    ++pc_test_checks;
}

/* The edge's NURBS between its vertices: it starts and ends at them,
 * follows its conic's Part 42 formula through the angle map, and its
 * samples lie on the face's surface. */
static void edge_on_surface(indexed *x, pc_arena *arena, const pc_step_located *ec,
                            const projcurve_surface *s, double tol, long face,
                            on_surface_stats *stats)
{
    pc_io_curve k;
    pc_angle_map map;
    const char *skip = NULL;
    CHECK_OK(pc_step_edge_curve(&x->f, arena, ec, &k, &map, &skip));
    if (skip != NULL)
        return;
    double ends[2][3], t0 = k.knots[k.degree], t1 = k.knots[k.n_ctrl];
    for (size_t j = 0; j < 2; ++j) {
        pc_step_located v;
        CHECK_OK(pc_step_resolve(&x->f, arena, ec->inst, pc_step_child(ec->node, 1 + j), &v));
        CHECK_OK(pc_step_point(&x->f, arena, v.inst, pc_step_child(v.node, 1), ends[j]));
    }
    const pc_step_node *sense = pc_step_child(ec->node, 4);
    const int forward = !(sense && sense->kind == PC_STEP_ENUM && sense->text[0] == 'F');
    double a[3], b[3];
    pc_rational_curve_eval(&k, t0, a);
    pc_rational_curve_eval(&k, t1, b);
    const double *from = ends[forward ? 0 : 1], *to = ends[forward ? 1 : 0];
    for (int q = 0; q < 3; ++q) {
        CHECK_NEAR(a[q], from[q], tol);
        CHECK_NEAR(b[q], to[q], tol);
    }
    pc_step_located c;
    CHECK_OK(pc_step_resolve(&x->f, arena, ec->inst, pc_step_child(ec->node, 3), &c));
    if (pc_step_is(c.node, "SURFACE_CURVE") || pc_step_is(c.node, "SEAM_CURVE"))
        CHECK_OK(pc_step_resolve(&x->f, arena, c.inst, pc_step_child(c.node, 1), &c));
    const int conic = pc_step_is(c.node, "CIRCLE") || pc_step_is(c.node, "ELLIPSE");
    /* B-spline edges are the file's own curves, off the planes they bound
     * by up to 9e-5 in linkrods (its edge tolerance): only their ends are
     * checked. */
    if (!conic && !pc_step_is(c.node, "LINE"))
        return;
    double o[3], ax[3], ay[3], ra = 0.0, rb = 0.0;
    if (conic)
        CHECK_OK(pc_step_conic(&x->f, arena, &c, o, ax, ay, &ra, &rb, &skip));
    for (int i = 0; i <= 16; ++i) {
        const double t = t0 + (t1 - t0) * i / 16.0;
        double p[3];
        pc_rational_curve_eval(&k, t, p);
        check_on(s, p, tol, face, stats);
        if (conic) {
            const double ang = pc_nurbs_to_angle(&map, t);
            for (int q = 0; q < 3; ++q)
                CHECK_NEAR(p[q], o[q] + ra * cos(ang) * ax[q] + rb * sin(ang) * ay[q],
                           1e-12 * (1.0 + ra));
        }
    }
    ++stats->edges;
}

/* Vertex points and edge curve samples of every edge of the face. */
static void face_on_surface(indexed *x, pc_arena *arena, const pc_step_instance *fi,
                            const projcurve_surface *s, double tol, on_surface_stats *stats)
{
    pc_step_node *face = NULL;
    CHECK_OK(pc_step_parse(&x->f, fi, arena, &face));
    const pc_step_node *bounds = pc_step_child(face, 1);
    for (const pc_step_node *b = bounds ? bounds->first : NULL; b; b = b->next) {
        pc_step_located fb, loop;
        CHECK_OK(pc_step_resolve(&x->f, arena, fi, b, &fb));
        CHECK_OK(pc_step_resolve(&x->f, arena, fb.inst, pc_step_child(fb.node, 1), &loop));
        const pc_step_node *items = pc_step_child(loop.node, 1);
        if (pc_step_is(loop.node, "VERTEX_LOOP")) {
            pc_step_located v;
            double p[3];
            CHECK_OK(pc_step_resolve(&x->f, arena, loop.inst, items, &v));
            CHECK_OK(pc_step_point(&x->f, arena, v.inst, pc_step_child(v.node, 1), p));
            check_on(s, p, tol, (long)fi->id, stats);
            continue;
        }
        for (const pc_step_node *oe = items ? items->first : NULL; oe; oe = oe->next) {
            pc_step_located e, ec;
            CHECK_OK(pc_step_resolve(&x->f, arena, loop.inst, oe, &e));
            CHECK_OK(pc_step_resolve(&x->f, arena, e.inst, pc_step_child(e.node, 3), &ec));
            for (size_t k = 1; k <= 2; ++k) {
                pc_step_located v;
                double p[3];
                CHECK_OK(pc_step_resolve(&x->f, arena, ec.inst, pc_step_child(ec.node, k), &v));
                CHECK_OK(pc_step_point(&x->f, arena, v.inst, pc_step_child(v.node, 1), p));
                check_on(s, p, tol, (long)fi->id, stats);
            }
            edge_on_surface(x, arena, &ec, s, tol, (long)fi->id, stats);
        }
    }
}

typedef struct kind_count {
    const char *kind;
    size_t count;
} kind_count;

static void check_model_file(const char *relative, const kind_count *want, size_t n_want,
                             size_t want_analytic_faces, double want_unit, double want_precision)
{
    const char *path = pc_test_data_path(relative);
    size_t len = 0;
    char *text = pc_test_read_file(path, &len);
    if (text == NULL) {
        pc_test_missing_data(path);
        return;
    }
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_memory(ctx, text, len, &m));
    indexed x;
    if (m == NULL || !index_file(text, len, &x)) {
        CHECK(0);
        free(text);
        projcurve_model_destroy(m);
        return;
    }
    CHECK(x.n_surfaces == projcurve_model_surface_count(m));
    for (size_t k = 0; k < n_want; ++k) {
        size_t got = 0;
        for (size_t i = 0; i < projcurve_model_surface_count(m); ++i)
            got += strcmp(projcurve_model_surface_kind(m, i), want[k].kind) == 0;
        if (got != want[k].count)
            pc_test_fail_at(__FILE__, __LINE__, "%s: %zu surfaces of kind %s, expected %zu",
                            relative, got, want[k].kind, want[k].count);
        ++pc_test_checks;
    }
    double unit = 0.0, precision = 0.0;
    CHECK(projcurve_model_length_unit(m, &unit) == 1);
    CHECK_NEAR(unit, want_unit, 1e-15);
    CHECK(projcurve_model_precision(m, &precision) == 1);
    CHECK_NEAR(precision, want_precision, 1e-18);
    on_surface_stats stats = {0, 0, 0.0};
    pc_arena arena;
    pc_arena_init(&arena, 1 << 16);
    size_t faces = 0;
    for (size_t i = 0; i < x.f.n_instances; ++i) {
        const pc_step_instance *fi = &x.f.instances[i];
        char name[PC_STEP_MAX_NAME];
        pc_step_name(&x.f, fi, name);
        if (strcmp(name, "ADVANCED_FACE") != 0)
            continue;
        pc_step_node *face = NULL;
        CHECK_OK(pc_step_parse(&x.f, fi, &arena, &face));
        const pc_step_node *sref = pc_step_child(face, 2);
        size_t k = 0;
        while (k < x.n_surfaces && !(sref && x.surface_ids[k] == sref->ref))
            ++k;
        CHECK(k < x.n_surfaces);
        /* B-spline faces keep the file's own surface: their vertices are
         * off it by the file's edge tolerances (up to 2e-4 in linkrods),
         * which is not what this test is about. */
        if (k < x.n_surfaces && strcmp(projcurve_model_surface_kind(m, k), "bspline") != 0) {
            ++faces;
            face_on_surface(&x, &arena, fi, projcurve_model_surface(m, k), want_precision, &stats);
        }
        pc_arena_release(&arena);
    }
    printf("%-40s %zu analytic faces, %zu edges, %zu points on their surfaces, farthest %.2e "
           "(precision %g)\n", relative, faces, stats.edges, stats.points, stats.worst, want_precision);
    CHECK(faces == want_analytic_faces && stats.points >= faces);
    /* every face of the file is built, the analytic ones on their NURBS */
    CHECK(projcurve_model_unbuilt_face_count(m) == 0);
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i)
        printf("%s: unbuilt: %s\n", relative, projcurve_model_unbuilt_face(m, i));
    pc_arena_release(&arena);
    index_free(&x);
    free(text);
    projcurve_model_destroy(m);
}

static void real_and_case_files(void)
{
    const kind_count linkrods[] = {{"plane", 6}, {"cylinder", 4}, {"torus", 9}, {"bspline", 18}};
    check_model_file("real/linkrods.step", linkrods, 4, 19, 1e-3, 2e-5);
    const kind_count cylinder[] = {{"plane", 2}, {"cylinder", 1}};
    check_model_file("cases-brep/cylinder_analytic.step", cylinder, 2, 3, 1e-3, 1e-7);
    const kind_count cone[] = {{"cone", 1}};
    check_model_file("cases-brep/gtest_cone_line_circle.step", cone, 1, 1, 1e-3, 1e-7);
    const kind_count cyl2[] = {{"cylinder", 1}};
    check_model_file("cases-brep/gtest_cylinder_line_circle.step", cyl2, 1, 1, 1e-3, 1e-7);
    const kind_count plane[] = {{"plane", 1}};
    check_model_file("cases-brep/gtest_plane_line_circle.step", plane, 1, 1, 1e-3, 1e-7);
    const kind_count sphere[] = {{"sphere", 1}};
    check_model_file("cases-brep/sphere_analytic.step", sphere, 1, 1, 1e-3, 1e-7);
}

/* ---- small files ------------------------------------------------------------ */

static projcurve_model *read_step(const char *data)
{
    static char text[16384];
    snprintf(text, sizeof text,
             "ISO-10303-21;\nHEADER;\nFILE_NAME('x','',(''),(''),'','','');\nENDSEC;\n"
             "DATA;\n%s\nENDSEC;\nEND-ISO-10303-21;\n",
             data);
    projcurve_model *m = NULL;
    if (projcurve_model_read_memory(ctx, text, strlen(text), &m) != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    return m;
}

/* A frame at (1, 2, 3), axis z = (0, 0, 1), x = (0, 1, 0) (so y = (-1, 0, 0)). */
#define FRAME                                                                                   \
    "#1=CARTESIAN_POINT('',(1.,2.,3.));#2=DIRECTION('',(0.,0.,1.));#3=DIRECTION('',(0.,1.,0.));\n" \
    "#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);\n"

static int skipped_mentions(const projcurve_model *m, const char *what)
{
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i)
        if (strstr(projcurve_model_skipped(m, i), what) != NULL)
            return 1;
    return 0;
}

/* The surface's point at NURBS (s, t) is the Part 42 point of the mapped
 * (u, v), written out here in the frame above. */
static void bounded_kinds(void)
{
    projcurve_model *m = read_step(FRAME
                                   "#5=SPHERICAL_SURFACE('',#4,2.);\n"
                                   "#6=TOROIDAL_SURFACE('',#4,5.,1.5);\n"
                                   "#7=DEGENERATE_TOROIDAL_SURFACE('',#4,1.,2.,.T.);\n"
                                   "#8=SPHERICAL_SURFACE('',#4,-2.);\n");
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 2);
    CHECK(skipped_mentions(m, "#7 DEGENERATE_TOROIDAL_SURFACE (a spindle torus"));
    CHECK(skipped_mentions(m, "#8 SPHERICAL_SURFACE (radius -2 is not positive)"));
    CHECK(strcmp(projcurve_model_surface_kind(m, 0), "sphere") == 0);
    CHECK(strcmp(projcurve_model_surface_kind(m, 1), "torus") == 0);
    CHECK(projcurve_model_surface_kind(m, 2) == NULL);
    CHECK(projcurve_model_length_unit(m, NULL) == 0 && projcurve_model_precision(m, NULL) == 0);
    double dom[4];
    CHECK_OK(projcurve_surface_domain(ctx, projcurve_model_surface(m, 0), dom));
    CHECK_NEAR(dom[0], 0.0, 0.0);
    CHECK_NEAR(dom[1], 2 * PI, 1e-15);
    CHECK_NEAR(dom[2], -PI / 2, 1e-15);
    CHECK_NEAR(dom[3], PI / 2, 1e-15);
    const pc_angle_map mu = pc_angle_map_make(0.0, 2 * PI), mv = pc_angle_map_make(-PI / 2, PI / 2);
    const pc_angle_map tv = pc_angle_map_make(0.0, 2 * PI);
    for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
            const double s = 2 * PI * i / 12.0, t = -PI / 2 + PI * j / 12.0;
            const double u = pc_nurbs_to_angle(&mu, s), v = pc_nurbs_to_angle(&mv, t);
            double p[3];
            CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 0), s, t, 0, p));
            /* C + R cos v (cos u x + sin u y) + R sin v z, x = e2, y = -e1 */
            CHECK_NEAR(p[0], 1.0 - 2.0 * cos(v) * sin(u), 1e-13);
            CHECK_NEAR(p[1], 2.0 + 2.0 * cos(v) * cos(u), 1e-13);
            CHECK_NEAR(p[2], 3.0 + 2.0 * sin(v), 1e-13);
            const double t2 = 2 * PI * j / 12.0, v2 = pc_nurbs_to_angle(&tv, t2);
            CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 1), s, t2, 0, p));
            const double rho = 5.0 + 1.5 * cos(v2);
            CHECK_NEAR(p[0], 1.0 - rho * sin(u), 1e-13);
            CHECK_NEAR(p[1], 2.0 + rho * cos(u), 1e-13);
            CHECK_NEAR(p[2], 3.0 + 1.5 * sin(v2), 1e-13);
        }
    projcurve_model_destroy(m);
}

/* A square face on a cone given in degrees, in an inch context: the cone's
 * box covers the face's heights with the stated margin; semi-angle read
 * as 30 degrees. */
static void units_and_boxes(void)
{
    projcurve_model *m = read_step(
        FRAME
        "#5=CONICAL_SURFACE('',#4,1.,30.);\n"
        "#10=CARTESIAN_POINT('',(1.,3.,3.));#11=VERTEX_POINT('',#10);\n"
        "#12=CARTESIAN_POINT('',(1.,4.1547005383792515,5.));#13=VERTEX_POINT('',#12);\n"
        "#14=DIRECTION('',(0.,1.,0.));#15=VECTOR('',#14,1.);#16=LINE('',#10,#15);\n"
        "#17=EDGE_CURVE('',#11,#13,#16,.T.);#18=ORIENTED_EDGE('',*,*,#17,.T.);\n"
        "#19=EDGE_LOOP('',(#18));#20=FACE_OUTER_BOUND('',#19,.T.);\n"
        "#21=ADVANCED_FACE('',(#20),#5,.T.);\n"
        "#22=PLANE('',#4);\n"
        "#30=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
        "#31=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#30);\n"
        "#32=(CONVERSION_BASED_UNIT('INCH',#31)LENGTH_UNIT()NAMED_UNIT(#33));\n"
        "#33=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"
        "#34=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n"
        "#35=PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(0.0174532925199433),#34);\n"
        "#36=(CONVERSION_BASED_UNIT('DEGREE',#35)NAMED_UNIT(#33)PLANE_ANGLE_UNIT());\n"
        "#37=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(0.0254),#30,'distance_accuracy_value','');\n"
        "#38=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#37))"
        "GLOBAL_UNIT_ASSIGNED_CONTEXT((#32,#36))REPRESENTATION_CONTEXT('',''));\n");
    if (m == NULL)
        return;
    double unit = 0.0, precision = 0.0;
    CHECK(projcurve_model_length_unit(m, &unit) == 1);
    CHECK_NEAR(unit, 0.0254, 1e-17);
    CHECK(projcurve_model_precision(m, &precision) == 1);
    CHECK_NEAR(precision, 0.001, 1e-17); /* 0.0254 mm in inches */
    CHECK(projcurve_model_surface_count(m) == 1);
    CHECK(skipped_mentions(m, "#22 PLANE (unbounded, and used by no face"));
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    double dom[4];
    CHECK_OK(projcurve_surface_domain(ctx, s, dom));
    /* heights 0 and 2 on the face: range [0, 2] widened by 1 % of 2 and
     * 1e-3 of max(2, R = 1) on each side */
    CHECK_NEAR(dom[2], -0.02 - 0.002, 1e-13);
    CHECK_NEAR(dom[3], 2.0 + 0.02 + 0.002, 1e-13);
    /* the semi-angle in degrees: radius at height 2 is 1 + 2 tan 30 deg */
    double p[3];
    CHECK_OK(projcurve_surface_eval(ctx, s, 0.0, 2.0, 0, p));
    CHECK_NEAR(p[1], 2.0 + 1.0 + 2.0 * tan(PI / 6), 1e-13);
    CHECK_NEAR(p[2], 5.0, 1e-13);
    projcurve_model_destroy(m);
}

/* Swept surfaces: a B-spline line revolved (a cone's band) and a circle
 * extruded (a cylinder). */
static void swept_kinds(void)
{
    projcurve_model *m = read_step(
        "#1=CARTESIAN_POINT('',(2.,0.,0.));#2=CARTESIAN_POINT('',(3.,0.,1.));\n"
        "#3=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),"
        ".UNSPECIFIED.);\n"
        "#4=CARTESIAN_POINT('',(0.,0.,0.));#5=DIRECTION('',(0.,0.,1.));\n"
        "#6=AXIS1_PLACEMENT('',#4,#5);#7=SURFACE_OF_REVOLUTION('',#3,#6);\n"
        "#8=DIRECTION('',(1.,0.,0.));#9=AXIS2_PLACEMENT_3D('',#4,#5,#8);\n"
        "#10=CIRCLE('',#9,1.5);#11=DIRECTION('',(0.,0.,1.));#12=VECTOR('',#11,4.);\n"
        "#13=SURFACE_OF_LINEAR_EXTRUSION('',#10,#12);\n"
        "#20=CARTESIAN_POINT('',(1.5,0.,0.));#21=VERTEX_POINT('',#20);\n"
        "#22=CARTESIAN_POINT('',(1.5,0.,8.));#23=VERTEX_POINT('',#22);\n"
        "#24=VECTOR('',#11,1.);#25=LINE('',#20,#24);#26=EDGE_CURVE('',#21,#23,#25,.T.);\n"
        "#27=ORIENTED_EDGE('',*,*,#26,.T.);#28=EDGE_LOOP('',(#27));\n"
        "#29=FACE_BOUND('',#28,.T.);#30=ADVANCED_FACE('',(#29),#13,.T.);\n");
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 2);
    CHECK(strcmp(projcurve_model_surface_kind(m, 0), "revolution") == 0);
    CHECK(strcmp(projcurve_model_surface_kind(m, 1), "extrusion") == 0);
    const pc_angle_map mu = pc_angle_map_make(0.0, 2 * PI);
    for (int i = 0; i <= 8; ++i) {
        const double s = 2 * PI * i / 8.0, u = pc_nurbs_to_angle(&mu, s), t = i / 8.0;
        double p[3];
        CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 0), s, t, 0, p));
        CHECK_NEAR(p[0], (2.0 + t) * cos(u), 1e-13);
        CHECK_NEAR(p[1], (2.0 + t) * sin(u), 1e-13);
        CHECK_NEAR(p[2], t, 1e-13);
        /* extrusion: u is the circle's NURBS parameter, v in units of V = 4 */
        CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 1), s, 0.25 * i, 0, p));
        CHECK_NEAR(p[0], 1.5 * cos(u), 1e-13);
        CHECK_NEAR(p[1], 1.5 * sin(u), 1e-13);
        CHECK_NEAR(p[2], 1.0 * i, 1e-13);
    }
    double dom[4];
    CHECK_OK(projcurve_surface_domain(ctx, projcurve_model_surface(m, 1), dom));
    CHECK(dom[2] < 0.0 && dom[3] > 2.0); /* the face's heights 0 .. 8 are v 0 .. 2 */
    projcurve_model_destroy(m);
}

/* The reader's function for the topology: a surface over given points. */
static void surface_over_points(void)
{
    static const char text[] =
        "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n" FRAME "#5=PLANE('',#4);\n"
        "#6=CYLINDRICAL_SURFACE('',#4,0.);\nENDSEC;\nEND-ISO-10303-21;\n";
    indexed x;
    if (!index_file(text, strlen(text), &x)) {
        CHECK(0);
        return;
    }
    pc_arena arena;
    pc_arena_init(&arena, 1 << 12);
    const double pts[6] = {1.0, 2.0, 3.0, -4.0, 7.0, 3.0}; /* plane (u, v) = (0, 0), (5, 5) */
    pc_step_analytic a;
    const char *skip = NULL;
    CHECK_OK(pc_step_analytic_surface(&x.f, &arena, 5, pts, 2, &a, &skip));
    CHECK(skip == NULL && strcmp(a.kind, "plane") == 0);
    const double pad = 0.01 * 5.0 + 1e-3 * 5.0;
    CHECK_NEAR(a.box[0], -pad, 1e-14);
    CHECK_NEAR(a.box[1], 5.0 + pad, 1e-14);
    CHECK_NEAR(a.box[2], -pad, 1e-14);
    CHECK_NEAR(a.box[3], 5.0 + pad, 1e-14);
    CHECK_OK(pc_step_analytic_surface(&x.f, &arena, 6, pts, 2, &a, &skip));
    CHECK(skip == pc_step_refused_reason);
    CHECK(strstr(projcurve_context_message(ctx), "radius 0 is not positive") != NULL);
    CHECK_STATUS(pc_step_analytic_surface(&x.f, &arena, 99, pts, 2, &a, &skip), PROJCURVE_ERR_PARSE);
    pc_arena_release(&arena);
    index_free(&x);
}

/* Malformed analytic entities and faces: listed with the reason, the rest
 * of the model still loads. */
static void malformed(void)
{
    projcurve_model *m = read_step(FRAME
                                   "#5=SPHERICAL_SURFACE('',#4,2.);\n"
                                   "#6=CYLINDRICAL_SURFACE('',#99,1.);\n"
                                   "#7=TOROIDAL_SURFACE('',#4,'big',1.);\n"
                                   "#8=FACE_BOUND('',#98,.T.);\n"
                                   "#9=ADVANCED_FACE('',(#8),#6,.T.);\n"
                                   "#10=ADVANCED_FACE('',(#4),#5,.T.);\n");
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 1);
    CHECK(skipped_mentions(m, "#6 CYLINDRICAL_SURFACE (STEP #6 (line"));
    CHECK(skipped_mentions(m, "#99, which is not defined"));
    CHECK(skipped_mentions(m, "#7 TOROIDAL_SURFACE (STEP #7 (line"));
    CHECK(skipped_mentions(m, "#9 ADVANCED_FACE (its bounds:"));
    CHECK(skipped_mentions(m, "#10 ADVANCED_FACE (its bounds:"));
    projcurve_model_destroy(m);
}

/* An ELLIPSE edge between two vertices, in both senses: the arc between
 * their parameters, counter clockwise. */
static void ellipse_edges(void)
{
    static const char text[] =
        "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n" FRAME "#5=ELLIPSE('',#4,3.,1.);\n"
        "#6=CARTESIAN_POINT('',(1.,5.,3.));#7=VERTEX_POINT('',#6);\n"
        "#8=CARTESIAN_POINT('',(0.,2.,3.));#9=VERTEX_POINT('',#8);\n"
        "#10=EDGE_CURVE('',#7,#9,#5,.T.);#11=EDGE_CURVE('',#7,#9,#5,.F.);\n"
        "#12=EDGE_CURVE('',#7,#7,#5,.T.);\nENDSEC;\nEND-ISO-10303-21;\n";
    indexed x;
    if (!index_file(text, strlen(text), &x)) {
        CHECK(0);
        return;
    }
    pc_arena arena;
    pc_arena_init(&arena, 1 << 12);
    const long ids[3] = {10, 11, 12};
    const double want[3][2] = {{0.0, PI / 2}, {PI / 2, 2 * PI}, {0.0, 2 * PI}};
    for (int e = 0; e < 3; ++e) {
        pc_step_located ec;
        const pc_step_node ref = {.kind = PC_STEP_REF, .ref = ids[e]};
        CHECK_OK(pc_step_resolve(&x.f, &arena, x.f.instances, &ref, &ec));
        pc_io_curve k;
        pc_angle_map map;
        const char *skip = NULL;
        CHECK_OK(pc_step_edge_curve(&x.f, &arena, &ec, &k, &map, &skip));
        CHECK(skip == NULL);
        if (skip != NULL)
            continue;
        CHECK_NEAR(k.knots[0], want[e][0], 1e-15);
        CHECK_NEAR(k.knots[k.n_ctrl + 2], want[e][1], 1e-15);
        for (int i = 0; i <= 20; ++i) {
            const double s = want[e][0] + (want[e][1] - want[e][0]) * i / 20.0;
            const double t = pc_nurbs_to_angle(&map, s);
            double p[3];
            pc_rational_curve_eval(&k, s, p);
            /* o + 3 cos t x + sin t y with x = e2, y = -e1 */
            CHECK_NEAR(p[0], 1.0 - sin(t), 1e-13);
            CHECK_NEAR(p[1], 2.0 + 3.0 * cos(t), 1e-13);
            CHECK_NEAR(p[2], 3.0, 1e-13);
        }
    }
    pc_arena_release(&arena);
    index_free(&x);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    real_and_case_files();
    bounded_kinds();
    units_and_boxes();
    swept_kinds();
    surface_over_points();
    ellipse_edges();
    malformed();
    projcurve_context_destroy(ctx);
    return pc_test_finish("io_step_analytic");
}
