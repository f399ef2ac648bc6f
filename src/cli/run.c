#include <math.h>
#include <stdlib.h>

#include "cli.h"

int cli_run(projcurve_context *ctx, cli_job *job)
{
    job->n_pairs = job->n_surfaces * job->n_curves;
    job->pairs = calloc(job->n_pairs ? job->n_pairs : 1, sizeof *job->pairs);
    if (job->pairs == NULL)
        return 0;
    job->time_ms = 0.0;
    job->failures = 0;
    size_t k = 0;
    for (size_t c = 0; c < job->n_curves; ++c)
        for (size_t s = 0; s < job->n_surfaces; ++s, ++k) {
            cli_pair *p = &job->pairs[k];
            p->surface = s;
            p->curve = c;
            const double t0 = cli_now_ms();
            p->status = job->orthogonal
                            ? projcurve_project_orthogonal(ctx, job->surfaces[s], job->curves[c],
                                                           job->opts, &p->result)
                            : projcurve_project_directional(ctx, job->surfaces[s],
                                                            job->curves[c], job->dir, job->opts,
                                                            &p->result);
            job->time_ms += cli_now_ms() - t0;
            if (p->status != PROJCURVE_OK) {
                fprintf(stderr, "projcurve: curve %zu onto surface %zu: %s: %s\n", c, s,
                        projcurve_status_string(p->status), projcurve_context_message(ctx));
                /* A partial result (a size, time or work limit, or a
                 * cancel) is kept and reported. */
                if (p->status != PROJCURVE_ERR_LIMIT_REACHED &&
                    p->status != PROJCURVE_ERR_CANCELLED)
                    p->result = NULL;
                ++job->failures;
            }
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

static double norm3(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* A derivative below this fraction of the other marks a collapsed edge
 * (a pole, an apex, a horn's tip), as in the library (ortho/collapsed.h). */
#define CLI_COLLAPSED_RATIO 1e-6

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Length of the part of d tangent to the plane with normal n. */
static double tangential(const double d[3], const double n[3])
{
    const double nn = dot3(n, n);
    const double dn = dot3(d, n) / nn;
    const double t[3] = {d[0] - dn * n[0], d[1] - dn * n[1], d[2] - dn * n[2]};
    return norm3(t);
}

/* The orthogonal residual: the tangential part of d = S - P. At a point of
 * a collapsed edge Su x Sv is rounding (|Sv| ~ 1e-15 at the horn's tip)
 * and the normal is its limit: with Sv ~ e Suv at a distance e from the
 * edge u = const, Su x Sv ~ e Su x Suv (Suv x Sv for Su ~ 0). Where that
 * limit vanishes too (a cone's apex has no tangent plane) only the regular
 * direction's condition is left: the component of d along it. */
static double orthogonal_residual(const double *s, const double d[3])
{
    const double *su = s + 3, *sv = s + 6, *suv = s + 12;
    const double lu = norm3(su), lv = norm3(sv);
    double n[3];
    if (lv < CLI_COLLAPSED_RATIO * lu || lu < CLI_COLLAPSED_RATIO * lv) {
        const int v_collapsed = lv < lu;
        const double *regular = v_collapsed ? su : sv;
        if (v_collapsed)
            cross3(su, suv, n);
        else
            cross3(suv, sv, n);
        if (norm3(n) > CLI_COLLAPSED_RATIO * norm3(regular) * norm3(suv))
            return tangential(d, n);
        return fabs(dot3(d, regular)) / norm3(regular);
    }
    cross3(su, sv, n);
    if (!(norm3(n) > 0.0))
        return INFINITY;
    return tangential(d, n);
}

/* Parameter nudge, as a fraction of the domain's width, that moves an
 * evaluation off a knot line to the patch on one side of it (S moves by
 * ~1e-12 of the model size). */
#define CLI_SIDE_NUDGE 1e-12

/* The orthogonal residual at (u, v), INFINITY where S cannot be evaluated. */
static double orthogonal_at(projcurve_context *ctx, const projcurve_surface *surface,
                            const double p[3], double u, double v)
{
    double s[18];
    if (projcurve_surface_eval(ctx, surface, u, v, 2, s) != PROJCURVE_OK)
        return INFINITY;
    const double d[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
    return orthogonal_residual(s, d);
}

/* The violation of the projection condition at one traced point. For the
 * orthogonal kind, the smallest of the residuals at (u, v) and just beside
 * it on either side in u and in v: on a knot line where S is only C0 (a
 * crease of a faceted surface, as every knot of a degree-1 surface) the
 * derivatives are those of one patch, and a foot point of the patch on the
 * other side measured with them showed residuals of 3,400
 * (test_pipe_out_true.step surface 0) while it is exact on its own side. */
static double residual_at(projcurve_context *ctx, const cli_job *job, const cli_pair *pair,
                          const double tuv[3])
{
    const projcurve_surface *surface = job->surfaces[pair->surface];
    double s[3], p[3];
    if (projcurve_curve_eval(ctx, job->curves[pair->curve], tuv[0], 0, p) != PROJCURVE_OK)
        return INFINITY;
    if (!job->orthogonal) {
        if (projcurve_surface_eval(ctx, surface, tuv[1], tuv[2], 0, s) != PROJCURVE_OK)
            return INFINITY;
        /* distance of S from the line P + lambda Dir */
        const double d[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
        double c[3];
        cross3(d, job->dir, c);
        return norm3(c) / norm3(job->dir);
    }
    double dom[4];
    projcurve_surface_domain(ctx, surface, dom);
    const double hu = CLI_SIDE_NUDGE * (dom[1] - dom[0]), hv = CLI_SIDE_NUDGE * (dom[3] - dom[2]);
    const double u = tuv[1], v = tuv[2];
    double r = orthogonal_at(ctx, surface, p, u, v);
    r = fmin(r, orthogonal_at(ctx, surface, p, fmax(dom[0], u - hu), v));
    r = fmin(r, orthogonal_at(ctx, surface, p, fmin(dom[1], u + hu), v));
    r = fmin(r, orthogonal_at(ctx, surface, p, u, fmax(dom[2], v - hv)));
    return fmin(r, orthogonal_at(ctx, surface, p, u, fmin(dom[3], v + hv)));
}

void cli_branch_measure(projcurve_context *ctx, const cli_job *job, const cli_pair *pair,
                        size_t branch, cli_branch_quality *q)
{
    q->residual = 0.0;
    q->deviation = -1.0;
    size_t n = 0;
    double probe[3];
    if (projcurve_result_branch_points(ctx, pair->result, branch, 0, probe, &n) != PROJCURVE_OK ||
        n == 0)
        return;
    double *tuv = malloc(3 * n * sizeof *tuv);
    if (tuv == NULL)
        return;
    projcurve_curve *composed = NULL;
    if (projcurve_result_branch_curve(ctx, pair->result, branch, &composed) == PROJCURVE_OK)
        q->deviation = 0.0;
    size_t got = 0;
    if (projcurve_result_branch_points(ctx, pair->result, branch, n, tuv, &got) == PROJCURVE_OK) {
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
}

const char *cli_start_name(projcurve_branch_start s)
{
    switch (s) {
    case PROJCURVE_START_CURVE_START: return "curve_start";
    case PROJCURVE_START_JUMP: return "jump";
    case PROJCURVE_START_BOUNDARY: return "boundary";
    case PROJCURVE_START_SILHOUETTE: return "silhouette";
    case PROJCURVE_START_CURVE_CROSSING: return "curve_crossing";
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
    }
    return "unknown";
}
