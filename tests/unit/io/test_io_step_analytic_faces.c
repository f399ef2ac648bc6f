/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP faces on analytic surfaces, from small files written here, checked
 * against the exact geometry: a plane z = 0 with the square [-1, 1]^2 as
 * outer loop (2D LINE pcurves) and a circular hole of radius 0.5 (no
 * pcurve: projected), a full cylinder of radius 1 and height 2 bounded by
 * its two circles and its seam (LINE pcurves in the cylinder's (angle,
 * height)), and a unit sphere bounded by a meridian from pole to pole used
 * twice as its seam. On a grid of the face's NURBS domain every point
 * classified IN lies on the analytic surface to 1e-12 and inside the
 * face's region; every point more than PC_MARGIN inside the region is IN,
 * every point more than PC_MARGIN outside (the hole, past the square, the
 * cylinder's ends) is OUT. The margin covers the classification's
 * tolerance near the boundary (the hole is a polyline within the file's
 * precision, 1e-7).
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "projcurve.h"
#include "step_text.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define PC_GRID 120
#define PC_MARGIN 1e-3
#define PC_ON_SURFACE 1e-12

static projcurve_context *ctx;

typedef struct region {
    double (*off)(const double p[3]);    /* distance from the analytic surface */
    double (*inside)(const double p[3]); /* > 0 inside the face, < 0 outside */
} region;

static double plane_off(const double p[3]) { return fabs(p[2]); }
static double plane_inside(const double p[3])
{
    return fmin(fmin(1.0 - fabs(p[0]), 1.0 - fabs(p[1])), hypot(p[0], p[1]) - 0.5);
}
static double cylinder_off(const double p[3]) { return fabs(hypot(p[0], p[1]) - 1.0); }
static double cylinder_inside(const double p[3]) { return fmin(p[2], 2.0 - p[2]); }
static double sphere_off(const double p[3]) { return fabs(hypot(hypot(p[0], p[1]), p[2]) - 1.0); }
static double sphere_inside(const double p[3]) { (void)p; return 1.0; }

static int axis(step_text *t, double z0)
{
    const int o = step_add(t, "CARTESIAN_POINT('',(0.,0.,%.17g))", z0);
    const int z = step_add(t, "DIRECTION('',(0.,0.,1.))"), x = step_add(t, "DIRECTION('',(1.,0.,0.))");
    return step_add(t, "AXIS2_PLACEMENT_3D('',#%d,#%d,#%d)", o, z, x);
}

static int vertex(step_text *t, double x, double y, double z)
{
    return step_add(t, "VERTEX_POINT('',#%d)", step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g,%.17g))", x, y, z));
}

/* A 2D LINE pcurve (u0, v0) + s (du, dv) on surface s. */
static int line_pcurve(step_text *t, int surface, double u0, double v0, double du, double dv,
                       int curve3)
{
    const int p = step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g))", u0, v0);
    const int d = step_add(t, "DIRECTION('',(%.17g,%.17g))", du, dv);
    const int l = step_add(t, "LINE('',#%d,#%d)", p, step_add(t, "VECTOR('',#%d,1.)", d));
    return step_add(t, "PCURVE('',#%d,#%d)", surface,
                    step_add(t, "DEFINITIONAL_REPRESENTATION('',(#%d),#%d)", l, curve3));
}

/* An edge a -> b on z = 0 along a LINE with its 2D LINE pcurve (u = x, v = y). */
static int plane_edge(step_text *t, int plane, const double a[2], const double b[2])
{
    const int pa = step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g,0.))", a[0], a[1]);
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = hypot(dx, dy);
    const int d = step_add(t, "DIRECTION('',(%.17g,%.17g,0.))", dx / len, dy / len);
    const int line = step_add(t, "LINE('',#%d,#%d)", pa, step_add(t, "VECTOR('',#%d,1.)", d));
    const int pc = line_pcurve(t, plane, a[0], a[1], dx / len, dy / len, line);
    const int sc = step_add(t, "SURFACE_CURVE('',#%d,(#%d),.PCURVE_S1.)", line, pc);
    return step_add(t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", vertex(t, a[0], a[1], 0.0),
                    vertex(t, b[0], b[1], 0.0), sc);
}

