/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The command's run and summary (src/cli/run.c, report_json.c) when memory
 * runs out, white-box: the command's own allocations go through the
 * allocation hook (src/common/alloc_hook.h, force-included into those
 * sources by the build), which this test fails on demand.
 *   - cli_run used to set n_pairs before its calloc; when the calloc failed
 *     cli_job_free walked a NULL array (a segfault). Now the job stays
 *     empty and free is safe, also when n_surfaces * n_curves overflows.
 *   - A branch whose measurement failed (an allocation) used to count as a
 *     residual of 0, so the summary said "max residual 0, max deviation 0"
 *     and the command exited 0; now it is NaN, counted as not measured,
 *     and the summary says so (the caller exits 1 on it).
 *   - The numbers a job reports are the user's (--surface 7 reports
 *     "surface": 7, not 0), pair_started sees every call in order, and the
 *     summary can be counted without being printed (--quiet).
 *   - The argument parsers refuse what is not exactly the numbers asked for.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "cli.h"
#include "projcurve.h"

/* Allocations of the command's sources counted while armed; the
 * fail_at-th (1-based) fails. The library's own are never failed here. */
static int armed;
static long n_allocs, fail_at;

int pc_alloc_hook_fail(const char *file, int line);
int pc_alloc_hook_fail(const char *file, int line)
{
    (void)line;
    if (!armed || strstr(file, "cli/") == NULL)
        return 0;
    return ++n_allocs == fail_at;
}

static void arm(long n)
{
    armed = 1;
    n_allocs = 0;
    fail_at = n;
}

static projcurve_context *ctx;

/* The plane z = 0 over [0, 1]^2 and a line above it, projected along -z:
 * one branch, exactly on the plane. */
static const double plane_net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
static const double line_net[] = {0.1, 0.2, 1, 0.8, 0.7, 1};
static const double knots[] = {0, 0, 1, 1};

static void make_job(cli_job *job, const projcurve_surface **s, const projcurve_curve **c)
{
    memset(job, 0, sizeof *job);
    job->surfaces = s;
    job->n_surfaces = 1;
    job->curves = c;
    job->n_curves = 1;
    job->dir[2] = -1.0;
}

static void test_run_without_memory(const projcurve_surface **s, const projcurve_curve **c)
{
    cli_job job;
    make_job(&job, s, c);
    arm(1); /* the pairs' calloc */
    CHECK(cli_run(ctx, &job) == 0);
    armed = 0;
    CHECK(job.pairs == NULL);
    CHECK(job.n_pairs == 0);
    cli_job_free(&job); /* used to walk job.pairs[0] of a NULL array */

    /* n_surfaces * n_curves overflows: refused before any allocation. */
    make_job(&job, s, c);
    job.n_surfaces = SIZE_MAX / 2 + 1;
    job.n_curves = 2;
    CHECK(cli_run(ctx, &job) == 0);
    CHECK(job.pairs == NULL && job.n_pairs == 0);
    cli_job_free(&job);
}

/* The summary line printed for job, and the count it returns. */
static size_t summary(const cli_job *job, char *text, size_t cap)
{
    FILE *f = tmpfile();
    CHECK(f != NULL);
    if (f == NULL)
        return SIZE_MAX;
    const size_t unmeasured = cli_print_summary(ctx, job, f);
    rewind(f);
    const size_t got = fread(text, 1, cap - 1, f);
    text[got] = '\0';
    fclose(f);
    return unmeasured;
}

