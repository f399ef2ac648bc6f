/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * JSON report:
 *   {"time_ms": T, "branches": [{"surface": i, "curve": j, "t_range": [a, b],
 *    "pieces": n, "degree": d, "control_points": m, "pcurve_degree": dq,
 *    "pcurve_control_points": mq, "start": "...", "end": "...",
 *    "points": k, "residual": r, "deviation": e}, ...], "failures": f,
 *    "timeouts": n}
 * surface and curve are the numbers info prints (in file order, also
 * when --surface / --curve pick one); timeouts counts the calls stopped by
 * the time limit (also counted in failures); degree and
 * control_points describe the branch's compact 3D curve (the pieces joined
 * into one B-spline where it has none; 0 when it was not composed),
 * pcurve_degree and pcurve_control_points its compact pcurve (0 when not
 * composed): what the IGES file holds; residual and deviation are
 * described in cli.h (deviation is null when not composed).
 */
#include <math.h>

#include "cli.h"

static void json_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.17g", v);
    else
        fputs("null", f);
}

static void branch_json(projcurve_context *ctx, const cli_job *job, const cli_pair *p, size_t b,
                        FILE *f)
{
    double t[2] = {0.0, 0.0};
    projcurve_branch_start start = PROJCURVE_START_CURVE_START;
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    size_t n_points = 0, n_pieces = 0, n_ctrl = 0, n_pcurve = 0;
    int degree = 0, pcurve_degree = 0;
    projcurve_result_branch_info(ctx, p->result, b, t, &start, &end, &n_points, &n_pieces);
    projcurve_curve *c = NULL, *pc = NULL;
    if (projcurve_result_branch_compact_curve(NULL, p->result, b, &c) == PROJCURVE_OK ||
        projcurve_result_branch_curve(NULL, p->result, b, &c) == PROJCURVE_OK)
        projcurve_curve_nurbs_info(ctx, c, &degree, &n_ctrl, NULL, NULL);
    if (projcurve_result_branch_compact_pcurve(NULL, p->result, b, &pc) == PROJCURVE_OK)
        projcurve_curve_nurbs_info(ctx, pc, &pcurve_degree, &n_pcurve, NULL, NULL);
    projcurve_curve_destroy(c);
    projcurve_curve_destroy(pc);
    cli_branch_quality q;
    cli_branch_measure(ctx, job, p, b, &q);
    fprintf(f, "    {\"surface\": %zu, \"curve\": %zu, \"t_range\": [",
            cli_surface_number(job, p->surface), cli_curve_number(job, p->curve));
    json_number(f, t[0]);
    fputs(", ", f);
    json_number(f, t[1]);
    fprintf(f,
            "], \"pieces\": %zu, \"degree\": %d, \"control_points\": %zu, "
            "\"pcurve_degree\": %d, \"pcurve_control_points\": %zu, \"start\": \"%s\", "
            "\"end\": \"%s\", \"points\": %zu, \"residual\": ",
            n_pieces, degree, n_ctrl, pcurve_degree, n_pcurve, cli_start_name(start),
            cli_end_name(end), n_points);
    json_number(f, q.residual);
    fputs(", \"deviation\": ", f);
    if (q.deviation >= 0.0)
        json_number(f, q.deviation);
    else
        fputs("null", f);
    fputc('}', f);
}

int cli_write_json(projcurve_context *ctx, const cli_job *job, const char *path)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "projcurve: cannot create %s\n", path);
        return 0;
    }
    fputs("{\"time_ms\": ", f);
    json_number(f, job->time_ms);
    fputs(", \"branches\": [", f);
    int first = 1;
    for (size_t i = 0; i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        const size_t n = projcurve_result_branch_count(p->result);
        for (size_t b = 0; b < n; ++b) {
            fputs(first ? "\n" : ",\n", f);
            branch_json(ctx, job, p, b, f);
            first = 0;
        }
    }
    fprintf(f, "%s], \"failures\": %zu, \"timeouts\": %zu}\n", first ? "" : "\n  ",
            job->failures, job->timeouts);
    const int ok = fclose(f) == 0;
    if (!ok)
        fprintf(stderr, "projcurve: error writing %s\n", path);
    return ok;
}

size_t cli_print_summary(projcurve_context *ctx, const cli_job *job, FILE *out)
{
    size_t branches = 0, pieces = 0, unmeasured = 0, composed = 0;
    double residual = 0.0, deviation = 0.0;
    for (size_t i = 0; i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        const size_t n = projcurve_result_branch_count(p->result);
        for (size_t b = 0; b < n; ++b) {
            size_t np = 0;
            cli_branch_quality q;
            if (projcurve_result_branch_info(ctx, p->result, b, NULL, NULL, NULL, NULL, &np) !=
                    PROJCURVE_OK ||
                !cli_branch_measure(ctx, job, p, b, &q)) {
                ++unmeasured;
                continue;
            }
            pieces += np;
            residual = fmax(residual, q.residual);
            if (q.deviation >= 0.0) {
                deviation = fmax(deviation, q.deviation);
                ++composed;
            }
        }
        branches += n;
    }
    if (out == NULL)
        return unmeasured;
    fprintf(out, "%zu curve(s) x %zu surface(s): %zu branch(es), %zu piece(s), %.1f ms; ",
            job->n_curves, job->n_surfaces, branches, pieces, job->time_ms);
    if (branches == unmeasured)
        fputs("max residual -", out);
    else
        fprintf(out, "max residual %.3g", residual);
    if (composed == 0)
        fputs(", max deviation -", out);
    else
        fprintf(out, ", max deviation %.3g", deviation);
    if (unmeasured)
        fprintf(out, " (%zu branch(es) could not be measured)", unmeasured);
    fprintf(out, "%s\n", job->failures || unmeasured ? " (some projections failed)" : "");
    return unmeasured;
}
