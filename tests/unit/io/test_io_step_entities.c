/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP entities read from small files written here: the order of control
 * points (STEP lists them u outermost), complex rational forms, implied
 * knots, circles, trimmed lines, circles and B-splines (by parameters and
 * by points), and what is listed as skipped. Expected points are analytic.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#define PI 3.14159265358979323846
#define TIGHT 1e-13

static projcurve_context *ctx;

static projcurve_model *read_step(const char *data)
{
    char text[8192];
    snprintf(text, sizeof text,
             "ISO-10303-21;\nHEADER;\nFILE_NAME('x;y','',(''),(''),'','','');\nENDSEC;\n"
             "DATA;\n/* a comment; with a semicolon */\n%s\nENDSEC;\nEND-ISO-10303-21;\n",
             data);
    projcurve_model *m = NULL;
    if (projcurve_model_read_memory(ctx, text, strlen(text), &m) != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    return m;
}

static void check_point(const double p[3], double x, double y, double z, double tol)
{
    CHECK_NEAR(p[0], x, tol);
    CHECK_NEAR(p[1], y, tol);
    CHECK_NEAR(p[2], z, tol);
}

static void surface_point_order(void)
{
    /* P(i, j) = (i, j, i j), listed ((P00, P01), (P10, P11), (P20, P21)). */
    projcurve_model *m = read_step(
        "#1=CARTESIAN_POINT('',(0.,0.,0.));#2=CARTESIAN_POINT('',(0.,1.,0.));\n"
        "#3=CARTESIAN_POINT('',(1.,0.,0.));#4=CARTESIAN_POINT('',(1.,1.,1.));\n"
        "#5=CARTESIAN_POINT('',(2.,0.,0.));#6=CARTESIAN_POINT('',(2.,1.,2.));\n"
        "#7=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#1,#2),(#3,#4),(#5,#6)),.UNSPECIFIED.,.F.,.F.,"
        ".F.,(2,1,2),(2,2),(0.,0.5,1.),(0.,1.),.UNSPECIFIED.);");
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 1);
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    size_t nu = 0, nv = 0;
    CHECK_OK(projcurve_surface_info(ctx, s, NULL, NULL, &nu, &nv, NULL, NULL, NULL));
    CHECK(nu == 3 && nv == 2);
    double p[3];
    CHECK_OK(projcurve_surface_eval(ctx, s, 1.0, 0.0, 0, p));
    check_point(p, 2, 0, 0, TIGHT);
    CHECK_OK(projcurve_surface_eval(ctx, s, 0.0, 1.0, 0, p));
    check_point(p, 0, 1, 0, TIGHT);
    CHECK_OK(projcurve_surface_eval(ctx, s, 0.5, 1.0, 0, p));
    check_point(p, 1, 1, 1, TIGHT);
    projcurve_model_destroy(m);
}

static void rational_complex_surface(void)
{
    /* A quarter cylinder of radius 3 around the z axis (u), z in [0, 5] (v). */
    const double w = sqrt(0.5);
    char data[4096];
    snprintf(data, sizeof data,
             "#1=CARTESIAN_POINT('',(3.,0.,0.));#2=CARTESIAN_POINT('',(3.,0.,5.));\n"
             "#3=CARTESIAN_POINT('',(3.,3.,0.));#4=CARTESIAN_POINT('',(3.,3.,5.));\n"
             "#5=CARTESIAN_POINT('',(0.,3.,0.));#6=CARTESIAN_POINT('',(0.,3.,5.));\n"
             "#7=( BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,((#1,#2),(#3,#4),(#5,#6)),"
             ".UNSPECIFIED.,.F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,1.),"
             ".UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(("
             "(1.,1.),(%.17g,%.17g),(1.,1.))) REPRESENTATION_ITEM('') SURFACE() );",
             w, w);
    projcurve_model *m = read_step(data);
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 1);
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    int rational = 0;
    CHECK_OK(projcurve_surface_info(ctx, s, NULL, NULL, NULL, NULL, NULL, NULL, &rational));
    CHECK(rational == 1);
    for (int i = 0; i <= 10; ++i) {
        double p[3];
        CHECK_OK(projcurve_surface_eval(ctx, s, i / 10.0, i / 10.0, 0, p));
        CHECK_NEAR(hypot(p[0], p[1]), 3.0, 1e-14);
        CHECK_NEAR(p[2], 5.0 * i / 10.0, 1e-14);
    }
    projcurve_model_destroy(m);
}

