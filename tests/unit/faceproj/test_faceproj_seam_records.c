/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Face pieces across their face's seam carry its jumps: the B-rep case
 * cyl_analytic_seam_conical (tests/data/cases-brep), the full cylinder
 * R 10 around z of cylinder_analytic.step, seam at angle 0, seen from the
 * eye (0, 0, 10) on its axis; the curve (radius 5, angles -70 .. 70 deg)
 * crosses angle 0 once. A ray from a point of the axis keeps the angle of
 * P(t) (closed form), so the one face piece over the whole curve crosses
 * the seam where atan2(Py, Px) = 0 (located by bisection on P), and its
 * point is the ray's hit of radius 10. The piece must carry one seam
 * record there with |du| the period of the surface's u, and its compact
 * pcurve plus the jumps at or before t (docs/seams.md) must lie in the
 * domain and on the analytic projection within eps_D (S of it compared
 * with the hit of the ray through it: the curve's point at its angle).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#define SAMPLES 200

static double angle_at(const projcurve_curve *c, double t)
{
    double p[3];
    CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
    return atan2(p[1], p[0]);
}

/* t where the curve's angle around z passes 0 (it runs from -70 to 70
 * degrees, increasing): bisection to rounding. */
static double seam_t(const projcurve_curve *c, double t0, double t1)
{
    double a = t0, b = t1;
    const int up = angle_at(c, t1) > angle_at(c, t0);
    for (int k = 0; k < 200 && b - a > 0.0; ++k) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b)
            break;
        if ((angle_at(c, m) < 0.0) == up)
            a = m;
        else
            b = m;
    }
    return 0.5 * (a + b);
}

/* t in [t0, t1] where the curve's angle around z is a (increasing along
 * the curve): bisection to rounding. */
static double t_of_angle(const projcurve_curve *c, double t0, double t1, double a)
{
    double lo = t0, hi = t1;
    for (int k = 0; k < 200; ++k) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi)
            break;
        if (angle_at(c, m) < a)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

/* The hit of radius 10 on the ray from the eye (0, 0, 10) through P(t). */
static void analytic_hit(const projcurve_curve *c, double t, double x[3])
{
    double p[3];
    CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
    const double d[3] = {p[0], p[1], p[2] - 10.0};
    const double lambda = 10.0 / hypot(d[0], d[1]);
    x[0] = lambda * d[0];
    x[1] = lambda * d[1];
    x[2] = 10.0 + lambda * d[2];
}

int main(void)
{
    projcurve_model *model = NULL, *curves = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path("cases-brep/cylinder_analytic.step"),
                                       &model));
    CHECK_OK(projcurve_model_read_file(
        NULL, pc_test_data_path("cases-brep/cyl_analytic_seam_conical.curves.igs"), &curves));
    if (model == NULL || curves == NULL || projcurve_model_shape_count(model) == 0 ||
        projcurve_model_curve_count(curves) == 0) {
        CHECK(0);
        projcurve_model_destroy(model);
        projcurve_model_destroy(curves);
        return pc_test_finish("test_faceproj_seam_records");
    }
    const projcurve_shape *shape = projcurve_model_shape(model, 0);
    const projcurve_curve *c = projcurve_model_curve(curves, 0);
    const double eye[3] = {0.0, 0.0, 10.0};
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    const double eps_d = 1e-3; /* the case's tol_dist */
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c, PROJCURVE_PROJECT_CONICAL, eye, o, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    size_t n_pieces = 0;
    CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, &n_pieces, NULL, NULL));
    size_t checked = 0;
    for (size_t j = 0; j < n_pieces; ++j) {
        size_t fi = 0, b = 0, n_seams = 0;
        const projcurve_result *fr = NULL;
        double tr[2];
        CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, j, &fi, &fr, &b, tr, NULL, NULL));
        const projcurve_surface *s = projcurve_face_surface(projcurve_shape_face(shape, fi));
        double dom[4];
        CHECK_OK(projcurve_surface_domain(NULL, s, dom));
        const double lo = fmin(tr[0], tr[1]), hi = fmax(tr[0], tr[1]);
        const double ts = seam_t(c, lo, hi);
        CHECK_OK(projcurve_result_branch_seam_count(NULL, fr, b, &n_seams));
        /* the piece covers the seam's t: one jump there */
        const int across = ts > lo && ts < hi;
        if (!across)
            continue;
        CHECK(n_seams == 1);
        printf("piece %zu: t [%.6f, %.6f], %zu seam record(s), seam expected at t %.12f\n", j, lo,
               hi, n_seams, ts);
        if (n_seams != 1)
            continue;
        double tk = 0.0, du = 0.0, dv = 0.0;
        CHECK_OK(projcurve_result_branch_seam(NULL, fr, b, 0, &tk, &du, &dv));
        /* the tracers place the seam to their resolution (~1e-10 of the
         * domain); 1e-8 of it is far below a step */
        CHECK_NEAR(tk, ts, 1e-8 * (hi - lo));
        CHECK_NEAR(fabs(du), dom[1] - dom[0], 1e-12 * (dom[1] - dom[0]));
        /* each side placed the seam to the tracer's resolution */
        CHECK_NEAR(dv, 0.0, 1e-9 * (dom[3] - dom[2]));
        int fitted = 0;
        double pe = 0, ce = 0;
        CHECK_OK(projcurve_result_branch_compact_info(NULL, fr, b, &fitted, &pe, &ce));
        printf("compact: fitted %d, pcurve error %.3g, curve error %.3g\n", fitted, pe, ce);
        projcurve_curve *q = NULL;
        CHECK_OK(projcurve_result_branch_compact_pcurve(NULL, fr, b, &q));
        for (int i = 0; q != NULL && i <= SAMPLES; ++i) {
            const double t = lo + (hi - lo) * i / SAMPLES;
            double uv[3], x[3], h[3];
            CHECK_OK(projcurve_curve_eval(NULL, q, t, 0, uv));
            if (t >= tk)
                uv[0] += du;
            /* in the domain (to the rounding of the fit's end poles) */
            const double slack = 1e-9 * (dom[1] - dom[0]);
            CHECK(uv[0] >= dom[0] - slack && uv[0] <= dom[1] + slack);
            CHECK_OK(projcurve_surface_eval(NULL, s, fmin(dom[1], fmax(dom[0], uv[0])), uv[1], 0,
                                            x));
            /* the ray through x meets the curve where its angle is x's
             * (the eye is on the axis): the projection's point of that
             * ray, compared in space (a joined pcurve need not follow t) */
            analytic_hit(c, t_of_angle(c, lo, hi, atan2(x[1], x[0])), h);
            const double off = sqrt((x[0] - h[0]) * (x[0] - h[0]) + (x[1] - h[1]) * (x[1] - h[1]) +
                                    (x[2] - h[2]) * (x[2] - h[2]));
            /* the compact pcurve is fitted within eps_D (its check, 0.8
             * eps_D, between samples a little more) */
            if (!(off <= eps_d))
                pc_test_fail_at(__FILE__, __LINE__, "t %.9f: S(q + jumps) %.3g from the hit", t,
                                off);
            ++pc_test_checks;
        }
        projcurve_curve_destroy(q);
        ++checked;
    }
    /* the curve crosses the seam once: some piece covers it */
    CHECK(checked == 1);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(o);
    projcurve_model_destroy(curves);
    projcurve_model_destroy(model);
    return pc_test_finish("test_faceproj_seam_records");
}
