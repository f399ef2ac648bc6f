/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Trim angles of a STEP TRIMMED_CURVE over a CIRCLE: many turns reduce to
 * the arc they name, absurd or non-finite values are refused with
 * PROJCURVE_ERR_PARSE naming the entity. The reader used to add 2 pi until
 * the end angle passed the start: 1e10 took 10 s and 1e300 never returned
 * (a1 + 2 pi == a1). Expected points are analytic (unit circle in z = 0).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "projcurve.h"

#define PI 3.14159265358979323846
/* Angles up to ~30 rad carry a rounding of a few ulp of 30 (~1e-14). */
#define TIGHT 1e-13
/* Ends the program if a read does not return at all (a correct read of
 * these few lines takes microseconds). */
#define HANG_GUARD_SECONDS 60

static projcurve_context *ctx;

static projcurve_status read_arc(const char *from, const char *to, const char *sense,
                                 projcurve_model **m)
{
    char text[2048];
    snprintf(text, sizeof text,
             "ISO-10303-21;\nHEADER;\nFILE_NAME('x','',(''),(''),'','','');\nENDSEC;\nDATA;\n"
             "#1=CARTESIAN_POINT('',(0.,0.,0.));#2=DIRECTION('',(0.,0.,1.));\n"
             "#3=DIRECTION('',(1.,0.,0.));#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);\n"
             "#5=CIRCLE('',#4,1.);\n"
             "#6=TRIMMED_CURVE('',#5,(PARAMETER_VALUE(%s)),(PARAMETER_VALUE(%s)),%s,"
             ".PARAMETER.);\nENDSEC;\nEND-ISO-10303-21;\n",
             from, to, sense);
    *m = NULL;
    return projcurve_model_read_memory(ctx, text, strlen(text), m);
}

static void expect_refused(const char *from, const char *to)
{
    projcurve_model *m = NULL;
    const projcurve_status st = read_arc(from, to, ".T.", &m);
    CHECK(st == PROJCURVE_ERR_PARSE);
    CHECK(m == NULL);
    if (st != PROJCURVE_OK)
        CHECK(strstr(projcurve_context_message(ctx), "#6") != NULL);
    projcurve_model_destroy(m);
}

/* The arc's ends lie at the angles a0 and a1 (a1 < a0: clockwise); points between lie on the
 * circle within the sweep (the rational parametrisation is not linear in
 * the angle, so only the ends have a closed-form parameter). */
static void expect_arc(const char *from, const char *to, const char *sense, double a0, double a1)
{
    projcurve_model *m = NULL;
    CHECK_OK(read_arc(from, to, sense, &m));
    if (m == NULL)
        return;
    CHECK(projcurve_model_curve_count(m) == 1);
    if (projcurve_model_curve_count(m) == 1) {
        const projcurve_curve *c = projcurve_model_curve(m, 0);
        double t0, t1, p[3];
        CHECK_OK(projcurve_curve_domain(ctx, c, &t0, &t1));
        for (int i = 0; i <= 8; ++i) {
            CHECK_OK(projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * i / 8.0, 0, p));
            CHECK_NEAR(hypot(p[0], p[1]), 1.0, TIGHT);
            CHECK_NEAR(p[2], 0.0, TIGHT);
            const double dir = a1 > a0 ? 1.0 : -1.0;
            double along = fmod(dir * (atan2(p[1], p[0]) - a0), 2.0 * PI);
            if (along < -TIGHT)
                along += 2.0 * PI;
            if (i == 0 || i == 8) {
                CHECK_NEAR(p[0], cos(i == 0 ? a0 : a1), TIGHT);
                CHECK_NEAR(p[1], sin(i == 0 ? a0 : a1), TIGHT);
            } else {
                CHECK(along > 0.0 && along < fabs(a1 - a0));
            }
        }
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    alarm(HANG_GUARD_SECONDS);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    /* Several turns apart: the arc is the difference modulo 2 pi. */
    char from[64], to[64];
    snprintf(from, sizeof from, "%.17g", 0.25);
    snprintf(to, sizeof to, "%.17g", 0.75 + 8.0 * PI);
    expect_arc(from, to, ".T.", 0.25, 0.75);
    snprintf(to, sizeof to, "%.17g", 0.75 - 6.0 * PI);
    expect_arc(from, to, ".T.", 0.25, 0.75);
    /* Against the sense: from the first angle clockwise to the second. */
    expect_arc(from, to, ".F.", 0.25 + 2.0 * PI, 0.75);
    /* Equal angles: a full turn, as before. */
    expect_arc("1.", "1.", ".T.", 1.0, 1.0 + 2.0 * PI);
    /* The limit itself is accepted (a sweep of 1e4 - 0.5 mod 2 pi). */
    expect_arc("0.5", "1.E4", ".T.", 0.5, 0.5 + fmod(1e4 - 0.5, 2.0 * PI));
    /* Absurd and non-finite angles are refused, in either slot. */
    expect_refused("0.", "1.E300");
    expect_refused("0.", "1.E10");
    expect_refused("-1.E300", "0.");
    expect_refused("0.", "1.E999");
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_step_trim_angles");
}