static void curves(void)
{
    char data[4096];
    snprintf(
        data, sizeof data,
        /* a cubic Bezier by implied knots */
        "#1=CARTESIAN_POINT('',(0.,0.,0.));#2=CARTESIAN_POINT('',(1.,2.,0.));\n"
        "#3=CARTESIAN_POINT('',(3.,2.,0.));#4=CARTESIAN_POINT('',(4.,0.,0.));\n"
        "#5=BEZIER_CURVE('',3,(#1,#2,#3,#4),.UNSPECIFIED.,.F.,.F.);\n"
        /* a full circle of radius 2 around (1,1,1) in z = 1, starting on +x */
        "#10=CARTESIAN_POINT('',(1.,1.,1.));#11=DIRECTION('',(0.,0.,1.));\n"
        "#12=DIRECTION('',(1.,0.,0.));#13=AXIS2_PLACEMENT_3D('',#10,#11,#12);\n"
        "#14=CIRCLE('',#13,2.);\n"
        /* a line trimmed to t in [1, 3] with |V| = 2: (2,0,0) to (6,0,0) */
        "#20=DIRECTION('',(1.,0.,0.));#21=VECTOR('',#20,2.);#22=LINE('',#1,#21);\n"
        "#23=TRIMMED_CURVE('',#22,(PARAMETER_VALUE(1.)),(PARAMETER_VALUE(3.)),.T.,"
        ".PARAMETER.);\n"
        /* a circle of radius 1 around the origin trimmed from pi/2 down to 0 */
        "#30=AXIS2_PLACEMENT_3D('',#1,#11,#12);#31=CIRCLE('',#30,1.);\n"
        "#32=TRIMMED_CURVE('',#31,(PARAMETER_VALUE(%.17g)),(PARAMETER_VALUE(0.)),.F.,"
        ".PARAMETER.);\n"
        /* a 2D pcurve: listed, not read */
        "#40=CARTESIAN_POINT('',(0.,0.));#41=CARTESIAN_POINT('',(1.,1.));\n"
        "#42=B_SPLINE_CURVE_WITH_KNOTS('',1,(#40,#41),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),"
        ".UNSPECIFIED.);\n"
        "#50=PLANE('',#30);",
        PI / 2);
    projcurve_model *m = read_step(data);
    if (m == NULL)
        return;
    CHECK(projcurve_model_curve_count(m) == 4);
    CHECK(projcurve_model_skipped_count(m) == 2); /* the pcurve and the plane */
    if (projcurve_model_curve_count(m) != 4) {
        projcurve_model_destroy(m);
        return;
    }
    double p[3], t0, t1;
    /* Bezier: B(1/2) = (0 + 3 + 9 + 4) / 8, (0 + 6 + 6 + 0) / 8 */
    const projcurve_curve *c = projcurve_model_curve(m, 0);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, 0.5 * (t0 + t1), 0, p));
    check_point(p, 2.0, 1.5, 0.0, TIGHT);
    /* circle */
    c = projcurve_model_curve(m, 1);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 3, 1, 1, TIGHT);
    for (int i = 0; i <= 16; ++i) {
        CHECK_OK(projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * i / 16.0, 0, p));
        CHECK_NEAR(hypot(p[0] - 1.0, p[1] - 1.0), 2.0, TIGHT);
        CHECK_NEAR(p[2], 1.0, TIGHT);
    }
    /* trimmed line */
    c = projcurve_model_curve(m, 2);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 2, 0, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
    check_point(p, 6, 0, 0, TIGHT);
    /* trimmed circle against its sense: from (0,1,0) to (1,0,0) */
    c = projcurve_model_curve(m, 3);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 0, 1, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
    check_point(p, 1, 0, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, 0.5 * (t0 + t1), 0, p));
    CHECK_NEAR(hypot(p[0], p[1]), 1.0, TIGHT);
    projcurve_model_destroy(m);
}

static void trimmed_bspline(void)
{
    /* A degree-1 B-spline (0,0,0) -> (4,0,0) over [0, 4], trimmed to [1, 3]. */
    projcurve_model *m = read_step(
        "#1=CARTESIAN_POINT('',(0.,0.,0.));#2=CARTESIAN_POINT('',(4.,0.,0.));\n"
        "#3=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,4.),"
        ".UNSPECIFIED.);\n"
        "#4=TRIMMED_CURVE('',#3,(PARAMETER_VALUE(1.)),(PARAMETER_VALUE(3.)),.T.,.PARAMETER.);");
    if (m == NULL)
        return;
    CHECK(projcurve_model_curve_count(m) == 1); /* the basis is read through the trim only */
    const projcurve_curve *c = projcurve_model_curve(m, 0);
    double t0, t1, p[3];
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_NEAR(t0, 1.0, 0.0);
    CHECK_NEAR(t1, 3.0, 0.0);
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 1, 0, 0, TIGHT);
    projcurve_model_destroy(m);
}

