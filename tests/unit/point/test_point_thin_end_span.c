/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Closest points and foot points on a surface whose v domain starts with a
 * knot span of rounding width: the quarter-cylinder face 5 of hammer.iges
 * (degree 1 x 2, rational, v knots -1.2e-15 (x3), 0 (x2), ...; the first
 * three control rows equal, so over that span S is its edge curve and
 * Sv = 0). Points of S a little inside the edge (v = 1e-7 .. 0.05) must
 * be their own closest point and a foot point; the minimiser, clamped to
 * the domain into that span, used to stop there, 1.4 model units away
 * (which made projcurve-bench shape report hammer circle dir 1.44 off the
 * faces). Points off S along its normal are checked against the
 * brute-force oracle (tests/support/closest_oracle.h).
 */
#include <math.h>

#include "check.h"
#include "closest_oracle.h"
#include "projcurve.h"

static const double ctrl[14 * 3] = {
    -4542.3142470000003, 19308.24109,        -8328.9677389999997,
    -5025.9648319999978, 19308.24109,        13645.575090000002,
    -4542.3142470000003, 19308.24109,        -8328.9677389999997,
    -5025.9648319999988, 19308.24109,        13645.575090000002,
    -4542.3142470000003, 19308.24109,        -8328.9677389999997,
    -5025.9648319999997, 19308.24109,        13645.57509,
    -4542.3142470000003, 17940.074990000001, -8328.9677389999997,
    -5025.9648319999997, 18423.725569999999, 13645.575090000002,
    -5910.4803449999999, 17940.074990000001, -8328.9677389999997,
    -5910.4803449999999, 18423.725569999999, 13645.57509,
    -7278.6464429999987, 17940.074990000001, -8328.9677389999997,
    -6794.9958580000011, 18423.725569999999, 13645.575090000002,
    -7278.6464429999996, 19308.24109,        -8328.9677389999997,
    -6794.9958580000002, 19308.24109,        13645.57509};
static const double weights[14] = {0.99999999999999956, 0.99999999999999956, 0.99999999999999978,
                                   0.99999999999999978, 1, 1, 0.70710678100000002,
                                   0.70710678100000002, 1, 1, 0.70710678100000002,
                                   0.70710678100000002, 1, 1};
static const double knots_u[4] = {-10.989932327, -10.989932327, 10.989932327, 10.989932327};
static const double knots_v[10] = {-1.2339906939999999e-15, -1.2339906939999999e-15,
                                   -1.2339906939999999e-15, 0, 0, 1.769252, 1.769252,
                                   3.5385040000000001, 3.5385040000000001, 3.5385040000000001};

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

int main(void)
{
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 2, 2, 7, ctrl, weights, knots_u, knots_v, &s));
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    const double size = dist3(box, box + 3);
    /* a point of S is its own closest point: the corrector's 1e-12 of the
     * size would do, 1e-12 leaves room for the rounding of S itself */
    const double on_tol = 1e-12 * size;
    const double us[3] = {-9.0, 0.3, 7.417753445};
    const double vs[6] = {1e-7, 1e-4, 0.0014, 0.00186, 0.01, 0.05};
    size_t worst_fails = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 6; ++j) {
            double p[3], uv[2], q[3], d = INFINITY;
            CHECK_OK(projcurve_surface_eval(NULL, s, us[i], vs[j], 0, p));
            CHECK_OK(projcurve_surface_closest_point(NULL, s, p, uv, q, &d));
            if (!(d <= on_tol) && worst_fails++ < 5)
                pc_test_fail_at(__FILE__, __LINE__,
                                "S(%.9g, %.9g): closest at (%.9g, %.3g), %.3g away", us[i],
                                vs[j], uv[0], uv[1], d);
            ++pc_test_checks;
            double feet[2 * 8];
            size_t n = 0;
            CHECK_OK(projcurve_surface_foot_points(NULL, s, p, 8, feet, &n));
            double nearest = INFINITY;
            for (size_t k = 0; k < n && k < 8; ++k) {
                double f[3];
                CHECK_OK(projcurve_surface_eval(NULL, s, feet[2 * k], feet[2 * k + 1], 0, f));
                nearest = fmin(nearest, dist3(f, p));
            }
            /* the foot Newton accepts at an angle of 1e-10 from the
             * normal: 1e-11 of the size here */
            if (!(nearest <= 1e-11 * size))
                pc_test_fail_at(__FILE__, __LINE__, "S(%.9g, %.9g): %zu foot points, nearest %.3g",
                                us[i], vs[j], n, nearest);
            ++pc_test_checks;
            /* off S along its normal, outwards and inwards (radius ~1400):
             * the brute-force oracle on a 120 x 120 grid */
            double d1[9];
            CHECK_OK(projcurve_surface_eval(NULL, s, us[i], vs[j], 1, d1));
            const double *su = d1 + 3, *sv = d1 + 6;
            double nrm[3] = {su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2],
                             su[0] * sv[1] - su[1] * sv[0]};
            const double nn = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            for (int side = -1; side <= 1; side += 2) {
                double x[3], ouv[2];
                for (int k = 0; k < 3; ++k)
                    x[k] = p[k] + side * 5.0 * nrm[k] / nn;
                CHECK_OK(projcurve_surface_closest_point(NULL, s, x, uv, q, &d));
                const double ref = pc_oracle_surface_closest(s, x, 120, ouv);
                /* both polish to rounding of |S - x| */
                if (!(fabs(d - ref) <= 1e-10 * size))
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "S(%.9g, %.9g) %+d * 5 n: library %.17g at (%.9g, %.3g), "
                                    "oracle %.17g at (%.9g, %.3g)",
                                    us[i], vs[j], side, d, uv[0], uv[1], ref, ouv[0], ouv[1]);
                ++pc_test_checks;
            }
        }
    projcurve_surface_destroy(s);
    return pc_test_finish("test_point_thin_end_span");
}
