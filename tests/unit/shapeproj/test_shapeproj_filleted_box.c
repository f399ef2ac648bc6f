/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A filleted box seen obliquely: an open shell (STEP text, edges shared,
 * pcurves left to the reader) of a box's profile swept along y: the side
 * x = -A, a quarter-cylinder fillet of radius R, the top z = H, a fillet,
 * the side x = A, for y in [0, L]. A line above it across x projected
 * along Dir = (0.6, 0.2, -1) with the nearest hit only: one connected
 * curve of three face pieces, left side -> left fillet -> top, chained
 * across the two shared edges with no gap. Oracle: the profile does not
 * depend on y, so each ray's first hit is found analytically in the
 * (x, z) plane (lines and a circle); every traced point must be that hit,
 * and every sampled t with a hit must be covered by the pieces.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"
#include "step_text.h"

#define A 2.0
#define H 2.0
#define R 0.5
#define L 4.0
#define MAX_POINTS 20000

static double points[3 * MAX_POINTS];

static int vertex(step_text *t, double x, double y, double z)
{
    return step_add(t, "VERTEX_POINT('',#%d)",
                    step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g,%.17g))", x, y, z));
}

static int dir3(step_text *t, double x, double y, double z)
{
    return step_add(t, "DIRECTION('',(%.17g,%.17g,%.17g))", x, y, z);
}

static int placement(step_text *t, double x, double y, double z, int axis, int ref)
{
    const int o = step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g,%.17g))", x, y, z);
    return step_add(t, "AXIS2_PLACEMENT_3D('',#%d,#%d,#%d)", o, axis, ref);
}

/* A straight edge from vertex va at a to vb at b. */
static int line_edge(step_text *t, int va, int vb, const double a[3], const double b[3])
{
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const int p = step_add(t, "CARTESIAN_POINT('',(%.17g,%.17g,%.17g))", a[0], a[1], a[2]);
    const int v = step_add(t, "VECTOR('',#%d,1.)", dir3(t, d[0] / n, d[1] / n, d[2] / n));
    const int line = step_add(t, "LINE('',#%d,#%d)", p, v);
    return step_add(t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", va, vb, line);
}

/* The profile's corners in (x, z): side, fillet, top, fillet, side. */
static const double corner[6][2] = {{-A, 0}, {-A, H - R}, {-A + R, H},
                                    {A - R, H}, {A, H - R}, {A, 0}};

static projcurve_model *filleted_box(projcurve_context *ctx)
{
    static step_text t;
    memset(&t, 0, sizeof t);
    t.next = 1;
    int v[2][6], along[6], across[2][5];
    double p[2][6][3];
    for (int e = 0; e < 2; ++e)
        for (int i = 0; i < 6; ++i) {
            p[e][i][0] = corner[i][0];
            p[e][i][1] = e ? L : 0.0;
            p[e][i][2] = corner[i][1];
            v[e][i] = vertex(&t, p[e][i][0], p[e][i][1], p[e][i][2]);
        }
    for (int i = 0; i < 6; ++i)
        along[i] = line_edge(&t, v[0][i], v[1][i], p[0][i], p[1][i]);
    /* the fillets: axis -y, reference +x, so that a point is
     * centre + R (cos th, 0, sin th) and th runs from the top down to the
     * side on the left (90 -> 180 deg) and from the side up (0 -> 90) on
     * the right; their edges run with th */
    const int ny = dir3(&t, 0, -1, 0), px = dir3(&t, 1, 0, 0);
    int fillet_surface[2];
    for (int s = 0; s < 2; ++s) {
        const double cx = s ? A - R : -A + R;
        fillet_surface[s] = step_add(&t, "CYLINDRICAL_SURFACE('',#%d,%.17g)",
                                     placement(&t, cx, 0.0, H - R, ny, px), R);
    }
    for (int e = 0; e < 2; ++e)
        for (int i = 0; i < 5; ++i) {
            if (i == 1 || i == 3) {
                const double cx = i == 1 ? -A + R : A - R;
                const int circle = step_add(&t, "CIRCLE('',#%d,%.17g)",
                                            placement(&t, cx, e ? L : 0.0, H - R, ny, px), R);
                /* left: from the top corner (2) to the side (1); right:
                 * from the side (4) to the top (3) */
                const int from = i == 1 ? v[e][2] : v[e][4], to = i == 1 ? v[e][1] : v[e][3];
                across[e][i] = step_add(&t, "EDGE_CURVE('',#%d,#%d,#%d,.T.)", from, to, circle);
            } else {
                across[e][i] = line_edge(&t, v[e][i], v[e][i + 1], p[e][i], p[e][i + 1]);
            }
        }
    int faces[5];
    for (int i = 0; i < 5; ++i) {
        /* corner i at y = 0 -> corner i+1 -> up to y = L -> back -> down */
        const char *arc_sense = (i == 1 || i == 3) ? ".F." : ".T.";
        const int e0 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,%s)", across[0][i], arc_sense);
        const int e1 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.T.)", along[i + 1]);
        const int e2 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,%s)", across[1][i],
                                (i == 1 || i == 3) ? ".T." : ".F.");
        const int e3 = step_add(&t, "ORIENTED_EDGE('',*,*,#%d,.F.)", along[i]);
        const int loop = step_add(&t, "EDGE_LOOP('',(#%d,#%d,#%d,#%d))", e0, e1, e2, e3);
        int surface;
        if (i == 1 || i == 3) {
            surface = fillet_surface[i == 3];
        } else if (i == 2) {
            surface = step_add(&t, "PLANE('',#%d)",
                               placement(&t, 0, 0, H, dir3(&t, 0, 0, 1), px));
        } else {
            const double x = i == 0 ? -A : A;
            surface = step_add(&t, "PLANE('',#%d)",
                               placement(&t, x, 0, 0, dir3(&t, i == 0 ? -1 : 1, 0, 0),
                                         dir3(&t, 0, 1, 0)));
        }
        faces[i] = step_add(&t, "ADVANCED_FACE('',(#%d),#%d,.T.)",
                            step_add(&t, "FACE_OUTER_BOUND('',#%d,.T.)", loop), surface);
    }
    const int shell = step_add(&t, "OPEN_SHELL('',(#%d,#%d,#%d,#%d,#%d))", faces[0], faces[1],
                               faces[2], faces[3], faces[4]);
    step_add(&t, "SHELL_BASED_SURFACE_MODEL('',(#%d))", shell);
    return step_read(ctx, &t);
}