/* The rational quadratic Bezier arc with end weights 1 and middle weight w,
 * evaluated in closed form by its Bernstein polynomials at s in [0, 1]. */
static void bezier_arc(const double p0[3], const double p1[3], const double p2[3], double w,
                       double s, double out[3])
{
    const double b0 = (1 - s) * (1 - s), b1 = 2 * s * (1 - s) * w, b2 = s * s;
    for (int k = 0; k < 3; ++k)
        out[k] = (b0 * p0[k] + b1 * p1[k] + b2 * p2[k]) / (b0 + b1 + b2);
}

static void rational_complex_curve(void)
{
    /* A quarter circle of radius 2 around (1, 0, 3) in z = 3, from +x to +y:
     * a rational quadratic with weights (1, sqrt 1/2, 1) over the domain
     * [2, 6], as a complex entity with the parts in STEP's alphabetic order. */
    const double w = sqrt(0.5);
    char data[4096];
    snprintf(data, sizeof data,
             "#1=CARTESIAN_POINT('',(3.,0.,3.));#2=CARTESIAN_POINT('',(3.,2.,3.));\n"
             "#3=CARTESIAN_POINT('',(1.,2.,3.));\n"
             "#4=( BOUNDED_CURVE() B_SPLINE_CURVE(2,(#1,#2,#3),.CIRCULAR_ARC.,.F.,.F.) "
             "B_SPLINE_CURVE_WITH_KNOTS((3,3),(2.,6.),.UNSPECIFIED.) CURVE() "
             "GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE((1.,%.17g,1.)) "
             "REPRESENTATION_ITEM('') );",
             w);
    projcurve_model *m = read_step(data);
    if (m == NULL)
        return;
    CHECK(projcurve_model_curve_count(m) == 1);
    CHECK(projcurve_model_skipped_count(m) == 0);
    if (projcurve_model_curve_count(m) != 1) {
        projcurve_model_destroy(m);
        return;
    }
    const projcurve_curve *c = projcurve_model_curve(m, 0);
    int degree = 0, rational = 0;
    size_t n_ctrl = 0;
    CHECK_OK(projcurve_curve_nurbs_info(ctx, c, &degree, &n_ctrl, NULL, &rational));
    CHECK(degree == 2 && n_ctrl == 3 && rational == 1);
    double t0, t1;
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_NEAR(t0, 2.0, 0.0);
    CHECK_NEAR(t1, 6.0, 0.0);
    const double p0[3] = {3, 0, 3}, p1[3] = {3, 2, 3}, p2[3] = {1, 2, 3};
    for (int i = 0; i <= 16; ++i) {
        double p[3], expected[3];
        CHECK_OK(projcurve_curve_eval(ctx, c, 2.0 + 4.0 * i / 16.0, 0, p));
        bezier_arc(p0, p1, p2, w, i / 16.0, expected);
        check_point(p, expected[0], expected[1], expected[2], TIGHT);
        /* and on the circle itself: the weights make the arc exact */
        CHECK_NEAR(hypot(p[0] - 1.0, p[1]), 2.0, TIGHT);
    }
    /* the middle of a symmetric arc is at 45 degrees */
    double mid[3];
    CHECK_OK(projcurve_curve_eval(ctx, c, 4.0, 0, mid));
    check_point(mid, 1.0 + sqrt(2.0), sqrt(2.0), 3.0, TIGHT);
    projcurve_model_destroy(m);
}

/* Every sample of c lies on the circle of radius 2 around (1, 1, 1) in
 * z = 1, and its angle moves from a0 by a total of sweep (signed, radians)
 * monotonically; the ends are the points given. */
static void check_arc(const projcurve_curve *c, const double from[3], const double to[3],
                      double a0, double sweep)
{
    double t0, t1, p[3];
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, from[0], from[1], from[2], TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
    check_point(p, to[0], to[1], to[2], TIGHT);
    double previous = 0.0; /* angle travelled from a0 */
    for (int i = 0; i <= 32; ++i) {
        CHECK_OK(projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * i / 32.0, 0, p));
        CHECK_NEAR(hypot(p[0] - 1.0, p[1] - 1.0), 2.0, TIGHT);
        CHECK_NEAR(p[2], 1.0, TIGHT);
        /* the angle from a0, unwrapped into the sweep's side */
        double a = atan2(p[1] - 1.0, p[0] - 1.0) - a0;
        a = remainder(a, 2.0 * PI);
        if (sweep > 0 && a < -1e-9)
            a += 2.0 * PI;
        if (sweep < 0 && a > 1e-9)
            a -= 2.0 * PI;
        if (i > 0)
            CHECK(sweep > 0 ? a > previous : a < previous);
        previous = a;
    }
    CHECK_NEAR(previous, sweep, 1e-12);
}

