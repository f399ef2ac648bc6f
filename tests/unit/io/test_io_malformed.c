/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bad input to the readers: truncated files, wrong column layout, bad
 * pointers, absurd counts, non-numeric fields, deep nesting, megabytes of
 * garbage and random mutations of real files. Every read must end with OK
 * or a clear error (status + message naming the line or entity); crashes,
 * hangs and leaks are caught by running this test under ASan/UBSan.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

static projcurve_context *ctx;

static char *slurp(const char *relative, size_t *len)
{
    FILE *fp = fopen(pc_test_data_path(relative), "rb");
    if (fp == NULL)
        return NULL;
    fseek(fp, 0, SEEK_END);
    const long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    if (buf == NULL || fread(buf, 1, (size_t)n, fp) != (size_t)n) {
        free(buf);
        fclose(fp);
        return NULL;
    }
    fclose(fp);
    buf[n] = '\0';
    *len = (size_t)n;
    return buf;
}

/* Reads from memory; on failure checks that a message was left. */
static projcurve_status read_mem(const char *data, size_t len, size_t *surfaces)
{
    projcurve_model *m = NULL;
    projcurve_context_clear(ctx);
    const projcurve_status st = projcurve_model_read_memory(ctx, data, len, &m);
    if (st == PROJCURVE_OK) {
        CHECK(m != NULL);
        if (surfaces)
            *surfaces = projcurve_model_surface_count(m);
        projcurve_model_destroy(m);
    } else {
        CHECK(m == NULL);
        CHECK(projcurve_context_message(ctx)[0] != '\0');
    }
    return st;
}

/* The read fails with `status` and a message containing `needle`. */
static void expect_error(const char *data, size_t len, projcurve_status status, const char *needle,
                         const char *what)
{
    const projcurve_status st = read_mem(data, len, NULL);
    const char *msg = projcurve_context_message(ctx);
    if (st != status || strstr(msg, needle) == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "%s: got %s \"%s\", expected %s with \"%s\"", what,
                        projcurve_status_string(st), msg, projcurve_status_string(status), needle);
    ++pc_test_checks;
}

/* Replaces the first occurrence of `from` (after offset `after`). */
static char *replaced(const char *text, size_t len, const char *from, const char *to,
                      size_t *out_len)
{
    const char *at = strstr(text, from);
    if (at == NULL)
        return NULL;
    const size_t a = (size_t)(at - text), nf = strlen(from), nt = strlen(to);
    char *out = malloc(len - nf + nt + 1);
    memcpy(out, text, a);
    memcpy(out + a, to, nt);
    memcpy(out + a + nt, at + nf, len - a - nf);
    *out_len = len - nf + nt;
    out[*out_len] = '\0';
    return out;
}

/* IGES records are fixed width: a longer replacement eats the blanks that
 * follow `from`, a shorter one is padded with blanks. */
static void check_replaced_record(const char *text, size_t len, const char *from, const char *to,
                                  projcurve_status status, const char *needle, const char *what)
{
    char f[128], t[128];
    const size_t nf = strlen(from), nt = strlen(to);
    const size_t w = nf > nt ? nf : nt;
    snprintf(f, sizeof f, "%s%*s", from, (int)(w - nf), "");
    snprintf(t, sizeof t, "%s%*s", to, (int)(w - nt), "");
    size_t n;
    char *bad = replaced(text, len, f, t, &n);
    CHECK(bad != NULL);
    if (bad)
        expect_error(bad, n, status, needle, what);
    free(bad);
}

static void check_replaced(const char *text, size_t len, const char *from, const char *to,
                           projcurve_status status, const char *needle, const char *what)
{
    size_t n;
    char *bad = replaced(text, len, from, to, &n);
    CHECK(bad != NULL);
    if (bad)
        expect_error(bad, n, status, needle, what);
    free(bad);
}

