/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * JSON report of projcurve project --faces:
 *   {"time_ms": T, "connected_curves": N, "face_pieces": M,
 *    "runs": [{"shape": s, "curve": j, "status": "...", "open_ends": g,
 *      "chain_tolerance": c, "curves": [{"closed": b, "t_range": [a, b],
 *        "pieces": [{"face": f, "shape_face": i, "t_range": [a, b],
 *          "start": "...", "end": "...", "degree": d, "control_points": m,
 *          "pcurve_degree": dq, "pcurve_control_points": mq, "seams": j}, ...]},
 *        ...]},
 *     ...], "failures": n, "timeouts": k}
 * shape counts the shapes of the files in order (as info lists them), face
 * is the model's face index (as info prints it), shape_face its index in
 * the shape; degree and control_points describe the piece's compact 3D
 * curve (the pieces joined where it has none; 0 when not composed),
 * pcurve_degree and pcurve_control_points its compact pcurve (unsplit),
 * seams the jumps of its pcurve across its face's seams and poles
 * (projcurve_result_branch_seam_count: the files written hold seams + 1
 * curves on the face's surface for the piece); time_ms is the time spent
 * in the projection calls only.
 */
#include <math.h>

#include "shape_job.h"

static void json_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.17g", v);
    else
        fputs("null", f);
}

static void json_range(FILE *f, const double t[2])
{
    fputc('[', f);
    json_number(f, t[0]);
    fputs(", ", f);
    json_number(f, t[1]);
    fputc(']', f);
}

static void piece_json(projcurve_context *ctx, const cli_shape_run *r, size_t c, size_t k,
                       FILE *f)
{
    size_t face = 0, branch = 0, model_face = 0, n_ctrl = 0, n_pcurve = 0;
    const projcurve_result *fr = NULL;
    double t[2] = {0.0, 0.0};
    projcurve_branch_start start = PROJCURVE_START_CURVE_START;
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    int degree = 0, pcurve_degree = 0;
    size_t seams = 0;
    projcurve_shape_result_piece(ctx, r->result, c, k, &face, &fr, &branch, t, &start, &end);
    projcurve_result_branch_seam_count(ctx, fr, branch, &seams);
    projcurve_shape_face_model_index(ctx, r->target, face, &model_face);
    projcurve_curve *cc = NULL, *pc = NULL;
    if (projcurve_result_branch_compact_curve(NULL, fr, branch, &cc) == PROJCURVE_OK ||
        projcurve_result_branch_curve(NULL, fr, branch, &cc) == PROJCURVE_OK)
        projcurve_curve_nurbs_info(ctx, cc, &degree, &n_ctrl, NULL, NULL);
    if (projcurve_result_branch_compact_pcurve(NULL, fr, branch, &pc) == PROJCURVE_OK)
        projcurve_curve_nurbs_info(ctx, pc, &pcurve_degree, &n_pcurve, NULL, NULL);
    projcurve_curve_destroy(cc);
    projcurve_curve_destroy(pc);
    fprintf(f, "{\"face\": %zu, \"shape_face\": %zu, \"t_range\": ", model_face, face);
    json_range(f, t);
    fprintf(f,
            ", \"start\": \"%s\", \"end\": \"%s\", \"degree\": %d, \"control_points\": %zu, "
            "\"pcurve_degree\": %d, \"pcurve_control_points\": %zu, \"seams\": %zu}",
            cli_start_name(start), cli_end_name(end), degree, n_ctrl, pcurve_degree, n_pcurve,
            seams);
}

static void run_json(projcurve_context *ctx, const cli_shape_job *job, const cli_shape_run *r,
                     FILE *f)
{
    fprintf(f, "    {\"shape\": %zu, \"curve\": %zu, \"status\": \"%s\", \"open_ends\": %zu, "
               "\"chain_tolerance\": ",
            r->shape, cli_shape_curve_number(job, r->curve), projcurve_status_string(r->status),
            projcurve_shape_result_open_end_count(r->result));
    json_number(f, projcurve_shape_result_chain_tolerance(r->result));
    fputs(", \"curves\": [", f);
    const size_t n = projcurve_shape_result_curve_count(r->result);
    for (size_t c = 0; c < n; ++c) {
        size_t n_pieces = 0;
        double t[2] = {0.0, 0.0};
        int closed = 0;
        projcurve_shape_result_curve_info(ctx, r->result, c, &n_pieces, t, &closed);
        fprintf(f, "%s\n      {\"closed\": %s, \"t_range\": ", c ? "," : "",
                closed ? "true" : "false");
        json_range(f, t);
        fputs(", \"pieces\": [", f);
        for (size_t k = 0; k < n_pieces; ++k) {
            fputs(k ? ",\n        " : "\n        ", f);
            piece_json(ctx, r, c, k, f);
        }
        fputs("]}", f);
    }
    fputs("]}", f);
}

/* Connected curves and face pieces over all runs. */
static void totals(const cli_shape_job *job, size_t *curves, size_t *pieces)
{
    *curves = *pieces = 0;
    for (size_t i = 0; i < job->n_runs; ++i) {
        const projcurve_shape_result *res = job->runs[i].result;
        const size_t n = projcurve_shape_result_curve_count(res);
        *curves += n;
        for (size_t c = 0; c < n; ++c) {
            size_t np = 0;
            if (projcurve_shape_result_curve_info(NULL, res, c, &np, NULL, NULL) == PROJCURVE_OK)
                *pieces += np;
        }
    }
}

int cli_write_shape_json(projcurve_context *ctx, const cli_shape_job *job, const char *path)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "projcurve: cannot create %s\n", path);
        return 0;
    }
    size_t curves = 0, pieces = 0;
    totals(job, &curves, &pieces);
    fputs("{\"time_ms\": ", f);
    json_number(f, job->time_ms);
    fprintf(f, ", \"connected_curves\": %zu, \"face_pieces\": %zu, \"runs\": [", curves, pieces);
    for (size_t i = 0; i < job->n_runs; ++i) {
        fputs(i ? ",\n" : "\n", f);
        run_json(ctx, job, &job->runs[i], f);
    }
    fprintf(f, "%s], \"failures\": %zu, \"timeouts\": %zu}\n", job->n_runs ? "\n  " : "",
            job->failures, job->timeouts);
    const int ok = fclose(f) == 0;
    if (!ok)
        fprintf(stderr, "projcurve: error writing %s\n", path);
    return ok;
}

void cli_print_shape_summary(const cli_shape_job *job, FILE *out)
{
    size_t curves = 0, pieces = 0, gaps = 0;
    totals(job, &curves, &pieces);
    for (size_t i = 0; i < job->n_runs; ++i)
        gaps += projcurve_shape_result_open_end_count(job->runs[i].result);
    fprintf(out,
            "%zu curve(s) x %zu shape(s): %zu connected curve(s), %zu face piece(s), %zu open "
            "end(s), %.1f ms%s\n",
            job->n_curves, job->n_curves ? job->n_runs / job->n_curves : 0, curves, pieces, gaps,
            job->time_ms, job->failures ? " (some projections failed)" : "");
}