static void point_trimmed_curves(void)
{
    projcurve_model *m = read_step(
        "#1=CARTESIAN_POINT('',(0.,0.,0.));#2=DIRECTION('',(1.,0.,0.));\n"
        "#3=VECTOR('',#2,2.);#4=LINE('',#1,#3);\n"
        "#5=CARTESIAN_POINT('',(3.,0.,0.));#6=CARTESIAN_POINT('',(1.,0.,0.));\n"
        /* a line trimmed by points against its sense: (3,0,0) to (1,0,0) */
        "#7=TRIMMED_CURVE('',#4,(#5),(#6),.F.,.CARTESIAN.);\n"
        /* the same line, trimmed by a parameter and a point: the parameter
         * (t = 2, the point (4,0,0)) wins over the point (1,0,0) */
        "#8=TRIMMED_CURVE('',#4,(#6,PARAMETER_VALUE(2.)),(#5),.T.,.PARAMETER.);\n"
        /* circles of radius 2 around (1,1,1) in z = 1, x axis first */
        "#10=CARTESIAN_POINT('',(1.,1.,1.));#11=DIRECTION('',(0.,0.,1.));\n"
        "#12=DIRECTION('',(1.,0.,0.));#13=AXIS2_PLACEMENT_3D('',#10,#11,#12);\n"
        "#14=CIRCLE('',#13,2.);#15=CIRCLE('',#13,2.);#16=CIRCLE('',#13,2.);\n"
        "#20=CARTESIAN_POINT('',(1.,3.,1.));#21=CARTESIAN_POINT('',(-1.,1.,1.));\n"
        "#22=CARTESIAN_POINT('',(3.,1.,1.));#23=CARTESIAN_POINT('',(1.,-1.,1.));\n"
        /* 90 to 180 degrees counter-clockwise */
        "#24=TRIMMED_CURVE('',#14,(#20),(#21),.T.,.CARTESIAN.);\n"
        /* 90 down to 0 degrees, clockwise (sense .F.) */
        "#25=TRIMMED_CURVE('',#15,(#20),(#22),.F.,.CARTESIAN.);\n"
        /* 270 up through 0 to 90 degrees: across the branch cut of atan2 */
        "#26=TRIMMED_CURVE('',#16,(#23),(#20),.T.,.CARTESIAN.);\n"
        /* a B-spline trimmed by points only: listed as skipped */
        "#30=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#5),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),"
        ".UNSPECIFIED.);\n"
        "#31=TRIMMED_CURVE('',#30,(#6),(#5),.T.,.CARTESIAN.);");
    if (m == NULL)
        return;
    CHECK(projcurve_model_curve_count(m) == 5);
    CHECK(projcurve_model_skipped_count(m) == 1);
    if (projcurve_model_skipped_count(m) == 1) {
        const char *why = projcurve_model_skipped(m, 0);
        if (strstr(why, "#31") == NULL || strstr(why, "trimmed by points only") == NULL)
            pc_test_fail_at(__FILE__, __LINE__, "skipped: '%s', expected #31 trimmed by points",
                            why);
        ++pc_test_checks;
    }
    if (projcurve_model_curve_count(m) != 5) {
        projcurve_model_destroy(m);
        return;
    }
    double t0, t1, p[3];
    const projcurve_curve *c = projcurve_model_curve(m, 0);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 3, 0, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
    check_point(p, 1, 0, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, 0.5 * (t0 + t1), 0, p));
    check_point(p, 2, 0, 0, TIGHT);
    c = projcurve_model_curve(m, 1);
    CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
    CHECK_OK(projcurve_curve_eval(ctx, c, t0, 0, p));
    check_point(p, 4, 0, 0, TIGHT);
    CHECK_OK(projcurve_curve_eval(ctx, c, t1, 0, p));
    check_point(p, 3, 0, 0, TIGHT);
    const double north[3] = {1, 3, 1}, west[3] = {-1, 1, 1}, east[3] = {3, 1, 1},
                 south[3] = {1, -1, 1};
    check_arc(projcurve_model_curve(m, 2), north, west, PI / 2, PI / 2);
    check_arc(projcurve_model_curve(m, 3), north, east, PI / 2, -PI / 2);
    check_arc(projcurve_model_curve(m, 4), south, north, -PI / 2, PI);
    projcurve_model_destroy(m);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    surface_point_order();
    rational_complex_surface();
    curves();
    trimmed_bspline();
    rational_complex_curve();
    point_trimmed_curves();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_step_entities");
}