static void iges_cases(void)
{
    size_t len;
    char *text = slurp("cases/song_yong_example1.igs", &len);
    if (text == NULL)
        pc_test_missing_data("cases/song_yong_example1.igs");
    size_t surfaces = 0;
    CHECK_OK(read_mem(text, len, &surfaces));
    CHECK(surfaces == 1);

    /* Truncated anywhere after the first record and before the sequence
     * number of the last (whose loss costs nothing): a PARSE error that
     * names the IGES line or says the file is truncated. */
    for (size_t cut = 81; cut + 8 < len; cut += 37) {
        const projcurve_status st = read_mem(text, cut, NULL);
        const char *msg = projcurve_context_message(ctx);
        if (st != PROJCURVE_ERR_PARSE ||
            (strstr(msg, "IGES line") == NULL && strstr(msg, "truncated") == NULL))
            pc_test_fail_at(__FILE__, __LINE__, "cut at %zu of %zu: %s \"%s\"", cut, len,
                            projcurve_status_string(st), msg);
        ++pc_test_checks;
    }
    expect_error(text, 2000, PROJCURVE_ERR_PARSE, "IGES line 25: only 56 columns",
                 "truncated in the P section");
    expect_error(text, 24 * 81, PROJCURVE_ERR_PARSE, "no terminate (T) record",
                 "truncated at a line end");
    CHECK_OK(read_mem(text, len - 1, NULL)); /* only the last line end missing */

    /* Wrong column layout: every record shifted right by one column. */
    {
        char *shifted = malloc(2 * len);
        size_t n = 0;
        int at_line_start = 1;
        for (size_t i = 0; i < len; ++i) {
            if (at_line_start)
                shifted[n++] = ' ';
            shifted[n++] = text[i];
            at_line_start = text[i] == '\n';
        }
        expect_error(shifted, n, PROJCURVE_ERR_PARSE, "line 1", "shifted columns");
        free(shifted);
    }
    /* Every record shifted left or right by one column, still 80 wide. */
    {
        char *left = malloc(len + 1), *right = malloc(len + 1);
        size_t nl = 0, nr = 0;
        for (size_t start = 0; start < len;) {
            const char *eol = memchr(text + start, '\n', len - start);
            const size_t end = eol ? (size_t)(eol - text) : len;
            for (size_t i = start + 1; i < end; ++i)
                left[nl++] = text[i];
            left[nl++] = ' ';
            right[nr++] = ' ';
            for (size_t i = start; i + 1 < end; ++i)
                right[nr++] = text[i];
            left[nl++] = right[nr++] = '\n';
            start = end + 1;
        }
        expect_error(left, nl, PROJCURVE_ERR_PARSE, "line 1: the section letter 'S' is in column 72",
                     "columns shifted left");
        expect_error(right, nr, PROJCURVE_ERR_PARSE, "line 1: the section letter 'S' is in column 74",
                     "columns shifted right");
        free(left);
        free(right);
    }
    /* Lines lost in the middle of the parameter section: the terminate
     * record's counts disagree. */
    {
        const size_t record = 81, drop_from = 20 * record, drop = 5 * record;
        char *holed = malloc(len);
        memcpy(holed, text, drop_from);
        memcpy(holed + drop_from, text + drop_from + drop, len - drop_from - drop);
        expect_error(holed, len - drop, PROJCURVE_ERR_PARSE,
                     "terminate record counts 55 P records, the file has 50", "lost lines");
        free(holed);
    }
    /* A parameter record carrying another entity's DE back pointer. */
    check_replaced_record(text, len, "0000001P0000004", "0000003P0000004", PROJCURVE_ERR_PARSE,
                          "line 13: parameter record belongs to DE 3, expected DE 1",
                          "wrong back pointer");
    /* A section letter that is not one. */
    check_replaced_record(text, len, "G0000002", "X0000002", PROJCURVE_ERR_PARSE, "line 3",
                   "bad section letter");
    /* Directory entry 1 points past the parameter section. */
    check_replaced_record(text, len, "     128       1       0", "     128     999       0",
                   PROJCURVE_ERR_PARSE, "DE 1", "parameter pointer past the end");
    /* Parameter line count absurd. */
    check_replaced_record(text, len, "     128       0       0      35", "     128       0       0 9999999",
                   PROJCURVE_ERR_PARSE, "DE 1", "absurd parameter line count");
    /* Absurd counts inside the entity: K1 = 99999999 control points. */
    check_replaced_record(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,", "128,99999999,1,5,1,0,0,1,0,0,0.0000000000000000E+00,", PROJCURVE_ERR_PARSE, "DE 1",
                   "absurd K1");
    check_replaced_record(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,", "128,5,1,-5,1,0,0,1,0,0,0.0000000000000000E+00,", PROJCURVE_ERR_PARSE, "degree M1",
                   "negative degree");
    /* Non-numeric parameter. */
    check_replaced_record(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,",
                   "128,5,1,5,1,0,0,1,0,0,0.00000000000abcdef0E+00,", PROJCURVE_ERR_PARSE,
                   "not a number", "non-numeric knot");
    /* A real beyond the doubles (1e999) is no number either; a Fortran 'D'
     * exponent is one, read as 'E'. */
    check_replaced_record(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,",
                          "128,5,1,5,1,0,0,1,0,0,1.0000000000000000E+999,", PROJCURVE_ERR_PARSE,
                          "not a number", "overflowing knot");
    {
        size_t n = 0;
        char *fortran = replaced(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,",
                                 "128,5,1,5,1,0,0,1,0,0,0.0000000000000000D+00,", &n);
        CHECK(fortran != NULL);
        if (fortran != NULL) {
            CHECK_OK(read_mem(fortran, n, &surfaces));
            CHECK(surfaces == 1);
        }
        free(fortran);
    }
    /* Global section delimiters: "1Hx" fields that are unusable (a digit,
     * '.') or the same for parameters and records. */
    static const char g1[] = ",,31HOpen CASCADE IGES processor 7.6,22Hsong_yong_example1.igs,";
    check_replaced_record(text, len, g1,
                          "1H5,,31HOpen CASCADE IGES processor 7.6,22Hsong_yong_example1.igs,",
                          PROJCURVE_ERR_PARSE,
                          "unusable parameter delimiter", "digit as parameter delimiter");
    check_replaced_record(text, len, g1,
                          ",1H.,31HOpen CASCADE IGES processor 7.6,22Hsong_yong_example1.igs,",
                          PROJCURVE_ERR_PARSE,
                          "unusable record delimiter", "'.' as record delimiter");
    check_replaced_record(text, len, g1,
                          "1H;;1H;;31HOpen CASCADE IGES processor 7.6,22Hsong_yong_example1.igs,",
                          PROJCURVE_ERR_PARSE,
                          "are both ';'", "one delimiter for both");
    /* Non-numeric directory field. */
    check_replaced_record(text, len, "     128       1       0", "     1x8       1       0",
                   PROJCURVE_ERR_PARSE, "directory field 1", "non-numeric DE field");
    /* Entity type in the P section disagrees with the directory. */
    check_replaced_record(text, len, "128,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,", "126,5,1,5,1,0,0,1,0,0,0.0000000000000000E+00,", PROJCURVE_ERR_PARSE, "entity type",
                   "type mismatch");
    /* Transformation pointer to a non-124 entity. */
    check_replaced_record(text, len, "     128       1       0       0       0       0       0",
                   "     128       1       0       0       0       0       3",
                   PROJCURVE_ERR_PARSE, "not 124", "transform pointer to a curve");
    /* Transformation pointer that is even (not a DE start). */
    check_replaced_record(text, len, "     128       1       0       0       0       0       0",
                   "     128       1       0       0       0       0       2",
                   PROJCURVE_ERR_PARSE, "pointer 2", "even DE pointer");
    /* Weights of zero reach the surface validation, named by entity. */
    free(text);
}

