/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Contexts hold all error state: threads that each use their own context see
 * only their own failures, and read-only options are shared safely. Each
 * thread provokes failures with values unique to it and checks that its
 * context reports exactly those (a global message buffer would mix them up).
 */
#include "check.h"
#include "projcurve.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

#define N_THREADS 4
#define N_ROUNDS 2000

typedef struct worker {
    int id;
    const projcurve_options *shared; /* read by every thread */
    int mismatches;
} worker;

static void *work(void *arg)
{
    worker *w = arg;
    projcurve_context *ctx = NULL;
    projcurve_options *own = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK ||
        projcurve_options_create(ctx, &own) != PROJCURVE_OK) {
        w->mismatches = N_ROUNDS;
        goto done;
    }
    for (int round = 0; round < N_ROUNDS; ++round) {
        /* Out of range for NEWTON_MAX_ITER ([1, 200]) and unique per thread/round. */
        const long long bad = 1000 + (long long)w->id * N_ROUNDS + round;
        char expected[32];
        snprintf(expected, sizeof expected, " %lld ", bad);
        long long shared_iter = 0;
        if (projcurve_options_set_int(ctx, own, PROJCURVE_OPT_NEWTON_MAX_ITER, bad) !=
                PROJCURVE_ERR_OUT_OF_RANGE ||
            strstr(projcurve_context_message(ctx), expected) == NULL ||
            projcurve_options_get_int(ctx, w->shared, PROJCURVE_OPT_NEWTON_MAX_ITER,
                                      &shared_iter) != PROJCURVE_OK ||
            shared_iter != 20)
            ++w->mismatches;
        projcurve_context_clear(ctx);
    }
done:
    projcurve_options_destroy(own);
    projcurve_context_destroy(ctx);
    return NULL;
}

int main(void)
{
    projcurve_options *shared = NULL;
    CHECK_OK(projcurve_options_create(NULL, &shared));
    worker workers[N_THREADS];
    pthread_t threads[N_THREADS];
    for (int i = 0; i < N_THREADS; ++i) {
        workers[i] = (worker){.id = i, .shared = shared, .mismatches = 0};
        CHECK(pthread_create(&threads[i], NULL, work, &workers[i]) == 0);
    }
    for (int i = 0; i < N_THREADS; ++i) {
        CHECK(pthread_join(threads[i], NULL) == 0);
        CHECK(workers[i].mismatches == 0);
    }
    projcurve_options_destroy(shared);
    return pc_test_finish("test_api_threads");
}