static projcurve_model *plane_with_hole(void)
{
    step_text t = {.next = 1};
    const int plane = step_add(&t, "PLANE('',#%d)", axis(&t, 0.0));
    const double c[5][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    int oe[4];
    for (int k = 0; k < 4; ++k)
        oe[k] = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", plane_edge(&t, plane, c[k], c[k + 1]));
    const int outer = step_add(&t, "EDGE_LOOP('',(#%d,#%d,#%d,#%d))", oe[0], oe[1], oe[2], oe[3]);
    const int v = vertex(&t, 0.5, 0.0, 0.0);
    const int circle = step_add(&t, "CIRCLE('',#%d,0.5)", axis(&t, 0.0));
    const int hole_edge = step_add(&t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", v, v, circle);
    const int hole = step_add(&t, "EDGE_LOOP('',(#%d))",
                              step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", hole_edge));
    const int b0 = step_add(&t, "FACE_OUTER_BOUND('',#%d,.T.)", outer);
    const int b1 = step_add(&t, "FACE_BOUND('',#%d,.F.)", hole);
    step_add(&t, "ADVANCED_FACE('',(#%d,#%d),#%d,.T.)", b0, b1, plane);
    return step_read(ctx, &t);
}

/* A circle of radius 1 at height z, closed at (1, 0, z), with its pcurve
 * v = z along u on the cylinder. */
static int cylinder_circle(step_text *t, int cylinder, int v, double z)
{
    const int circle = step_add(t, "CIRCLE('',#%d,1.)", axis(t, z));
    const int pc = line_pcurve(t, cylinder, 0.0, z, 1.0, 0.0, circle);
    const int sc = step_add(t, "SURFACE_CURVE('',#%d,(#%d),.PCURVE_S1.)", circle, pc);
    return step_add(t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", v, v, sc);
}

static projcurve_model *full_cylinder(void)
{
    step_text t = {.next = 1};
    const int cyl = step_add(&t, "CYLINDRICAL_SURFACE('',#%d,1.)", axis(&t, 0.0));
    const int v0 = vertex(&t, 1.0, 0.0, 0.0), v1 = vertex(&t, 1.0, 0.0, 2.0);
    const int bottom = cylinder_circle(&t, cyl, v0, 0.0), top = cylinder_circle(&t, cyl, v1, 2.0);
    const int p0 = step_add(&t, "CARTESIAN_POINT('',(1.,0.,0.))");
    const int dz = step_add(&t, "DIRECTION('',(0.,0.,1.))");
    const int line = step_add(&t, "LINE('',#%d,#%d)", p0, step_add(&t, "VECTOR('',#%d,1.)", dz));
    const int pa = line_pcurve(&t, cyl, 2.0 * M_PI, 0.0, 0.0, 1.0, line);
    const int pb = line_pcurve(&t, cyl, 0.0, 0.0, 0.0, 1.0, line);
    const int seam_curve = step_add(&t, "SEAM_CURVE('',#%d,(#%d,#%d),.PCURVE_S1.)", line, pa, pb);
    const int seam = step_add(&t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", v0, v1, seam_curve);
    const int e0 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", bottom);
    const int e1 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", seam);
    const int e2 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.F.)", top);
    const int e3 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.F.)", seam);
    const int loop = step_add(&t, "EDGE_LOOP('',(#%d,#%d,#%d,#%d))", e0, e1, e2, e3);
    step_add(&t, "ADVANCED_FACE('',(#%d),#%d,.T.)", step_add(&t, "FACE_OUTER_BOUND('',#%d,.T.)", loop), cyl);
    return step_read(ctx, &t);
}

/* The meridian u = 0 from the south pole to the north one (a CIRCLE in
 * the plane y = 0 whose angle pi/2 is the north pole), used twice. */
static projcurve_model *sphere_with_poles(void)
{
    step_text t = {.next = 1};
    const int sphere = step_add(&t, "SPHERICAL_SURFACE('',#%d,1.)", axis(&t, 0.0));
    const int s = vertex(&t, 0.0, 0.0, -1.0), n = vertex(&t, 0.0, 0.0, 1.0);
    const int o = step_add(&t, "CARTESIAN_POINT('',(0.,0.,0.))");
    const int ny = step_add(&t, "DIRECTION('',(0.,-1.,0.))"), x = step_add(&t, "DIRECTION('',(1.,0.,0.))");
    const int meridian = step_add(&t, "CIRCLE('',#%d,1.)",
                                  step_add(&t, "AXIS2_PLACEMENT_3D('',#%d,#%d,#%d)", o, ny, x));
    const int pa = line_pcurve(&t, sphere, 2.0 * M_PI, -0.5 * M_PI, 0.0, 1.0, meridian);
    const int pb = line_pcurve(&t, sphere, 0.0, -0.5 * M_PI, 0.0, 1.0, meridian);
    const int seam_curve = step_add(&t, "SEAM_CURVE('',#%d,(#%d,#%d),.PCURVE_S1.)", meridian, pa, pb);
    const int seam = step_add(&t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", s, n, seam_curve);
    const int e0 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", seam);
    const int e1 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.F.)", seam);
    const int loop = step_add(&t, "EDGE_LOOP('',(#%d,#%d))", e0, e1);
    step_add(&t, "ADVANCED_FACE('',(#%d),#%d,.T.)", step_add(&t, "FACE_OUTER_BOUND('',#%d,.T.)", loop), sphere);
    return step_read(ctx, &t);
}

/* Classifies the cell centres of a PC_GRID x PC_GRID grid of the face's
 * surface domain against the region; want_out: points OUT are expected. */
static void check_face(projcurve_model *m, const char *what, const region *r, int want_out)
{
    if (m == NULL)
        return;
    CHECK(projcurve_model_face_count(m) == 1 && projcurve_model_unbuilt_face_count(m) == 0);
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i)
        printf("%s: unbuilt: %s\n", what, projcurve_model_unbuilt_face(m, i));
    const projcurve_face *f = projcurve_model_face(m, 0);
    if (f == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    const projcurve_surface *s = projcurve_face_surface(f);
    double d[4];
    CHECK_OK(projcurve_surface_domain(ctx, s, d));
    size_t in = 0, out = 0, wrong = 0;
    double worst = 0.0;
    for (int i = 0; i < PC_GRID; ++i)
        for (int j = 0; j < PC_GRID; ++j) {
            const double u = d[0] + (d[1] - d[0]) * (i + 0.5) / PC_GRID;
            const double v = d[2] + (d[3] - d[2]) * (j + 0.5) / PC_GRID;
            double p[3];
            projcurve_where w = PROJCURVE_ON;
            CHECK_OK(projcurve_face_classify(ctx, f, u, v, &w));
            CHECK_OK(projcurve_surface_eval(ctx, s, u, v, 0, p));
            const double inside = r->inside(p);
            if (w == PROJCURVE_IN) {
                ++in;
                worst = fmax(worst, r->off(p));
                wrong += inside < -PC_MARGIN;
            } else if (w == PROJCURVE_OUT) {
                ++out;
                wrong += inside > PC_MARGIN;
            }
        }
    printf("%s: %zu IN, %zu OUT, %zu misjudged, IN points off the surface by %.2e at most\n", what,
           in, out, wrong, worst);
    CHECK(in > PC_GRID * PC_GRID / 4);
    CHECK(want_out ? out > 0 : out == 0);
    CHECK(wrong == 0);
    CHECK(worst <= PC_ON_SURFACE);
    projcurve_model_destroy(m);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const region plane = {plane_off, plane_inside}, cylinder = {cylinder_off, cylinder_inside};
    const region sphere = {sphere_off, sphere_inside};
    check_face(plane_with_hole(), "plane with a circular hole", &plane, 1);
    check_face(full_cylinder(), "full cylinder with its seam", &cylinder, 1);
    check_face(sphere_with_poles(), "sphere with its poles", &sphere, 0);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_step_analytic_faces");
}