static void mutate(const char *relative, size_t rounds, unsigned long long seed)
{
    size_t len;
    char *text = slurp(relative, &len);
    if (text == NULL)
        pc_test_missing_data(relative);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    char *work = malloc(len + 1);
    static const char alphabet[] = "0123456789,;.-+EeDH#()'$* \n/=ABCXYZ<>\"";
    for (size_t r = 0; r < rounds; ++r) {
        memcpy(work, text, len + 1);
        const int edits = 1 + (int)pc_test_rng_uniform(&rng, 0.0, 8.0);
        for (int e = 0; e < edits; ++e) {
            const size_t at = (size_t)pc_test_rng_uniform(&rng, 0.0, (double)len);
            work[at] = alphabet[(size_t)pc_test_rng_uniform(&rng, 0.0, sizeof alphabet - 1.0)];
        }
        const size_t n = (size_t)pc_test_rng_uniform(&rng, (double)len * 0.5, (double)len + 1.0);
        (void)read_mem(work, n > len ? len : n, NULL);
    }
    free(work);
    free(text);
}

static void garbage(void)
{
    const size_t len = 3u << 20;
    char *junk = malloc(len);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 42);
    for (size_t i = 0; i < len; ++i)
        junk[i] = (char)(int)pc_test_rng_uniform(&rng, 0.0, 256.0);
    expect_error(junk, len, PROJCURVE_ERR_PARSE, "unrecognised", "random bytes");
    /* The same behind each format's signature. */
    memcpy(junk, "ISO-10303-21;\nHEADER;ENDSEC;\nDATA;\n", 35);
    CHECK(read_mem(junk, len, NULL) != PROJCURVE_OK);
    memcpy(junk, "<xml><Geometry type=\"TensorBSpline2\">", 37);
    CHECK(read_mem(junk, len, NULL) != PROJCURVE_OK);
    memcpy(junk, "32\n", 3);
    CHECK(read_mem(junk, len, NULL) != PROJCURVE_OK);
    char *iges = malloc(len);
    for (size_t i = 0; i < len; ++i)
        iges[i] = (i % 81 == 80) ? '\n' : (i % 81 == 72) ? "SGDPT"[(i / 81 / 4000) % 5] : junk[i];
    CHECK(read_mem(iges, len, NULL) != PROJCURVE_OK);
    free(iges);
    /* Megabytes of valid-looking tokens. */
    for (size_t i = 0; i < len; ++i)
        junk[i] = "<Geometry "[i % 10];
    CHECK(read_mem(junk, len, NULL) != PROJCURVE_OK);
    memcpy(junk, "ISO-10303-21;\nDATA;\n#1=A", 24);
    for (size_t i = 24; i < len; ++i)
        junk[i] = '(';
    expect_error(junk, len, PROJCURVE_ERR_PARSE, "#1", "deep nesting");
    free(junk);
    expect_error("", 0, PROJCURVE_ERR_PARSE, "unrecognised", "empty input");
}

