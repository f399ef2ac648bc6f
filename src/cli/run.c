/* SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "residual.h"
#include "vec3.h"

int cli_run(projcurve_context *ctx, cli_job *job)
{
    /* n_pairs is set only with the array it counts, so that cli_job_free
     * never walks a NULL or short array. */
    job->pairs = NULL;
    job->n_pairs = 0;
    const size_t n = job->n_surfaces * job->n_curves;
    if (job->n_curves != 0 && n / job->n_curves != job->n_surfaces)
        return 0;
    cli_pair *pairs = calloc(n ? n : 1, sizeof *pairs);
    if (pairs == NULL)
        return 0;
    job->pairs = pairs;
    job->n_pairs = n;
    job->time_ms = 0.0;
    job->failures = 0;
    job->timeouts = 0;
    size_t k = 0;
    for (size_t c = 0; c < job->n_curves; ++c)
        for (size_t s = 0; s < job->n_surfaces; ++s, ++k) {
            cli_pair *p = &job->pairs[k];
            p->surface = s;
            p->curve = c;
            if (job->pair_started)
                job->pair_started(job->pair_user, k, n);
            const double t0 = cli_now_ms();
            if (job->orthogonal)
                p->status = projcurve_project_orthogonal(ctx, job->surfaces[s], job->curves[c],
                                                         job->opts, &p->result);
            else if (job->conical)
                p->status = projcurve_project_conical(ctx, job->surfaces[s], job->curves[c],
                                                      job->eye, job->opts, &p->result);
            else
                p->status = projcurve_project_directional(ctx, job->surfaces[s],
                                                          job->curves[c], job->dir, job->opts,
                                                          &p->result);
            job->time_ms += cli_now_ms() - t0;
            if (p->status != PROJCURVE_OK) {
                const char *why = projcurve_context_message(ctx);
                fprintf(stderr, "projcurve: curve %zu onto surface %zu: %s: %s\n",
                        cli_curve_number(job, c), cli_surface_number(job, s),
                        projcurve_status_string(p->status), why);
                /* the library's message is the only place that tells the
                 * time limit from the work and piece limits */
                if (p->status == PROJCURVE_ERR_LIMIT_REACHED && strstr(why, "time limit"))
                    ++job->timeouts;
                /* A partial result (a size, time or work limit, or a
                 * cancel) is kept and reported. */
                if (p->status != PROJCURVE_ERR_LIMIT_REACHED &&
                    p->status != PROJCURVE_ERR_CANCELLED)
                    p->result = NULL;
                ++job->failures;
            }
            /* places where the projection could not be followed or
             * verified: the result is incomplete there */
            const size_t failed = projcurve_result_failure_count(p->result);
            if (failed > 0)
                fprintf(stderr,
                        "projcurve: curve %zu onto surface %zu: %zu place(s) where the "
                        "projection could not be followed or verified (branches ending or "
                        "starting 'failed')\n",
                        cli_curve_number(job, c), cli_surface_number(job, s), failed);
            job->failures += failed;
        }
    return 1;
}

void cli_job_free(cli_job *job)
{
    for (size_t i = 0; i < job->n_pairs; ++i)
        projcurve_result_destroy(job->pairs[i].result);
    free(job->pairs);
    job->pairs = NULL;
    job->n_pairs = 0;
}

/* The violation of the projection condition at one traced point: the
 * distance of S(u, v) from the line of P(t)'s ray (for the orthogonal kind,
 * residual.h). */