/* The first lambda > 0 where the ray (x, z) + lambda (dx, dz) meets the
 * profile, and the profile part (0..4) it meets; -1 for none. */
static int first_hit(double x, double z, double dx, double dz, double *lambda)
{
    int part = -1;
    *lambda = INFINITY;
    for (int i = 0; i < 5; ++i) {
        if (i == 1 || i == 3) {
            const double cx = i == 1 ? -A + R : A - R, cz = H - R;
            const double ox = x - cx, oz = z - cz;
            const double a = dx * dx + dz * dz, b = 2 * (ox * dx + oz * dz),
                         c = ox * ox + oz * oz - R * R;
            const double disc = b * b - 4 * a * c;
            if (disc < 0)
                continue;
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                const double l = (-b + sgn * sqrt(disc)) / (2 * a);
                const double hx = ox + l * dx, hz = oz + l * dz;
                /* the quarter: left x <= cx, z >= cz; right x >= cx */
                const int on = hz >= -1e-12 && (i == 1 ? hx <= 1e-12 : hx >= -1e-12);
                if (l > 0 && on && l < *lambda) {
                    *lambda = l;
                    part = i;
                }
            }
        } else {
            const double *a = corner[i], *b = corner[i + 1];
            const double ex = b[0] - a[0], ez = b[1] - a[1];
            const double den = dx * ez - dz * ex;
            if (den == 0)
                continue;
            const double l = ((a[0] - x) * ez - (a[1] - z) * ex) / den;
            const double s = ((a[0] - x) * dz - (a[1] - z) * dx) / den;
            if (l > 0 && s >= 0 && s <= 1 && l < *lambda) {
                *lambda = l;
                part = i;
            }
        }
    }
    return part;
}

