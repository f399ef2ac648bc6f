/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Length units: the reader keeps the unit a file declares (IGES global
 * parameter 14, a STEP length unit), the writer writes the unit it is
 * given (parameters 14 and 15), and a file read back says what was
 * written. Facts from the test data: sunglasses_lens.igs is in inches
 * ("1,2HIN" in its global section), linkrods.step in millimetres
 * (SI_UNIT(.MILLI.,.METRE.)).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"

static int unit_of_file(const char *relative)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(relative), &m));
    const int unit = projcurve_model_unit(m);
    projcurve_model_destroy(m);
    return unit;
}

static int unit_of_text(const char *text)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_memory(NULL, text, strlen(text), &m));
    const int unit = projcurve_model_unit(m);
    projcurve_model_destroy(m);
    return unit;
}

static void test_files(void)
{
    CHECK(unit_of_file("real/sunglasses_lens.igs") == PROJCURVE_UNIT_INCH);
    CHECK(unit_of_file("real/linkrods.step") == PROJCURVE_UNIT_MM);
    CHECK(unit_of_file("cases/song_yong_example1.igs") == PROJCURVE_UNIT_MM);
    CHECK(projcurve_model_unit(NULL) == PROJCURVE_UNIT_UNKNOWN);
}

/* A STEP text with one B-spline curve and the given unit instance. */
static void test_step(void)
{
    static const char head[] =
        "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n"
        "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=CARTESIAN_POINT('',(1.,2.,0.));\n"
        "#3=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#2),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),"
        ".UNSPECIFIED.);\n";
    static const char tail[] = "ENDSEC;\nEND-ISO-10303-21;\n";
    static const struct {
        const char *unit;
        int expected;
    } cases[] = {
        {"#9=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n", PROJCURVE_UNIT_MM},
        {"#9=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));\n", PROJCURVE_UNIT_METRE},
        {"#9=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.CENTI.,.METRE.));\n", PROJCURVE_UNIT_CM},
        {"#8=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
         "#9=(CONVERSION_BASED_UNIT('INCH',#7)LENGTH_UNIT()NAMED_UNIT(#6));\n",
         PROJCURVE_UNIT_INCH},
        {"#9=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n", PROJCURVE_UNIT_UNKNOWN},
        {"", PROJCURVE_UNIT_UNKNOWN},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[1024];
        snprintf(text, sizeof text, "%s%s%s", head, cases[k].unit, tail);
        const int got = unit_of_text(text);
        if (got != cases[k].expected)
            fprintf(stderr, "STEP unit %s: got %d, expected %d\n", cases[k].unit, got,
                    cases[k].expected);
        CHECK(got == cases[k].expected);
    }
}

static char *file_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    const long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = n >= 0 ? calloc((size_t)n + 1, 1) : NULL;
    if (text != NULL && fread(text, 1, (size_t)n, f) != (size_t)n) {
        free(text);
        text = NULL;
    }
    fclose(f);
    return text;
}

/* Written with a unit (or the default), read back with it; the global
 * section carries the flag and its name. */
static void test_write(void)
{
    static const double ctrl[] = {0, 0, 0, 1, 2, 0}, knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    static const struct {
        int unit;
        const char *global;
    } cases[] = {{0, ",2,2HMM,"},
                 {PROJCURVE_UNIT_INCH, ",1,2HIN,"},
                 {PROJCURVE_UNIT_METRE, ",6,1HM,"},
                 {PROJCURVE_UNIT_MICROINCH, ",11,3HUIN,"}};
    char path[64];
    snprintf(path, sizeof path, "test_io_units_%d.igs", (int)getpid());
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        projcurve_iges_writer *w = NULL;
        CHECK_OK(projcurve_iges_writer_create(NULL, &w));
        if (cases[k].unit != 0)
            CHECK_OK(projcurve_iges_writer_set_unit(NULL, w, cases[k].unit));
        CHECK_OK(projcurve_iges_writer_add_curve(NULL, w, c));
        CHECK_OK(projcurve_iges_writer_write(NULL, w, path));
        projcurve_iges_writer_destroy(w);
        char *text = file_text(path);
        CHECK(text != NULL && strstr(text, cases[k].global) != NULL);
        free(text);
        projcurve_model *m = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, path, &m));
        const int expected = cases[k].unit ? cases[k].unit : PROJCURVE_UNIT_MM;
        CHECK(projcurve_model_unit(m) == expected);
        projcurve_model_destroy(m);
    }
    remove(path);
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(NULL, &w));
    static const int refused[] = {0, 3, 12, -1};
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; ++k)
        CHECK_STATUS(projcurve_iges_writer_set_unit(NULL, w, refused[k]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_iges_writer_set_unit(NULL, NULL, PROJCURVE_UNIT_MM),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_iges_writer_destroy(w);
    projcurve_curve_destroy(c);
}

int main(void)
{
    test_files();
    test_step();
    test_write();
    return pc_test_finish("test_io_units");
}
