/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Status strings, version query, contexts and options: every documented
 * status of these functions, including each bad input (NULL handles and
 * pointers, unknown keys, wrong types, NaN/inf, out-of-range values, wrong
 * major version). Expected bounds and defaults are copied from the
 * documentation in projcurve.h, not from the implementation's table.
 */
#include "check.h"
#include "projcurve.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PC_LAST_STATUS PROJCURVE_ERR_CANCELLED

static void test_status_strings(void)
{
    for (int a = 0; a <= (int)PC_LAST_STATUS; ++a) {
        const char *name = projcurve_status_string((projcurve_status)a);
        CHECK(name != NULL && name[0] != '\0');
        CHECK(strcmp(name, "unknown status") != 0);
        for (int b = 0; b < a; ++b)
            CHECK(strcmp(name, projcurve_status_string((projcurve_status)b)) != 0);
    }
    CHECK(strcmp(projcurve_status_string(PROJCURVE_OK), "ok") == 0);
    CHECK(strcmp(projcurve_status_string((projcurve_status)(PC_LAST_STATUS + 1)),
                 "unknown status") == 0);
    CHECK(strcmp(projcurve_status_string((projcurve_status)-1), "unknown status") == 0);
    CHECK(strcmp(projcurve_status_string((projcurve_status)1000000), "unknown status") == 0);
}

static void test_version(void)
{
    CHECK(projcurve_version_number() == PROJCURVE_VERSION_NUMBER);
    CHECK(strcmp(projcurve_version_string(), PROJCURVE_VERSION_STRING) == 0);
    char expected[64];
    snprintf(expected, sizeof expected, "%d.%d.%d", PROJCURVE_VERSION_MAJOR,
             PROJCURVE_VERSION_MINOR, PROJCURVE_VERSION_PATCH);
    CHECK(strcmp(projcurve_version_string(), expected) == 0);
    CHECK(projcurve_version_number() / 10000u == (unsigned)PROJCURVE_VERSION_MAJOR);
}