static const char step_text[] =
    "ISO-10303-21;\nHEADER;\nFILE_NAME('a;b','',(''),(''),'','','');\nENDSEC;\nDATA;\n"
    "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=CARTESIAN_POINT('',(1.,0.,0.));\n"
    "#3=CARTESIAN_POINT('',(0.,1.,0.));\n#4=CARTESIAN_POINT('',(1.,1.,1.));\n"
    "#5=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#1,#3),(#2,#4)),.UNSPECIFIED.,.F.,.F.,.F.,"
    "(2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.);\n"
    "#6=B_SPLINE_CURVE_WITH_KNOTS('',1,(#1,#4),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,2.),.UNSPECIFIED.);\n"
    "ENDSEC;\nEND-ISO-10303-21;\n";

static void step_cases(void)
{
    const size_t len = sizeof step_text - 1;
    size_t surfaces = 0;
    CHECK_OK(read_mem(step_text, len, &surfaces));
    CHECK(surfaces == 1);
    /* Cut anywhere before the DATA section's ENDSEC: a PARSE error. */
    const size_t data_end = (size_t)(strstr(step_text, "ENDSEC;\nEND-ISO") - step_text);
    for (size_t cut = 0; cut < data_end; cut += 7)
        CHECK_STATUS(read_mem(step_text, cut, NULL), PROJCURVE_ERR_PARSE);
    check_replaced(step_text, len, "ENDSEC;\nEND", "END", PROJCURVE_ERR_PARSE, "ENDSEC",
                   "no ENDSEC");
    check_replaced(step_text, len, "((#1,#3),(#2,#4))", "((#1,#3),(#2,#99))", PROJCURVE_ERR_PARSE,
                   "#99", "undefined reference");
    check_replaced(step_text, len, "(2,2),(2,2),(0.,1.)", "(3,2),(2,2),(0.,1.)", PROJCURVE_ERR_PARSE,
                   "#5", "multiplicities");
    check_replaced(step_text, len, "(2,2),(0.,2.)", "(1,1,2),(0.,2.)", PROJCURVE_ERR_PARSE, "#6",
                   "unpaired knots");
    check_replaced(step_text, len, "(#1,#4),.UNSP", "(#1,#4,),.UNSP", PROJCURVE_ERR_PARSE, "#6",
                   "empty list item");
    check_replaced(step_text, len, "#4=CARTESIAN_POINT('',(1.,1.,1.));",
                   "#4=CARTESIAN_POINT('',(1.,1.,1.x));", PROJCURVE_ERR_PARSE, "#4", "bad number");
    check_replaced(step_text, len, "#4=CARTESIAN_POINT", "#3=CARTESIAN_POINT", PROJCURVE_ERR_PARSE,
                   "twice", "duplicate instance");
    check_replaced(step_text, len, "('',1,1,((", "('',99,1,((", PROJCURVE_ERR_PARSE, "degree",
                   "absurd degree");
    /* the lexer's syntax errors, each named in the message with its instance */
    static const char *const p3 = "#3=CARTESIAN_POINT('',(0.,1.,0.));";
    static const struct {
        const char *to, *needle;
    } syntax[] = {
        {"#3=;", "empty instance"},
        {"#3=1;", "expected an entity NAME(...)"},
        {"#3=CARTESIAN_POINT('',(0.,1.,0.)) X;", "text after the entity"},
        {"#3=(CARTESIAN_POINT('',(0.,1.,0.));", "complex instance is not closed"},
        {"#3=(1 CARTESIAN_POINT('',(0.,1.,0.)));", "expected a sub-entity NAME(...)"},
        {"#3=CARTESIAN_POINT('',(0.,1.,@));", "unexpected character"},
        {"#3=CARTESIAN_POINT('',(0.,1.,#));", "bad reference"},
        {"#3=CARTESIAN_POINT('',(0.,1.,.F));", "an enumeration is not closed by '.'"},
        {"#3=CARTESIAN_POINT('',(0.,1.,LENGTH_MEASURE));", "expected '(' after a type name"},
        {"#3=CARTESIAN_POINT('',(0.,1.,0.);", "a list is not closed"},
    };
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; ++i)
        check_replaced(step_text, len, p3, syntax[i].to, PROJCURVE_ERR_PARSE, syntax[i].needle,
                       syntax[i].needle);
    /* a quote doubled inside a string is one quote, not its end */
    size_t n = 0;
    char *quoted = replaced(step_text, len, p3, "#3=CARTESIAN_POINT('it''s',(0.,1.,0.));", &n);
    CHECK(quoted != NULL);
    if (quoted != NULL) {
        CHECK_OK(read_mem(quoted, n, &surfaces));
        CHECK(surfaces == 1);
    }
    free(quoted);
}

