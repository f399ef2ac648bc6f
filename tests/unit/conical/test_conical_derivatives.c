/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The conical projector's equations: q' and q'' (with the t-derivatives
 * of the ray direction, docs/conical.md) against central finite
 * differences of the exact projection curve, corrected by Newton at
 * t - h, t, t + h; the residual and the ray direction at the points; the
 * corrector's refusal at the eye.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "conical/conical.h"
#include "shapes.h"

/* The corrector's tolerance (relative): tight, so that the corrected
 * points carry ~1e-14 of error into the differences. */
#define NEWTON_TOL 1e-14
/* Central differences err by ~h^2 |q'''| / 6 (q') and h^2 |q''''| / 12
 * (q''), plus ~1e-14 / h and ~1e-14 / h^2 from the corrected points:
 * with h = 3e-5 about 1e-7 and 1e-5 relative to the derivatives' size
 * here; a wrong term (mu' P' dropped, say) moves q'' by O(1). The t
 * checked keep 0.0185 away from the circle's knots (q'' jumps there). */
#define FD_H 3e-5
#define TOL_D1 1e-6
#define TOL_D2 1e-4

static double rel(double a, double b, double scale)
{
    return fabs(a - b) / fmax(1.0, scale);
}

/* The point of the branch through the ray hit `which` at t, and its
 * neighbours at t -+ h corrected from the Taylor guess. Returns the
 * number of parameters checked (0 when the ray has no such hit). */
static int check_at(const projcurve_surface *s, const pc_projector *proj, double t, size_t which)
{
    pc_vec3 p, dir;
    CHECK(pc_conical_ray(proj, t, &p, &dir));
    double hits[3 * 8];
    size_t n = 0;
    const double origin[3] = {p.x, p.y, p.z}, d[3] = {dir.x, dir.y, dir.z};
    CHECK_OK(projcurve_surface_intersect_line(NULL, s, origin, d, 1, 8, hits, NULL, &n));
    if (n <= which)
        return 0;
    double uv[2] = {hits[3 * which], hits[3 * which + 1]};
    CHECK(proj->correct(proj, t, uv, NULL));
    pc_proj_point q;
    CHECK(proj->derivatives(proj, t, uv[0], uv[1], &q));
    CHECK(proj->residual(proj, t, uv[0], uv[1]) <= 1e-12 * proj->model_size);
    /* the ray direction the tracer is given is (P - E) / |P - E| */
    const pc_vec3 rd = proj->ray_dir(proj, &q);
    CHECK(vec3_dist(rd, dir) <= 1e-15);
    double lo[2], hi[2];
    for (int k = 0; k < 2; ++k) {
        const double h = k == 0 ? -FD_H : FD_H;
        double *x = k == 0 ? lo : hi;
        x[0] = uv[0] + h * q.du + 0.5 * h * h * q.ddu;
        x[1] = uv[1] + h * q.dv + 0.5 * h * h * q.ddv;
        CHECK(proj->correct(proj, t + h, x, NULL));
    }
    const double fd1[2] = {(hi[0] - lo[0]) / (2.0 * FD_H), (hi[1] - lo[1]) / (2.0 * FD_H)};
    const double fd2[2] = {(hi[0] - 2.0 * uv[0] + lo[0]) / (FD_H * FD_H),
                           (hi[1] - 2.0 * uv[1] + lo[1]) / (FD_H * FD_H)};
    const double s1 = fabs(q.du) + fabs(q.dv), s2 = fabs(q.ddu) + fabs(q.ddv);
    const double e1 = fmax(rel(q.du, fd1[0], s1), rel(q.dv, fd1[1], s1));
    const double e2 = fmax(rel(q.ddu, fd2[0], s2), rel(q.ddv, fd2[1], s2));
    if (!(e1 <= TOL_D1) || !(e2 <= TOL_D2))
        printf("  t %.3f hit %zu: q' (%.9g, %.9g) fd (%.9g, %.9g); q'' (%.9g, %.9g) fd "
               "(%.9g, %.9g)\n",
               t, which, q.du, q.dv, fd1[0], fd1[1], q.ddu, q.ddv, fd2[0], fd2[1]);
    CHECK(e1 <= TOL_D1);
    CHECK(e2 <= TOL_D2);
    return 1;
}