static void test_measure(const projcurve_surface **s, const projcurve_curve **c)
{
    cli_job job;
    make_job(&job, s, c);
    CHECK(cli_run(ctx, &job) == 1);
    CHECK(job.n_pairs == 1 && job.failures == 0);
    CHECK(projcurve_result_branch_count(job.pairs[0].result) == 1);

    /* Measured: the branch lies on the plane under the line. */
    cli_branch_quality q;
    CHECK(cli_branch_measure(ctx, &job, &job.pairs[0], 0, &q) == 1);
    CHECK(q.residual >= 0.0 && q.residual <= 1e-12);
    CHECK(q.deviation >= 0.0 && q.deviation <= 1e-12);
    char text[1024];
    CHECK(summary(&job, text, sizeof text) == 0);
    CHECK(strstr(text, "1 branch(es)") != NULL);
    CHECK(strstr(text, "could not be measured") == NULL);

    /* The measurement's point buffer cannot be allocated: unknown, not 0. */
    arm(1);
    CHECK(cli_branch_measure(ctx, &job, &job.pairs[0], 0, &q) == 0);
    armed = 0;
    CHECK(isnan(q.residual));
    CHECK(q.deviation < 0.0);
    arm(1);
    const size_t unmeasured = summary(&job, text, sizeof text);
    armed = 0;
    CHECK(unmeasured == 1);
    if (strstr(text, "max residual -") == NULL || strstr(text, "1 branch(es) could not be") == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "summary without memory: %s", text);

    /* A pair without result (a failed call) and a branch past the end. */
    CHECK(cli_branch_measure(ctx, &job, &job.pairs[0], 1, &q) == 0);
    CHECK(isnan(q.residual));
    cli_job_free(&job);
    CHECK(job.pairs == NULL && job.n_pairs == 0);
}

static int calls_seen[4];
static size_t calls_n;

static void count_pair(void *user, size_t k, size_t n)
{
    (void)user;
    if (k < 4)
        ++calls_seen[k];
    calls_n = n;
}

static void test_numbers(const projcurve_surface **s, const projcurve_curve **c)
{
    cli_job job;
    make_job(&job, s, c);
    const size_t surface_number = 7, curve_number = 3;
    job.surface_numbers = &surface_number;
    job.curve_numbers = &curve_number;
    job.pair_started = count_pair;
    CHECK(cli_run(ctx, &job) == 1);
    CHECK(calls_seen[0] == 1 && calls_seen[1] == 0 && calls_n == 1);
    CHECK(job.timeouts == 0);
    CHECK(cli_print_summary(ctx, &job, NULL) == 0);
    /* cli_write_json takes a path: a file beside the test, removed after */
    const char *path = "test_cli_run_numbers.json";
    char text[4096];
    CHECK(cli_write_json(ctx, &job, path) == 1);
    FILE *in = fopen(path, "r");
    const size_t got = in ? fread(text, 1, sizeof text - 1, in) : 0;
    text[got] = '\0';
    if (in)
        fclose(in);
    remove(path);
    if (strstr(text, "\"surface\": 7, \"curve\": 3") == NULL ||
        strstr(text, "\"timeouts\": 0") == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "JSON without the user's numbers: %s", text);
    cli_job_free(&job);
}

static void test_parsers(void)
{
    size_t i = 99;
    double v[6];
    CHECK(cli_parse_index("0", &i) && i == 0);
    CHECK(cli_parse_index("12", &i) && i == 12);
    CHECK(!cli_parse_index("", &i) && !cli_parse_index("-1", &i) && !cli_parse_index("1.5", &i));
    CHECK(!cli_parse_index("+3", &i) && !cli_parse_index("3 ", &i));
    CHECK(!cli_parse_index("99999999999999999999999", &i)); /* no wrap-around */
    CHECK(cli_parse_reals("1,2,3,4,5,6", 6, v) && v[0] == 1 && v[5] == 6);
    CHECK(!cli_parse_reals("1,2,3,4,5", 6, v) && !cli_parse_reals("1,2,3,4,5,6,7", 6, v));
    CHECK(!cli_parse_reals("1,2,3,4,5,nan", 6, v) && !cli_parse_reals("1,2,3,4,5,1e999", 6, v));
    CHECK(!cli_parse_reals("1,,3", 3, v) && !cli_parse_reals("", 0, v));
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_surface *plane = NULL;
    projcurve_curve *line = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, plane_net, NULL, knots, knots,
                                            &plane));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, line_net, NULL, knots, &line));
    const projcurve_surface *s[1] = {plane};
    const projcurve_curve *c[1] = {line};
    if (plane != NULL && line != NULL) {
        test_run_without_memory(s, c);
        test_measure(s, c);
        test_numbers(s, c);
    }
    test_parsers();
    projcurve_curve_destroy(line);
    projcurve_surface_destroy(plane);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_cli_run");
}
