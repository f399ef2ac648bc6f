/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Length units: the reader keeps the unit a file declares (IGES global
 * parameter 14, the length unit of a STEP geometric context) as metres per
 * unit, the writer writes the unit it is given as an IGES flag and name
 * (parameters 14 and 15), and a file read back says what was written. Facts from the test data: sunglasses_lens.igs is in inches
 * ("1,2HIN" in its global section), linkrods.step in millimetres
 * (SI_UNIT(.MILLI.,.METRE.)).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"

/* The metres per unit a model states, 0 when it states none. */
static double metres_of_model(const projcurve_model *m)
{
    double metres = -1.0;
    if (!projcurve_model_length_unit(m, &metres))
        return metres == -1.0 ? 0.0 : -2.0; /* -2: untouched output written */
    return metres;
}

static double unit_of_file(const char *relative)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(relative), &m));
    const double metres = metres_of_model(m);
    projcurve_model_destroy(m);
    return metres;
}

static double unit_of_text(const char *text)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_memory(NULL, text, strlen(text), &m));
    const double metres = metres_of_model(m);
    projcurve_model_destroy(m);
    return metres;
}

/* Two unit sizes agree: a conversion-based unit is the product of its
 * factor and its base (25.4 x 0.001), a few ulps off the exact size. */
static int same_unit(double got, double expected)
{
    return fabs(got - expected) <= 4.0 * DBL_EPSILON * expected;
}

static void test_files(void)
{
    CHECK(unit_of_file("real/sunglasses_lens.igs") == 0.0254);
    CHECK(unit_of_file("real/linkrods.step") == 0.001);
    CHECK(unit_of_file("cases/song_yong_example1.igs") == 0.001);
    CHECK(metres_of_model(NULL) == 0.0);
}

/* A STEP text with one B-spline curve, the given unit instances and a
 * geometric context (#10) that assigns the unit #5. */
static void test_step(void)
{
    static const char head[] =
        "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n"
        "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=CARTESIAN_POINT('',(1.,2.,0.));\n"
        "#3=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),"
        ".UNSPECIFIED.);\n";
    static const char context[] =
        "#10=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#5))"
        "REPRESENTATION_CONTEXT('',''));\n";
    static const char tail[] = "ENDSEC;\nEND-ISO-10303-21;\n";
    static const struct {
        const char *units;
        int with_context;
        double expected; /* metres; 0: no unit */
    } cases[] = {
        {"#5=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n", 1, 0.001},
        {"#5=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));\n", 1, 1.0},
        {"#5=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.CENTI.,.METRE.));\n", 1, 0.01},
        {"#4=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
         "#6=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#4);\n"
         "#7=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"
         "#5=(CONVERSION_BASED_UNIT('INCH',#6)LENGTH_UNIT()NAMED_UNIT(#7));\n",
         1, 0.0254},
        /* an angle unit is no length unit */
        {"#5=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n", 1, 0.0},
        /* a unit no context assigns says nothing of the geometry */
        {"#5=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n", 0, 0.0},
        {"", 0, 0.0},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[2048];
        snprintf(text, sizeof text, "%s%s%s%s", head, cases[k].units,
                 cases[k].with_context ? context : "", tail);
        const double got = unit_of_text(text);
        const int ok = cases[k].expected == 0.0 ? got == 0.0 : same_unit(got, cases[k].expected);
        if (!ok)
            fprintf(stderr, "STEP unit %s: got %.17g m, expected %.17g m\n", cases[k].units, got,
                    cases[k].expected);
        CHECK(ok);
    }
}

/* Written with a unit (or the default), read back with it; the global
 * section carries the flag and its name. */
static void test_write(void)
{
    static const double ctrl[] = {0, 0, 0, 1, 2, 0}, knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    static const struct {
        double metres; /* 0: not set */
        const char *global;
        double read_back;
    } cases[] = {{0.0, ",2,2HMM,", 0.001},
                 {0.0254, ",1,2HIN,", 0.0254},
                 {25.4 * 0.001, ",1,2HIN,", 0.0254}, /* a STEP inch, with its rounding */
                 {1.0, ",6,1HM,", 1.0},
                 {0.3048, ",4,2HFT,", 0.3048},
                 {2.54e-8, ",11,3HUIN,", 2.54e-8}};
    char path[64];
    snprintf(path, sizeof path, "test_io_units_%d.igs", (int)getpid());
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        projcurve_iges_writer *w = NULL;
        CHECK_OK(projcurve_iges_writer_create(NULL, &w));
        if (cases[k].metres != 0.0)
            CHECK_OK(projcurve_iges_writer_set_length_unit(NULL, w, cases[k].metres));
        CHECK_OK(projcurve_iges_writer_add_curve(NULL, w, c));
        CHECK_OK(projcurve_iges_writer_write(NULL, w, path));
        projcurve_iges_writer_destroy(w);
        char *text = pc_test_read_file(path, NULL);
        CHECK(text != NULL && strstr(text, cases[k].global) != NULL);
        free(text);
        projcurve_model *m = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, path, &m));
        CHECK(metres_of_model(m) == cases[k].read_back);
        projcurve_model_destroy(m);
    }
    /* refused: no IGES unit, or not a length; the writer keeps its unit */
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(NULL, &w));
    CHECK_OK(projcurve_iges_writer_set_length_unit(NULL, w, 0.0254));
    static const double refused[] = {0.0, -0.001, 0.002, 3.0, 0.0254 * (1.0 + 1e-6)};
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; ++k)
        CHECK_STATUS(projcurve_iges_writer_set_length_unit(NULL, w, refused[k]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_iges_writer_set_length_unit(NULL, w, NAN), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_iges_writer_set_length_unit(NULL, w, INFINITY),
                 PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_iges_writer_set_length_unit(NULL, NULL, 0.001),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_OK(projcurve_iges_writer_add_curve(NULL, w, c));
    CHECK_OK(projcurve_iges_writer_write(NULL, w, path));
    projcurve_iges_writer_destroy(w);
    char *text = pc_test_read_file(path, NULL);
    CHECK(text != NULL && strstr(text, ",1,2HIN,") != NULL);
    free(text);
    remove(path);
    projcurve_curve_destroy(c);
}

int main(void)
{
    test_files();
    test_step();
    test_write();
    return pc_test_finish("test_io_units");
}