static void test_context(void)
{
    projcurve_context *ctx = NULL;
    CHECK_STATUS(projcurve_context_create(PROJCURVE_VERSION_MAJOR, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context *untouched = (projcurve_context *)&ctx; /* any non-NULL marker */
    projcurve_context *out = untouched;
    CHECK_STATUS(projcurve_context_create(PROJCURVE_VERSION_MAJOR + 1, &out),
                 PROJCURVE_ERR_VERSION);
    CHECK(out == untouched);
    CHECK_STATUS(projcurve_context_create(0u, &out), PROJCURVE_ERR_VERSION);
    CHECK(out == untouched);

    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK(ctx != NULL);
    CHECK_OK(projcurve_context_status(ctx));
    CHECK(strcmp(projcurve_context_message(ctx), "") == 0);

    /* A failure is recorded with a message that names the culprit... */
    projcurve_options *opts = NULL;
    CHECK_STATUS(projcurve_options_create(ctx, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_context_status(ctx), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "out") != NULL);
    /* ...survives a later successful call... */
    CHECK_OK(projcurve_options_create(ctx, &opts));
    CHECK_STATUS(projcurve_context_status(ctx), PROJCURVE_ERR_NULL_ARGUMENT);
    /* ...is replaced by the next failure, and forgotten by clear. */
    CHECK_STATUS(projcurve_options_set_int(ctx, opts, (projcurve_option)99, 1),
                 PROJCURVE_ERR_UNKNOWN_OPTION);
    CHECK_STATUS(projcurve_context_status(ctx), PROJCURVE_ERR_UNKNOWN_OPTION);
    CHECK(strstr(projcurve_context_message(ctx), "99") != NULL);
    projcurve_context_clear(ctx);
    CHECK_OK(projcurve_context_status(ctx));
    CHECK(strcmp(projcurve_context_message(ctx), "") == 0);

    /* NULL context: calls work, nothing is kept. */
    CHECK(strcmp(projcurve_context_message(NULL), "no context") == 0);
    CHECK_STATUS(projcurve_context_status(NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context_clear(NULL);
    CHECK_STATUS(projcurve_options_set_int(NULL, opts, (projcurve_option)99, 1),
                 PROJCURVE_ERR_UNKNOWN_OPTION);

    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    projcurve_context_destroy(NULL);
}

/* One row per option, from the comments in projcurve.h. */
typedef struct option_case {
    projcurve_option key;
    projcurve_option_type type;
    double min_value, max_value, default_value;
    int min_exclusive;
} option_case;

static const option_case option_cases[] = {
    {PROJCURVE_OPT_TOL_DISTANCE, PROJCURVE_OPTION_DOUBLE, 0.0, 1e300, 0.0, 1}, /* 0: unset */
    {PROJCURVE_OPT_TOL_ANGLE_DEG, PROJCURVE_OPTION_DOUBLE, 0.0, 90.0, 1.0, 1},
    {PROJCURVE_OPT_NEWTON_TOL, PROJCURVE_OPTION_DOUBLE, 1e-15, 1e-3, 1e-12, 0},
    {PROJCURVE_OPT_NEWTON_MAX_ITER, PROJCURVE_OPTION_INTEGER, 1, 200, 20, 0},
    {PROJCURVE_OPT_METHOD, PROJCURVE_OPTION_INTEGER, PROJCURVE_METHOD_SECOND_ORDER,
     PROJCURVE_METHOD_RK4, PROJCURVE_METHOD_SECOND_ORDER, 0},
    {PROJCURVE_OPT_PARAM_STEP, PROJCURVE_OPTION_DOUBLE, 0.0, 1e300, 0.0, 0},
    {PROJCURVE_OPT_ARC_STEP_FRACTION, PROJCURVE_OPTION_DOUBLE, 1e-7, 1.0, 1.0 / 64.0, 0},
    {PROJCURVE_OPT_MAX_POINTS, PROJCURVE_OPTION_INTEGER, 16, 1099511627776.0, 1e5, 0},
    {PROJCURVE_OPT_MAX_PIECES, PROJCURVE_OPTION_INTEGER, 1, 1099511627776.0, 5e4, 0},
    {PROJCURVE_OPT_COMPOSE, PROJCURVE_OPTION_INTEGER, 0, 1, 1, 0},
    {PROJCURVE_OPT_JUMP_DETECTION, PROJCURVE_OPTION_INTEGER, 0, 1, 1, 0},
    {PROJCURVE_OPT_PCURVE_DEGREE, PROJCURVE_OPTION_INTEGER, 1, 3, 3, 0},
    {PROJCURVE_OPT_FOOT_POINTS, PROJCURVE_OPTION_INTEGER, PROJCURVE_FOOT_POINTS_MINIMA,
     PROJCURVE_FOOT_POINTS_ALL, PROJCURVE_FOOT_POINTS_MINIMA, 0},
    {PROJCURVE_OPT_TIME_LIMIT, PROJCURVE_OPTION_DOUBLE, 0.0, 1e9, 0.0, 0},
    {PROJCURVE_OPT_MAX_WORK, PROJCURVE_OPTION_INTEGER, 0, 1099511627776.0, 0, 0},
    {PROJCURVE_OPT_CURVE_DEGREE, PROJCURVE_OPTION_INTEGER, 1, 25, 5, 0},
    {PROJCURVE_OPT_HITS, PROJCURVE_OPTION_INTEGER, PROJCURVE_HITS_ALL, PROJCURVE_HITS_NEAREST,
     PROJCURVE_HITS_ALL, 0},
    {PROJCURVE_OPT_MAX_DISTANCE, PROJCURVE_OPTION_DOUBLE, 0.0, 1e300, 0.0, 0},
    {PROJCURVE_OPT_THREADS, PROJCURVE_OPTION_INTEGER, 1, 1024, 1, 0},
};
#define N_OPTION_CASES (sizeof option_cases / sizeof option_cases[0])

static void test_option_info(void)
{
    for (size_t i = 0; i < N_OPTION_CASES; ++i) {
        const option_case *c = &option_cases[i];
        projcurve_option_type type = (projcurve_option_type)-1;
        double lo = NAN, hi = NAN, def = NAN;
        CHECK_OK(projcurve_option_info(NULL, c->key, &type, &lo, &hi, &def));
        CHECK(type == c->type);
        CHECK(lo == c->min_value);
        CHECK(hi == c->max_value);
        CHECK(def == c->default_value);
        /* Every output may be NULL. */
        CHECK_OK(projcurve_option_info(NULL, c->key, NULL, NULL, NULL, NULL));
    }
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const int unknown[] = {0, -1, 500, 1000};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
        double untouched = 42.0;
        CHECK_STATUS(projcurve_option_info(ctx, (projcurve_option)unknown[i], NULL, NULL, NULL,
                                           &untouched),
                     PROJCURVE_ERR_UNKNOWN_OPTION);
        CHECK(untouched == 42.0);
        CHECK(strstr(projcurve_context_message(ctx), "unknown option") != NULL);
    }
    projcurve_context_destroy(ctx);
}

/* Defaults, valid and invalid values of one double option. */
static void check_double_option(projcurve_context *ctx, projcurve_options *opts,
                                const option_case *c)
{
    double v = NAN;
    long long iv = 0;
    CHECK_OK(projcurve_options_get_double(ctx, opts, c->key, &v));
    CHECK(v == c->default_value);
    CHECK_STATUS(projcurve_options_get_int(ctx, opts, c->key, &iv), PROJCURVE_ERR_WRONG_KIND);
    CHECK_STATUS(projcurve_options_set_int(ctx, opts, c->key, 1), PROJCURVE_ERR_WRONG_KIND);

    CHECK_OK(projcurve_options_set_double(ctx, opts, c->key, c->max_value));
    CHECK_OK(projcurve_options_get_double(ctx, opts, c->key, &v));
    CHECK(v == c->max_value);
    if (!c->min_exclusive) {
        CHECK_OK(projcurve_options_set_double(ctx, opts, c->key, c->min_value));
        CHECK_OK(projcurve_options_get_double(ctx, opts, c->key, &v));
        CHECK(v == c->min_value);
    }
    const double mid = 0.5 * (c->min_value + c->max_value);
    CHECK_OK(projcurve_options_set_double(ctx, opts, c->key, mid));

    /* Rejected values leave the option at mid. */
    const double bad[] = {nextafter(c->max_value, INFINITY),
                          c->min_exclusive ? c->min_value : nextafter(c->min_value, -INFINITY),
                          -1.0, 1e308};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        CHECK_STATUS(projcurve_options_set_double(ctx, opts, c->key, bad[i]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
        CHECK(strstr(projcurve_context_message(ctx), "outside") != NULL);
    }
    const double not_finite[] = {NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < 3; ++i) {
        if (c->key == PROJCURVE_OPT_MAX_DISTANCE && not_finite[i] == INFINITY) {
            /* +inf is "no limit", stored as its 0 (projcurve.h) */
            CHECK_OK(projcurve_options_set_double(ctx, opts, c->key, INFINITY));
            CHECK_OK(projcurve_options_get_double(ctx, opts, c->key, &v));
            CHECK(v == 0.0);
            CHECK_OK(projcurve_options_set_double(ctx, opts, c->key, mid));
            continue;
        }
        CHECK_STATUS(projcurve_options_set_double(ctx, opts, c->key, not_finite[i]),
                     PROJCURVE_ERR_NOT_FINITE);
    }
    CHECK_OK(projcurve_options_get_double(ctx, opts, c->key, &v));
    CHECK(v == mid);
}

/* Defaults, valid and invalid values of one integer option. */
static void check_int_option(projcurve_context *ctx, projcurve_options *opts,
                             const option_case *c)
{
    long long v = -7;
    double dv = 0.0;
    const long long lo = (long long)c->min_value, hi = (long long)c->max_value;
    CHECK_OK(projcurve_options_get_int(ctx, opts, c->key, &v));
    CHECK(v == (long long)c->default_value);
    CHECK_STATUS(projcurve_options_get_double(ctx, opts, c->key, &dv), PROJCURVE_ERR_WRONG_KIND);
    CHECK_STATUS(projcurve_options_set_double(ctx, opts, c->key, 1.0), PROJCURVE_ERR_WRONG_KIND);
    CHECK(strstr(projcurve_context_message(ctx), "integer") != NULL);

    CHECK_OK(projcurve_options_set_int(ctx, opts, c->key, hi));
    CHECK_OK(projcurve_options_get_int(ctx, opts, c->key, &v));
    CHECK(v == hi);
    CHECK_OK(projcurve_options_set_int(ctx, opts, c->key, lo));
    CHECK_OK(projcurve_options_get_int(ctx, opts, c->key, &v));
    CHECK(v == lo);

    const long long bad[] = {hi + 1, lo - 1, -1000000, 1LL << 62};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        CHECK_STATUS(projcurve_options_set_int(ctx, opts, c->key, bad[i]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
        CHECK(strstr(projcurve_context_message(ctx), "outside") != NULL);
    }
    CHECK_OK(projcurve_options_get_int(ctx, opts, c->key, &v));
    CHECK(v == lo);
}

static void test_options_values(void)
{
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &opts));
    for (size_t i = 0; i < N_OPTION_CASES; ++i) {
        if (option_cases[i].type == PROJCURVE_OPTION_DOUBLE)
            check_double_option(ctx, opts, &option_cases[i]);
        else
            check_int_option(ctx, opts, &option_cases[i]);
    }
    /* Setting one option leaves the others alone. */
    projcurve_options *fresh = NULL;
    CHECK_OK(projcurve_options_create(NULL, &fresh));
    CHECK_OK(projcurve_options_set_double(ctx, fresh, PROJCURVE_OPT_TOL_ANGLE_DEG, 5.0));
    double v = 0.0;
    long long iv = 0;
    CHECK_OK(projcurve_options_get_double(ctx, fresh, PROJCURVE_OPT_NEWTON_TOL, &v));
    CHECK(v == 1e-12);
    CHECK_OK(projcurve_options_get_int(ctx, fresh, PROJCURVE_OPT_MAX_POINTS, &iv));
    CHECK(iv == 100000);
    projcurve_options_destroy(fresh);
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
}

/* PCURVE_DEGREE takes 1 or 3: the 2 inside its bounds is refused too. */
static void test_pcurve_degree_choices(void)
{
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &opts));
    CHECK_OK(projcurve_options_set_int(ctx, opts, PROJCURVE_OPT_PCURVE_DEGREE, 1));
    const long long bad[] = {2, 0, 4, -3};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        CHECK_STATUS(projcurve_options_set_int(ctx, opts, PROJCURVE_OPT_PCURVE_DEGREE, bad[i]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK(strstr(projcurve_context_message(ctx), "PCURVE_DEGREE") != NULL);
    long long v = 0;
    CHECK_OK(projcurve_options_get_int(ctx, opts, PROJCURVE_OPT_PCURVE_DEGREE, &v));
    CHECK(v == 1); /* the bad values left the 1 set (not the default 3) */
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
}

static void test_options_bad_handles(void)
{
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &opts));
    double v = 3.0;
    long long iv = 3;
    const projcurve_option k_d = PROJCURVE_OPT_TOL_ANGLE_DEG, k_i = PROJCURVE_OPT_COMPOSE;

    CHECK_STATUS(projcurve_options_set_double(ctx, NULL, k_d, 1.0), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "options") != NULL);
    CHECK_STATUS(projcurve_options_set_int(ctx, NULL, k_i, 1), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_options_get_double(ctx, NULL, k_d, &v), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_options_get_int(ctx, NULL, k_i, &iv), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_options_get_double(ctx, opts, k_d, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(strstr(projcurve_context_message(ctx), "value") != NULL);
    CHECK_STATUS(projcurve_options_get_int(ctx, opts, k_i, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(v == 3.0 && iv == 3);

    const int unknown[] = {0, -5, 500, 77};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
        const projcurve_option k = (projcurve_option)unknown[i];
        CHECK_STATUS(projcurve_options_set_double(ctx, opts, k, 1.0), PROJCURVE_ERR_UNKNOWN_OPTION);
        CHECK_STATUS(projcurve_options_set_int(ctx, opts, k, 1), PROJCURVE_ERR_UNKNOWN_OPTION);
        CHECK_STATUS(projcurve_options_get_double(ctx, opts, k, &v), PROJCURVE_ERR_UNKNOWN_OPTION);
        CHECK_STATUS(projcurve_options_get_int(ctx, opts, k, &iv), PROJCURVE_ERR_UNKNOWN_OPTION);
    }
    CHECK(v == 3.0 && iv == 3);
    projcurve_options_destroy(opts);
    projcurve_options_destroy(NULL);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    test_status_strings();
    test_version();
    test_context();
    test_option_info();
    test_options_values();
    test_options_bad_handles();
    test_pcurve_degree_choices();
    return pc_test_finish("test_api_basics");
}