static void teapot_cases(void)
{
    static const char small[] = "1\n1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16\n16\n"
                                "0,0,0\n1,0,0\n2,0,0\n3,0,0\n0,1,0\n1,1,0\n2,1,0\n3,1,0\n"
                                "0,2,0\n1,2,0\n2,2,0\n3,2,0\n0,3,0\n1,3,0\n2,3,0\n3,3,1\n";
    const size_t len = sizeof small - 1;
    size_t surfaces = 0;
    CHECK_OK(read_mem(small, len, &surfaces));
    CHECK(surfaces == 1);
    check_replaced(small, len, "15,16\n", "15,17\n", PROJCURVE_ERR_PARSE, "vertex index 17",
                   "index past the vertices");
    check_replaced(small, len, "16\n0,0,0", "99999999\n0,0,0", PROJCURVE_ERR_PARSE, "line 3",
                   "absurd vertex count");
    check_replaced(small, len, "1\n1,2", "9999999\n1,2", PROJCURVE_ERR_PARSE, "line 1",
                   "absurd patch count");
    check_replaced(small, len, "3,3,1\n", "3,3,z\n", PROJCURVE_ERR_PARSE, "line 19",
                   "non-numeric coordinate");
    /* Cut anywhere before the last coordinate: a PARSE error. */
    for (size_t cut = 0; cut + 2 < len; cut += 3)
        CHECK_STATUS(read_mem(small, cut, NULL), PROJCURVE_ERR_PARSE);
}