static double residual_at(projcurve_context *ctx, const cli_job *job, const cli_pair *pair,
                          const double tuv[3])
{
    const projcurve_surface *surface = job->surfaces[pair->surface];
    double s[3], p[3];
    if (projcurve_curve_eval(ctx, job->curves[pair->curve], tuv[0], 0, p) != PROJCURVE_OK)
        return INFINITY;
    if (job->orthogonal)
        return cli_orthogonal_residual(ctx, surface, p, tuv[1], tuv[2]);
    if (projcurve_surface_eval(ctx, surface, tuv[1], tuv[2], 0, s) != PROJCURVE_OK)
        return INFINITY;
    if (job->conical) {
        /* distance of S from the line E + lambda (P - E); the library
         * refuses a curve through the eye, so P - E is not zero here */
        const double d[3] = {s[0] - job->eye[0], s[1] - job->eye[1], s[2] - job->eye[2]};
        const double ray[3] = {p[0] - job->eye[0], p[1] - job->eye[1], p[2] - job->eye[2]};
        double c[3];
        cross3(d, ray, c);
        const double len = norm3(ray);
        return len > 0.0 ? norm3(c) / len : INFINITY;
    }
    /* distance of S from the line P + lambda Dir */
    const double d[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
    double c[3];
    cross3(d, job->dir, c);
    return norm3(c) / norm3(job->dir);
}

int cli_branch_measure(projcurve_context *ctx, const cli_job *job, const cli_pair *pair,
                       size_t branch, cli_branch_quality *q)
{
    /* Unknown until measured: a failure below leaves NaN, never a 0 that
     * would read as a perfect branch. */
    q->residual = NAN;
    q->deviation = -1.0;
    size_t n = 0;
    double probe[3];
    if (projcurve_result_branch_points(ctx, pair->result, branch, 0, probe, &n) != PROJCURVE_OK)
        return 0;
    if (n == 0) {
        q->residual = 0.0; /* no traced point: nothing violates the condition */
        return 1;
    }
    if (n > SIZE_MAX / (3 * sizeof(double)))
        return 0;
    double *tuv = malloc(3 * n * sizeof *tuv);
    if (tuv == NULL)
        return 0;
    projcurve_curve *composed = NULL;
    const projcurve_status cst = projcurve_result_branch_curve(ctx, pair->result, branch, &composed);
    /* A branch without composed pieces (INVALID_ARGUMENT) or too short in t
     * to form a curve (OUT_OF_RANGE) has no deviation; any other failure
     * (memory) makes the measurement unknown. */
    int measured = cst == PROJCURVE_OK || cst == PROJCURVE_ERR_INVALID_ARGUMENT ||
                   cst == PROJCURVE_ERR_OUT_OF_RANGE;
    if (cst == PROJCURVE_OK)
        q->deviation = 0.0;
    size_t got = 0;
    if (!measured) {
        /* leave the residual unknown */
    } else if (projcurve_result_branch_points(ctx, pair->result, branch, n, tuv, &got) !=
               PROJCURVE_OK) {
        measured = 0;
    } else {
        q->residual = 0.0;
        double t0 = 0.0, t1 = 0.0;
        if (composed)
            projcurve_curve_domain(ctx, composed, &t0, &t1);
        for (size_t i = 0; i < got; ++i) {
            const double *v = tuv + 3 * i;
            q->residual = fmax(q->residual, residual_at(ctx, job, pair, v));
            double s[3], c[3];
            if (composed && v[0] >= t0 && v[0] <= t1 &&
                projcurve_surface_eval(ctx, job->surfaces[pair->surface], v[1], v[2], 0, s) ==
                    PROJCURVE_OK &&
                projcurve_curve_eval(ctx, composed, v[0], 0, c) == PROJCURVE_OK) {
                const double d[3] = {s[0] - c[0], s[1] - c[1], s[2] - c[2]};
                q->deviation = fmax(q->deviation, norm3(d));
            }
        }
    }
    projcurve_curve_destroy(composed);
    free(tuv);
    if (!measured) {
        q->residual = NAN;
        q->deviation = -1.0;
    }
    return measured;
}

const char *cli_start_name(projcurve_branch_start s)
{
    switch (s) {
    case PROJCURVE_START_CURVE_START: return "curve_start";
    case PROJCURVE_START_JUMP: return "jump";
    case PROJCURVE_START_BOUNDARY: return "boundary";
    case PROJCURVE_START_SILHOUETTE: return "silhouette";
    case PROJCURVE_START_CURVE_CROSSING: return "curve_crossing";
    case PROJCURVE_START_FAILED: return "failed";
    case PROJCURVE_START_TRIM: return "trim";
    case PROJCURVE_START_VISIBLE: return "visible";
    case PROJCURVE_START_MAX_DISTANCE: return "max_distance";
    }
    return "unknown";
}

const char *cli_end_name(projcurve_branch_end e)
{
    switch (e) {
    case PROJCURVE_END_CURVE_END: return "curve_end";
    case PROJCURVE_END_BOUNDARY: return "boundary";
    case PROJCURVE_END_SILHOUETTE: return "silhouette";
    case PROJCURVE_END_CURVATURE_CENTRE: return "curvature_centre";
    case PROJCURVE_END_LIMIT: return "limit";
    case PROJCURVE_END_FAILED: return "failed";
    case PROJCURVE_END_CURVE_CROSSING: return "curve_crossing";
    case PROJCURVE_END_TRIM: return "trim";
    case PROJCURVE_END_OCCLUDED: return "occluded";
    case PROJCURVE_END_MAX_DISTANCE: return "max_distance";
    }
    return "unknown";
}

const char *cli_start_words(projcurve_branch_start s)
{
    switch (s) {
    case PROJCURVE_START_CURVE_START: return "the start of the curve";
    case PROJCURVE_START_JUMP: return "a jump to another part of the surface";
    case PROJCURVE_START_BOUNDARY: return "the edge of the surface";
    case PROJCURVE_START_SILHOUETTE: return "a silhouette";
    case PROJCURVE_START_CURVE_CROSSING: return "where the curve leaves the surface";
    case PROJCURVE_START_FAILED: return "a stretch that could not be followed";
    case PROJCURVE_START_TRIM: return "the trimmed edge of a face";
    case PROJCURVE_START_VISIBLE: return "where it comes out from behind another part";
    case PROJCURVE_START_MAX_DISTANCE: return "where it comes within the maximum distance";
    }
    return "an unknown place";
}

const char *cli_end_words(projcurve_branch_end e)
{
    switch (e) {
    case PROJCURVE_END_CURVE_END: return "the end of the curve";
    case PROJCURVE_END_BOUNDARY: return "the edge of the surface";
    case PROJCURVE_END_SILHOUETTE: return "a silhouette";
    case PROJCURVE_END_CURVATURE_CENTRE: return "a centre of curvature";
    case PROJCURVE_END_LIMIT: return "a limit (time, work or pieces)";
    case PROJCURVE_END_FAILED: return "a stretch that could not be followed";
    case PROJCURVE_END_CURVE_CROSSING: return "where the curve meets the surface";
    case PROJCURVE_END_TRIM: return "the trimmed edge of a face";
    case PROJCURVE_END_OCCLUDED: return "where another part hides it";
    case PROJCURVE_END_MAX_DISTANCE: return "where it goes beyond the maximum distance";
    }
    return "an unknown place";
}
