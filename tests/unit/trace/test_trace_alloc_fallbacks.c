/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A failed allocation never changes a result: surface and curve creation
 * plus a directional projection (with the length estimate and the jump
 * criteria) are run once to count their allocations, then once per
 * allocation with exactly that one failing. Each run must end with
 * PROJCURVE_ERR_NO_MEMORY or give the reference result bit for bit. The
 * span-polynomial tables ("NULL only costs speed") and the control-polygon
 * hits of the jump criteria used to fall back silently to other rounding
 * or other steps (189 pieces instead of 187 on a real model).
 *
 * The allocator is interposed in this executable (glibc's __libc_*); the
 * sanitizers interpose it themselves, so the test is skipped there.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PC_NO_INTERPOSE 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define PC_NO_INTERPOSE 1
#endif
#endif

/* Ends the program if a run does not return (each takes milliseconds). */
#define HANG_GUARD_SECONDS 300

#ifndef PC_NO_INTERPOSE
extern void *__libc_malloc(size_t n);
extern void *__libc_calloc(size_t n, size_t size);
extern void *__libc_realloc(void *p, size_t n);

/* Allocations counted while armed; the fail_at-th (1-based) fails. */
static int armed;
static long n_allocs, fail_at;

static int should_fail(void)
{
    return armed && ++n_allocs == fail_at;
}

void *malloc(size_t n)
{
    return should_fail() ? NULL : __libc_malloc(n);
}

void *calloc(size_t n, size_t size)
{
    return should_fail() ? NULL : __libc_calloc(n, size);
}

void *realloc(void *p, size_t n)
{
    return should_fail() ? NULL : __libc_realloc(p, n);
}

static projcurve_context *ctx;

/* The flattened points of every branch, or NULL with *st the failure. */
typedef struct run_result {
    projcurve_status st;
    size_t n_branches, n_values;
    double *values;
} run_result;

static const double curve_pts[] = {5, 10, 30, 30, 40, 30, 60, 60, 30, 95, 90, 30};
static const double curve_knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
/* A bicubic bumpy sheet over [0, 100]^2 (as shape_bumpy of trace_shapes.h,
 * created here so that the allocations are the library's only). */
static double net[3 * 64];
static const double net_knots[12] = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};

static void make_net(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 21);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            net[3 * (j * 8 + i) + 0] = 100.0 * i / 7.0;
            net[3 * (j * 8 + i) + 1] = 100.0 * j / 7.0;
            net[3 * (j * 8 + i) + 2] = pc_test_rng_uniform(&rng, -8.0, 8.0);
        }
}

static projcurve_status collect(const projcurve_result *r, run_result *out)
{
    out->n_branches = projcurve_result_branch_count(r);
    size_t total = 0;
    for (size_t b = 0; b < out->n_branches; ++b) {
        size_t n = 0;
        projcurve_status st = projcurve_result_branch_points(ctx, r, b, 0, NULL, &n);
        if (st != PROJCURVE_OK)
            return st;
        total += n;
    }
    const int dim = projcurve_result_point_dim(r);
    out->n_values = total * (size_t)dim;
    out->values = calloc(out->n_values + 1, sizeof(double));
    if (out->values == NULL)
        return PROJCURVE_ERR_NO_MEMORY;
    size_t at = 0;
    for (size_t b = 0; b < out->n_branches; ++b) {
        size_t n = 0;
        projcurve_status st = projcurve_result_branch_points(ctx, r, b, (out->n_values - at) / dim,
                                                             out->values + at, &n);
        if (st != PROJCURVE_OK)
            return st;
        at += n * (size_t)dim;
    }
    return PROJCURVE_OK;
}

/* Creates the inputs and projects, the allocator armed throughout. */
static run_result run(long fail)
{
    run_result out = {PROJCURVE_OK, 0, 0, NULL};
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    projcurve_result *r = NULL;
    n_allocs = 0;
    fail_at = fail;
    armed = 1;
    const double dir[3] = {0.0, 0.0, -1.0};
    out.st = projcurve_surface_create_nurbs(ctx, 3, 3, 8, 8, net, NULL, net_knots, net_knots, &s);
    if (out.st == PROJCURVE_OK)
        out.st = projcurve_curve_create_nurbs(ctx, 3, 4, curve_pts, NULL, curve_knots, &c);
    if (out.st == PROJCURVE_OK)
        out.st = projcurve_project_directional(ctx, s, c, dir, NULL, &r);
    armed = 0;
    if (out.st == PROJCURVE_OK)
        out.st = collect(r, &out);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return out;
}

int main(void)
{
    pc_test_hang_guard(HANG_GUARD_SECONDS);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    make_net();
    run_result ref = run(0);
    const long total = n_allocs;
    CHECK_OK(ref.st);
    CHECK(ref.n_branches > 0);
    long n_failed = 0, n_same = 0;
    for (long k = 1; k <= total && ref.st == PROJCURVE_OK; ++k) {
        run_result got = run(k);
        if (got.st == PROJCURVE_OK) {
            /* Bit-identical: the same operations on the same inputs. */
            const int same = got.n_branches == ref.n_branches && got.n_values == ref.n_values &&
                             memcmp(got.values, ref.values, ref.n_values * sizeof(double)) == 0;
            if (!same)
                pc_test_fail_at(__FILE__, __LINE__,
                                "allocation %ld of %ld failed silently: %zu branches, %zu values "
                                "(reference %zu, %zu)",
                                k, total, got.n_branches, got.n_values, ref.n_branches,
                                ref.n_values);
            n_same += same;
        } else {
            CHECK(got.st == PROJCURVE_ERR_NO_MEMORY);
            n_failed++;
        }
        free(got.values);
    }
    printf("%ld allocations: %ld runs failed with NO_MEMORY, %ld gave the reference\n", total,
           n_failed, n_same);
    free(ref.values);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_trace_alloc_fallbacks");
}

#else /* PC_NO_INTERPOSE */

int main(void)
{
    pc_test_skip("the sanitizers interpose the allocator themselves");
    return 77;
}

#endif
