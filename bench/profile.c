/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Per-stage profile of a case (profile.h).
 */
#define _POSIX_C_SOURCE 200809L
#include "profile.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "api/project.h"
#include "common/vec.h"
#include "deviation.h"
#include "directional/directional_project.h"
#include "geom/surface.h"
#include "ortho/ortho_project.h"

/* The most calls one profile averages (a call of a few microseconds). */
#define PCB_PROFILE_MAX_CALLS 100000

static double thread_cpu_s(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One call of the case through the engine with the stage clock set. */
static projcurve_status profiled_call(projcurve_context *ctx, const pcb_case *c,
                                      const projcurve_options *opts, pc_stage_clock *clock,
                                      projcurve_result **out)
{
    pc_params p;
    pc_budget budget;
    projcurve_status st = pc_projection_params(ctx, opts, c->surface->size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    p.stages = clock;
    if (c->orthogonal)
        return pc_ortho_project(ctx, c->surface, c->curve, &p, out);
    const pc_vec3 dir = vec3_normalize(vec3(c->dir[0], c->dir[1], c->dir[2]));
    return pc_directional_project(ctx, c->surface, c->curve, dir, &p, out);
}

/* The shape figures of the last result. */
static void result_figures(projcurve_context *ctx, const projcurve_result *r, pcb_profile *out)
{
    projcurve_result_stat(ctx, r, PROJCURVE_STAT_PIECES, &out->pieces);
    projcurve_result_stat(ctx, r, PROJCURVE_STAT_POINTS, &out->points);
    pcb_result_curves rc = {NULL, 0};
    if (pcb_result_compact_curves_init(ctx, r, &rc, &out->poles, NULL, &out->pcurve_poles,
                                       NULL) != PROJCURVE_OK)
        out->poles = out->pcurve_poles = NAN;
    pcb_result_curves_free(&rc);
}

int pcb_profile_case(const pcb_case *c, double tol, int quick, double min_s, pcb_profile *out,
                     char *status, size_t status_size)
{
    memset(out, 0, sizeof *out);
    out->tol = tol;
    out->poles = out->pcurve_poles = NAN;
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    projcurve_status st = pcb_case_options(ctx, c, &opts);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_double(ctx, opts, PROJCURVE_OPT_TOL_DISTANCE, tol);
    pc_stage_clock clock;
    memset(&clock, 0, sizeof clock);
    double total = 0.0;
    size_t calls = 0;
    /* one untimed warm-up call, whose result gives the shape figures */
    projcurve_result *r = NULL;
    if (st == PROJCURVE_OK)
        st = profiled_call(ctx, c, opts, NULL, &r);
    if (st == PROJCURVE_OK)
        result_figures(ctx, r, out);
    projcurve_result_destroy(r);
    const size_t least = quick ? 1 : 3;
    while (st == PROJCURVE_OK && calls < PCB_PROFILE_MAX_CALLS &&
           (calls < least || (!quick && total < min_s))) {
        r = NULL;
        const double t0 = thread_cpu_s();
        st = profiled_call(ctx, c, opts, &clock, &r);
        total += thread_cpu_s() - t0;
        projcurve_result_destroy(r);
        ++calls;
    }
    if (st != PROJCURVE_OK)
        snprintf(status, status_size, "%s: %s", projcurve_status_string(st),
                 projcurve_context_message(ctx));
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    if (st != PROJCURVE_OK || calls == 0)
        return -1;
    out->calls = (double)calls;
    out->total_ms = 1e3 * total / (double)calls;
    double known = 0.0;
    for (int s = 0; s < PC_STAGE_COUNT; ++s) {
        out->stage_ms[s] = 1e3 * clock.seconds[s] / (double)calls;
        if (s != PC_STAGE_OTHER)
            known += out->stage_ms[s];
    }
    out->stage_ms[PC_STAGE_OTHER] = fmax(0.0, out->total_ms - known);
    return 0;
}

void pcb_profile_print_header(void)
{
    printf("%-30s %-6s %9s %9s", "case", "at", "eps_D", "total_ms");
    for (int s = 0; s < PC_STAGE_COUNT; ++s)
        printf(" %8.8s", pc_stage_name((pc_stage)s));
    printf(" %7s %6s %6s\n", "pieces", "poles", "uv_pl");
}

void pcb_profile_print(const char *name, const char *label, const pcb_profile *p)
{
    printf("%-30s %-6s %9.2e %9.3f", name, label, p->tol, p->total_ms);
    for (int s = 0; s < PC_STAGE_COUNT; ++s)
        printf(" %8.3f", p->stage_ms[s]);
    printf(" %7.0f %6.0f %6.0f\n", p->pieces, p->poles, p->pcurve_poles);
}
