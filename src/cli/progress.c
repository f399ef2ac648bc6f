/* SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* fileno */

#include <string.h>
#include <unistd.h>

#include "progress.h"

int cli_progress_init(cli_progress *p, FILE *out, const cli_job *job, int forced)
{
    memset(p, 0, sizeof *p);
    p->out = out;
    p->job = job;
    p->terminal = isatty(fileno(out));
    p->delay_ms = forced ? 0.0 : CLI_PROGRESS_DELAY_MS;
    p->start_ms = cli_now_ms();
    p->drawn_ms = -1e300;
    return forced || p->terminal;
}

/* Draws the line for the fraction f of the current pair, when it is time. */
static void draw(cli_progress *p, double f, int now_or_never)
{
    const double now = cli_now_ms();
    if (now - p->start_ms < p->delay_ms)
        return;
    if (!now_or_never && now - p->drawn_ms < CLI_PROGRESS_REDRAW_MS)
        return;
    p->drawn_ms = now;
    const cli_job *job = p->job;
    const size_t ns = job->n_surfaces ? job->n_surfaces : 1;
    const double overall = p->n_pairs ? ((double)p->pair + f) / (double)p->n_pairs : 1.0;
    char line[160];
    int len = snprintf(line, sizeof line, "projcurve: %3.0f%% (pair %zu of %zu: curve %zu onto "
                                          "surface %zu)",
                       100.0 * overall, p->pair + 1, p->n_pairs,
                       cli_curve_number(job, p->pair / ns), cli_surface_number(job, p->pair % ns));
    if (len < 0)
        return;
    if ((size_t)len >= sizeof line)
        len = (int)sizeof line - 1;
    if (p->terminal) {
        /* redrawn in place, padded over a longer previous line */
        const int pad = p->width > (size_t)len ? (int)(p->width - (size_t)len) : 0;
        fprintf(p->out, "\r%s%*s", line, pad, "");
    } else {
        fprintf(p->out, "%s\n", line); /* a log: one line each */
    }
    fflush(p->out);
    p->width = (size_t)len;
}

void cli_progress_pair(void *user, size_t k, size_t n)
{
    cli_progress *p = user;
    p->pair = k;
    p->n_pairs = n;
    draw(p, 0.0, 0);
}

int cli_progress_call(void *user, double fraction_done)
{
    cli_progress *p = user;
    draw(p, fraction_done >= 0.0 && fraction_done <= 1.0 ? fraction_done : 0.0, 0);
    return 0;
}

void cli_progress_finish(cli_progress *p)
{
    if (p->width == 0)
        return;
    if (p->terminal) {
        fprintf(p->out, "\r%*s\r", (int)p->width, "");
    } else {
        /* a log keeps the last state: where the run ended */
        draw(p, p->job->n_pairs && p->job->pairs ? 1.0 : 0.0, 1);
    }
    fflush(p->out);
    p->width = 0;
}
