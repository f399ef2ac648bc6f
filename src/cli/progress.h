/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The progress line of projcurve project on stderr: "projcurve: 42% (pair
 * 3 of 12: curve 0 onto surface 2)", redrawn in place ("\r") at most every
 * CLI_PROGRESS_REDRAW_MS, fed by the library's progress callback
 * (projcurve_options_set_progress) within each call and by cli_job's
 * pair_started between calls. It appears once the run has lasted
 * CLI_PROGRESS_DELAY_MS (a short run prints nothing), or from the start when
 * forced, and is erased (on a terminal) or ended with a newline when the
 * run is over, before the summary.
 */
#ifndef PC_CLI_PROGRESS_H
#define PC_CLI_PROGRESS_H

#include <stdio.h>

#include "cli.h"

#define CLI_PROGRESS_DELAY_MS 1000.0
#define CLI_PROGRESS_REDRAW_MS 100.0

typedef struct cli_progress {
    FILE *out;
    const cli_job *job;
    int terminal;    /* out is a terminal: erase the line at the end */
    double delay_ms; /* from the start of the run to the first line */
    double start_ms, drawn_ms;
    size_t pair, n_pairs;
    size_t width;    /* characters of the last line drawn, 0: none yet */
} cli_progress;

/* Prepares p for job; returns 1 when a progress line may be drawn: forced,
 * or out is a terminal. Then set job->pair_started = cli_progress_pair,
 * job->pair_user = p, and the library's callback to cli_progress_call. */
int cli_progress_init(cli_progress *p, FILE *out, const cli_job *job, int forced);
void cli_progress_pair(void *user, size_t k, size_t n);
/* The library's progress callback: never asks to stop (returns 0). */
int cli_progress_call(void *user, double fraction_done);
/* Erases (terminal) or ends (otherwise) the line, if one was drawn. */
void cli_progress_finish(cli_progress *p);

#endif /* PC_CLI_PROGRESS_H */
