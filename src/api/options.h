/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The layout behind the public options handle, and its resolution into the
 * engine's parameters (common/params.h). Only src/api/ sees it.
 */
#ifndef PC_API_OPTIONS_H
#define PC_API_OPTIONS_H

#include "common/params.h"
#include "projcurve.h"

struct projcurve_options {
    /* what the engine reads (common/params.h); tol_distance 0 is unset,
     * automatic (the setters reject 0) */
    PC_PARAMS_OPTIONS(PC_PARAMS_DECLARE_FIELD)
    double time_limit;         /* seconds per call, 0 = none: PROJCURVE_OPT_TIME_LIMIT */
    long long max_work;        /* units per call, 0 = none: PROJCURVE_OPT_MAX_WORK */
    projcurve_progress_fn progress; /* projcurve_options_set_progress; NULL = none */
    void *progress_user;
    /* No option key, not in the public API: 0 skips the compact fits
     * (pc_params.compact), so that the benchmark can time what they add.
     * 1 (the default) in every projection a caller can ask for. */
    long long compact;
};

/* Fills o with every default (used when the caller passes NULL options). */
void pc_options_defaults(struct projcurve_options *o);

/* Checks every value of o against the bounds projcurve_option_info tells
 * (a handle can only hold valid values; this guards against a corrupted
 * one). Statuses: OK, OUT_OF_RANGE, NOT_FINITE, with the option's name. */
projcurve_status pc_options_check(projcurve_context *ctx, const struct projcurve_options *o);

/* The engine's parameters from o: every option the engine reads, eps_D as
 * set (0 while unset), no budget. */
void pc_options_to_params(const struct projcurve_options *o, pc_params *p);

#endif /* PC_API_OPTIONS_H */