static void gismo_cases(void)
{
    static const char xml[] =
        "<xml>\n<Geometry type=\"TensorBSpline2\">\n<Basis type=\"TensorBSplineBasis2\">\n"
        "<Basis type=\"BSplineBasis\" index=\"0\"><KnotVector degree=\"1\">0 0 1 1</KnotVector>"
        "</Basis>\n<Basis type=\"BSplineBasis\" index=\"1\"><KnotVector degree=\"1\">0 0 1 1"
        "</KnotVector></Basis>\n</Basis>\n<coefs geoDim=\"3\">0 0 0\n1 0 0\n0 1 0\n1 1 1\n</coefs>\n"
        "</Geometry>\n</xml>\n";
    const size_t len = sizeof xml - 1;
    size_t surfaces = 0;
    CHECK_OK(read_mem(xml, len, &surfaces));
    CHECK(surfaces == 1);
    check_replaced(xml, len, "1 1 1\n</coefs>", "1 1 x\n</coefs>", PROJCURVE_ERR_PARSE, "line 10",
                   "non-numeric coefficient");
    check_replaced(xml, len, "1 1 1\n</coefs>", "</coefs>", PROJCURVE_ERR_PARSE, "coefficients",
                   "missing control point");
    check_replaced(xml, len, "degree=\"1\">0 0 1 1</KnotVector></Basis>\n<Basis",
                   "degree=\"99\">0 0 1 1</KnotVector></Basis>\n<Basis", PROJCURVE_ERR_PARSE,
                   "degree", "absurd degree");
    /* Cut anywhere before the end of </Geometry>: a PARSE error. */
    const size_t closed = (size_t)(strstr(xml, "</Geometry>") - xml) + strlen("</Geometry>");
    for (size_t cut = 0; cut < closed; cut += 5)
        CHECK_STATUS(read_mem(xml, cut, NULL), PROJCURVE_ERR_PARSE);
    /* Two geometries, the file cut inside the second: an error naming the
     * line where it opens, not a model with the first one only. */
    char two[2 * sizeof xml];
    snprintf(two, sizeof two, "%s%s", xml, xml);
    const char *second = strstr(two + len, "<Geometry");
    CHECK(second != NULL);
    if (second != NULL) {
        for (size_t cut = (size_t)(second - two) + 10; cut + 20 < strlen(two); cut += 11)
            expect_error(two, cut, PROJCURVE_ERR_PARSE, "line 15: <Geometry> is not closed",
                         "G+Smo truncated in its second geometry");
    }
}

/* ---- files whose cost grows with references, built here ---------------- */

typedef struct text_buf {
    char *s;
    size_t len, cap;
} text_buf;

static void put(text_buf *b, const char *fmt, ...)
{
    va_list args, again;
    va_start(args, fmt);
    va_copy(again, args);
    const int n = vsnprintf(NULL, 0, fmt, args);
    va_end(args);
    if (b->len + (size_t)n + 1 > b->cap) {
        b->cap = 2 * (b->len + (size_t)n + 1);
        b->s = realloc(b->s, b->cap);
    }
    vsnprintf(b->s + b->len, (size_t)n + 1, fmt, again);
    va_end(again);
    b->len += (size_t)n;
}

/* An IGES file of n entities (type, parameters without the type). */
static char *iges_file(const int *types, char *const *params, size_t n, size_t *len)
{
    text_buf out = {0}, pars = {0};
    size_t *start = calloc(n, sizeof *start), *count = calloc(n, sizeof *count), seq = 1;
    put(&out, "%-72sS%7d\n", "generated", 1);
    put(&out, "%-72sG%7d\n", "1H,,1H;;", 1);
    for (size_t e = 0; e < n; ++e) {
        char head[16];
        snprintf(head, sizeof head, "%d,", types[e]);
        const size_t hl = strlen(head), pl = strlen(params[e]);
        char *all = malloc(hl + pl + 1);
        memcpy(all, head, hl);
        memcpy(all + hl, params[e], pl + 1);
        start[e] = seq;
        for (size_t at = 0; at < hl + pl; at += 64, ++count[e])
            put(&pars, "%-64.64s %7zuP%7zu\n", all + at, 2 * e + 1, seq++);
        free(all);
    }
    for (size_t e = 0; e < n; ++e) {
        put(&out, "%8d%8zu%8d%8d%8d%8d%8d%8d%8sD%7zu\n", types[e], start[e], 0, 0, 0, 0, 0, 0,
            "00000000", 2 * e + 1);
        put(&out, "%8d%8d%8d%8zu%8d%8s%8s%8s%8dD%7zu\n", types[e], 0, 0, count[e], 0, "", "", "", 0,
            2 * e + 2);
    }
    put(&out, "%s", pars.s);
    put(&out, "S%7dG%7dD%7zuP%7zu%40sT%7d\n", 1, 1, 2 * n, seq - 1, "", 1);
    free(pars.s);
    free(start);
    free(count);
    *len = out.len;
    return out.s;
}