int main(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_model *m = filleted_box(ctx);
    if (m == NULL || projcurve_model_shape_count(m) != 1) {
        CHECK(m != NULL && projcurve_model_shape_count(m) == 1);
        projcurve_model_destroy(m);
        projcurve_context_destroy(ctx);
        return pc_test_finish("test_shapeproj_filleted_box");
    }
    const projcurve_shape *shape = projcurve_model_shape(m, 0);
    CHECK(projcurve_shape_face_count(shape) == 5);
    CHECK(projcurve_model_unbuilt_face_count(m) == 0);
    /* x0 from -4.3 to 0 at z = H + 2: the rays meet the left side (x0 up to
     * -3.5), the left fillet, then the top (from x0 = -2.7) */
    const double y = L / 2, z = H + 2;
    const double ctrl[6] = {-4.3, y, z, 0.0, y, z}, knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, ctrl, NULL, knots, &c));
    const double dir[3] = {0.6, 0.2, -1.0};
    projcurve_options *opts = NULL;
    CHECK_OK(projcurve_options_create(ctx, &opts));
    CHECK_OK(projcurve_options_set_int(ctx, opts, PROJCURVE_OPT_HITS, PROJCURVE_HITS_NEAREST));
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(ctx, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, opts,
                                     &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    CHECK(projcurve_shape_result_open_end_count(sr) == 0);
    size_t np = 0;
    CHECK_OK(projcurve_shape_result_curve_info(ctx, sr, 0, &np, NULL, NULL));
    CHECK(np == 3);
    /* the size is ~6; traced points sit within the corrector's 1e-12 of
     * it on the ray: 1e-9 is far above that, far below a wrong hit */
    const double tol = 1e-9 * 6.0;
    double covered[2] = {INFINITY, -INFINITY};
    for (size_t j = 0; j < np; ++j) {
        size_t face = 9, b = 0;
        const projcurve_result *r = NULL;
        double tr[2];
        CHECK_OK(projcurve_shape_result_piece(ctx, sr, 0, j, &face, &r, &b, tr, NULL, NULL));
        covered[0] = fmin(covered[0], tr[0]);
        covered[1] = fmax(covered[1], tr[1]);
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_points(ctx, r, b, MAX_POINTS, points, &n));
        const projcurve_face *f = projcurve_shape_face(shape, face);
        size_t bad = 0;
        int part_seen = -1;
        for (size_t i = 0; i < n && i < MAX_POINTS; ++i) {
            double p[3], s[3], lambda;
            CHECK_OK(projcurve_curve_eval(ctx, c, points[3 * i], 0, p));
            CHECK_OK(projcurve_surface_eval(ctx, projcurve_face_surface(f), points[3 * i + 1],
                                            points[3 * i + 2], 0, s));
            const int part = first_hit(p[0], p[2], dir[0], dir[2], &lambda);
            const double want[3] = {p[0] + lambda * dir[0], p[1] + lambda * dir[1],
                                    p[2] + lambda * dir[2]};
            const double err = fabs(s[0] - want[0]) + fabs(s[1] - want[1]) + fabs(s[2] - want[2]);
            if (part < 0 || err > tol) {
                if (bad++ < 3)
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "piece %zu point %zu: (%g, %g, %g), first hit part %d at "
                                    "(%g, %g, %g)",
                                    j, i, s[0], s[1], s[2], part, want[0], want[1], want[2]);
            }
        }
        /* the part hit at the middle of the piece (a piece on a plane may
         * have no traced point inside: a line's image is straight) */
        double pm[3], lm;
        CHECK_OK(projcurve_curve_eval(ctx, c, 0.5 * (tr[0] + tr[1]), 0, pm));
        part_seen = first_hit(pm[0], pm[2], dir[0], dir[2], &lm);
        /* the pieces come side, fillet, top */
        CHECK(part_seen == (int)j);
    }
    /* every t whose ray hits the profile is covered by the pieces */
    for (int k = 0; k <= 200; ++k) {
        const double t = k / 200.0;
        double p[3], lambda;
        CHECK_OK(projcurve_curve_eval(ctx, c, t, 0, p));
        if (first_hit(p[0], p[2], dir[0], dir[2], &lambda) >= 0 && !(t >= covered[0] - 1e-12 &&
                                                                    t <= covered[1] + 1e-12))
            pc_test_fail_at(__FILE__, __LINE__, "t %g hits the box, not covered [%g, %g]", t,
                            covered[0], covered[1]);
    }
    printf("filleted box: %zu face pieces over t [%g, %g]\n", np, covered[0], covered[1]);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(opts);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_shapeproj_filleted_box");
}