/* Checks q', q'' along the curve on every hit; returns the points checked. */
static int check_surface(const char *name, const pc_shape_surface *shape,
                         const pc_shape_curve *curve_shape, const double eye[3])
{
    projcurve_surface *s = pc_shape_surface_create(shape);
    projcurve_curve *c = pc_shape_curve_create(curve_shape);
    CHECK(s != NULL && c != NULL);
    int checked = 0;
    if (s != NULL && c != NULL) {
        pc_projector proj;
        pc_conical_data data;
        pc_conical_cache cache;
        pc_conical_init(&proj, &data, &cache, s, c, vec3_load(eye), NEWTON_TOL, 50);
        for (int k = 1; k < 20; ++k)
            for (size_t which = 0; which < 2; ++which)
                checked += check_at(s, &proj, (k + 0.37) / 20.0, which);
    }
    printf("%s: q', q'' checked at %d points\n", name, checked);
    projcurve_surface_destroy(s);
    projcurve_curve_destroy(c);
    return checked;
}

/* The corrector and the derivatives fail where P(t) is the eye. */
static void test_eye_point(void)
{
    pc_shape_surface plane = pc_shape_plane(3, 3, 1, 1);
    const double centre[3] = {0.0, 0.0, 1.0};
    pc_shape_curve circle = pc_shape_circle(centre, 0.5);
    projcurve_surface *s = pc_shape_surface_create(&plane);
    projcurve_curve *c = pc_shape_curve_create(&circle);
    double p[3];
    projcurve_curve_eval(NULL, c, 0.0, 0, p);
    pc_projector proj;
    pc_conical_data data;
    pc_conical_cache cache;
    pc_conical_init(&proj, &data, &cache, s, c, vec3_load(p), 1e-12, 30);
    double uv[2] = {0.5, 0.5};
    pc_proj_point q;
    pc_vec3 dir;
    CHECK(!proj.correct(&proj, 0.0, uv, NULL));
    CHECK(!proj.derivatives(&proj, 0.0, 0.5, 0.5, &q));
    CHECK(!pc_conical_ray(&proj, 0.0, NULL, &dir));
    CHECK(pc_conical_ray(&proj, 0.25, NULL, &dir)); /* elsewhere it is defined */
    projcurve_surface_destroy(s);
    projcurve_curve_destroy(c);
    pc_shape_surface_free(&plane);
    pc_shape_curve_free(&circle);
}

int main(void)
{
    /* a circle of radius 0.25 at z = 1 over the middle of the bumpy
     * graph, the eye above and off its axis: the ray direction turns all
     * the way round, P'' and mu' are both far from 0 */
    const double centre[3] = {0.45, 0.55, 1.0}, eye[3] = {0.6, 0.4, 6.0};
    pc_shape_curve circle = pc_shape_circle(centre, 0.25);
    pc_shape_surface bumpy = pc_shape_bumpy(7, 4, 4, 0.15, 0);
    pc_shape_surface rational = pc_shape_bumpy(11, 3, 3, 0.15, 1);
    CHECK(check_surface("bumpy bicubic", &bumpy, &circle, eye) >= 19);
    CHECK(check_surface("bumpy rational", &rational, &circle, eye) >= 19);
    /* a sphere seen from outside: front and back hits */
    const double origin[3] = {0.0, 0.0, 0.0}, sphere_centre[3] = {0.0, 0.1, 2.0};
    const double sphere_eye[3] = {0.1, 0.0, 4.0};
    pc_shape_surface sphere = pc_shape_sphere(origin, 1.0);
    pc_shape_curve ring = pc_shape_circle(sphere_centre, 0.3);
    CHECK(check_surface("sphere", &sphere, &ring, sphere_eye) >= 2 * 19);
    test_eye_point();
    pc_shape_surface_free(&bumpy);
    pc_shape_surface_free(&rational);
    pc_shape_surface_free(&sphere);
    pc_shape_curve_free(&circle);
    pc_shape_curve_free(&ring);
    return pc_test_finish("test_conical_derivatives");
}