/* A degree-1 126 with n points along x. */
static char *long_curve(size_t n)
{
    text_buf b = {0};
    put(&b, "%zu,1,0,0,1,0,", n - 1);
    put(&b, "0.,");
    for (size_t i = 0; i < n; ++i)
        put(&b, "%zu.,", i);
    put(&b, "%zu.,", n - 1);
    for (size_t i = 0; i < n; ++i)
        put(&b, "1.,");
    for (size_t i = 0; i < n; ++i)
        put(&b, "%zu.,0.,0.,", i);
    put(&b, "0.,%zu.;", n - 1);
    return b.s;
}

static void reference_bombs(void)
{
    /* 20000 composite members all pointing at one 4000-point curve. */
    text_buf composite = {0};
    const size_t members = 20000;
    put(&composite, "%zu", members);
    for (size_t i = 0; i < members; ++i)
        put(&composite, ",1");
    put(&composite, ";");
    int types[2] = {126, 102};
    char *params[2] = {long_curve(4000), composite.s};
    size_t len;
    char *text = iges_file(types, params, 2, &len);
    expect_error(text, len, PROJCURVE_ERR_PARSE, "too many times", "many references, IGES");
    free(text);
    /* A composite of a curve with 30000 knots: listed, not joined slowly. */
    free(params[0]);
    params[0] = long_curve(30000);
    free(composite.s);
    composite = (text_buf){0};
    put(&composite, "2,1,1;");
    params[1] = composite.s;
    text = iges_file(types, params, 2, &len);
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_memory(ctx, text, len, &m));
    int listed = 0;
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i)
        listed |= strstr(projcurve_model_skipped(m, i), "too many knots") != NULL;
    CHECK(listed);
    projcurve_model_destroy(m);
    free(text);
    free(params[0]);
    free(params[1]);

    /* STEP: 3000 trimmed curves over one 3000-point B-spline. */
    text_buf step = {0};
    const size_t n = 3000;
    put(&step, "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n");
    for (size_t i = 1; i <= n; ++i)
        put(&step, "#%zu=CARTESIAN_POINT('',(%zu.,0.,0.));\n", i, i);
    put(&step, "#%zu=B_SPLINE_CURVE_WITH_KNOTS('',1,(", n + 1);
    for (size_t i = 1; i <= n; ++i)
        put(&step, i < n ? "#%zu," : "#%zu", i);
    put(&step, "),.UNSPECIFIED.,.F.,.F.,(2,");
    for (size_t i = 2; i < n; ++i)
        put(&step, "1,");
    put(&step, "2),(");
    for (size_t i = 0; i < n; ++i)
        put(&step, i + 1 < n ? "%zu.," : "%zu.", i);
    put(&step, "),.UNSPECIFIED.);\n");
    for (size_t i = 0; i < n; ++i)
        put(&step, "#%zu=TRIMMED_CURVE('',#%zu,(PARAMETER_VALUE(1.)),(PARAMETER_VALUE(2.)),.T.,"
                   ".PARAMETER.);\n",
            n + 2 + i, n + 1);
    put(&step, "ENDSEC;\nEND-ISO-10303-21;\n");
    expect_error(step.s, step.len, PROJCURVE_ERR_PARSE, "too many times", "many references, STEP");
    free(step.s);
}

/* Reads a generated file of n entities and expects the error. */
static void expect_iges_error(const int *types, char *const *params, size_t n,
                              projcurve_status status, const char *needle, const char *what)
{
    size_t len;
    char *text = iges_file(types, params, n, &len);
    expect_error(text, len, status, needle, what);
    free(text);
}

/* Pointers between entities that lead nowhere, counts that cannot be,
 * and values the geometry checks refuse, each named by its entity. */
static void pointers_and_counts(void)
{
    char line[] = "1,1,0,0,1,0,0.,0.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,0.,1.;";
    char bad_member[] = "2,1,99;", even_member[] = "1,2;", huge_composite[] = "2000000000,1;";
    char negative_composite[] = "-3,1;";
    char cos_bad[] = "1,0,1,7,0;", cos_curve_bad[] = "1,0,0,41,0;";
    const int curve_102[2] = {126, 102}, curve_142[2] = {126, 142};
    char *p[2] = {line, bad_member};
    expect_iges_error(curve_102, p, 2, PROJCURVE_ERR_PARSE, "DE 3: pointer 99",
                      "composite member past the directory");
    p[1] = even_member;
    expect_iges_error(curve_102, p, 2, PROJCURVE_ERR_PARSE, "DE 3: pointer 2",
                      "composite member at an even DE");
    p[1] = huge_composite;
    expect_iges_error(curve_102, p, 2, PROJCURVE_ERR_PARSE, "DE 3", "absurd member count");
    p[1] = negative_composite;
    expect_iges_error(curve_102, p, 2, PROJCURVE_ERR_PARSE, "DE 3", "negative member count");
    p[1] = cos_bad;
    expect_iges_error(curve_142, p, 2, PROJCURVE_ERR_PARSE, "DE 3: pointer 7",
                      "142 parameter curve past the directory");
    p[1] = cos_curve_bad;
    expect_iges_error(curve_142, p, 2, PROJCURVE_ERR_PARSE, "DE 3: pointer 41",
                      "142 3D curve past the directory");

    /* A weight of zero reaches the curve validation, named by the entity. */
    char zero_weight[] = "1,1,0,0,0,0,0.,0.,1.,1.,0.,1.,0.,0.,0.,1.,0.,0.,0.,1.;";
    const int curve[1] = {126};
    char *one[1] = {zero_weight};
    expect_iges_error(curve, one, 1, PROJCURVE_ERR_BAD_WEIGHT, "IGES entity 126 at DE 1",
                      "zero weight");
    /* More knots claimed than the record holds. */
    char short_curve[] = "40,1,0,0,1,0,0.,0.,1.,1.;";
    one[0] = short_curve;
    expect_iges_error(curve, one, 1, PROJCURVE_ERR_PARSE, "IGES entity 126 at DE 1",
                      "count beyond the parameters");
}

static void api_misuse(void)
{
    projcurve_model *m = NULL;
    CHECK_STATUS(projcurve_model_read_file(ctx, NULL, &m), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_model_read_file(ctx, "x.igs", NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_model_read_memory(ctx, NULL, 3, &m), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_model_read_file(ctx, "/nonexistent/file.igs", &m), PROJCURVE_ERR_IO);
    CHECK(strstr(projcurve_context_message(ctx), "/nonexistent/file.igs") != NULL);
    CHECK_STATUS(projcurve_model_read_file(NULL, "/nonexistent/file.igs", &m), PROJCURVE_ERR_IO);
    CHECK(m == NULL);
    CHECK(projcurve_model_surface_count(NULL) == 0);
    CHECK(projcurve_model_curve_count(NULL) == 0);
    CHECK(projcurve_model_skipped_count(NULL) == 0);
    CHECK(projcurve_model_surface(NULL, 0) == NULL);
    CHECK(projcurve_model_curve(NULL, 0) == NULL);
    CHECK(projcurve_model_skipped(NULL, 0) == NULL);
    projcurve_model_destroy(NULL);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    api_misuse();
    step_cases();
    teapot_cases();
    gismo_cases();
    garbage();
    mutate("cases/song_yong_example1.igs", 400, 1);
    mutate("cases/nurbs_half_cylinder_down.igs", 200, 2);
    mutate("real/test-joinsurf_01.stp", 150, 3);
    mutate("real/horn.xml", 100, 4);
    mutate("real/teapot_newell_spd.txt", 200, 5);
    iges_cases();
    reference_bombs();
    pointers_and_counts();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_malformed");
}
