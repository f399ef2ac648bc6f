/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/branch_view.h"

#include <math.h>


/* Consecutive pieces share their end vertex: their t agree to this
 * fraction of the branch's range (rounding), or the branch is broken. */
#define PC_FIT_JOIN_REL 1e-12
/* A corrected point farther than this many piece lengths (in u, v) from
 * its guess has left the branch. */
#define PC_FIT_MAX_JUMP 2.0
/* Slack of that test for pieces shorter than rounding, relative to the
 * size of the surface's domain. */
#define PC_FIT_MOVE_REL 1e-9

void pc_fit_piece_range(const pc_piece *p, double *lo, double *hi)
{
    *lo = fmin(p->t0, p->t1);
    *hi = fmax(p->t0, p->t1);
}

const pc_piece *pc_fit_piece(const pc_fit_branch *fb, size_t k)
{
    return &fb->b->pieces[fb->reversed ? fb->b->n_pieces - 1 - k : k];
}

int pc_fit_branch_init(pc_fit_branch *fb, const pc_projector *proj, const pc_branch *b,
                       pc_budget *budget)
{
    if (b->n_pieces == 0)
        return 0;
    fb->proj = proj;
    fb->surface = &proj->surface->nurbs;
    fb->b = b;
    fb->reversed = b->pieces[0].t0 > b->pieces[0].t1;
    fb->budget = budget;
    fb->hint_u = fb->hint_v = 0;
    fb->corrections = 0;
    fb->progress = 0.0;
    double lo, hi;
    pc_fit_piece_range(pc_fit_piece(fb, 0), &lo, &hi);
    fb->t_lo = lo;
    pc_fit_piece_range(pc_fit_piece(fb, b->n_pieces - 1), &lo, &hi);
    fb->t_hi = hi;
    if (!(fb->t_hi > fb->t_lo))
        return 0;
    const double slack = PC_FIT_JOIN_REL * (fb->t_hi - fb->t_lo);
    for (size_t k = 0; k < b->n_pieces; ++k) {
        const pc_piece *p = pc_fit_piece(fb, k);
        if ((p->t1 > p->t0) == fb->reversed || p->t0 == p->t1)
            return 0;
        if (k > 0) {
            double plo, phi, qlo, qhi;
            pc_fit_piece_range(pc_fit_piece(fb, k - 1), &plo, &phi);
            pc_fit_piece_range(p, &qlo, &qhi);
            if (fabs(qlo - phi) > slack)
                return 0;
        }
    }
    const double *d = fb->surface->domain;
    fb->min_move = PC_FIT_MOVE_REL * fmax(d[1] - d[0], d[3] - d[2]);
    return 1;
}

void pc_fit_piece_uv(const pc_piece *p, double t, double uv[2])
{
    double s = (t - p->t0) / (p->t1 - p->t0);
    s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
    double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
    const int n = p->uv_degree;
    for (int i = 0; i <= 2 * n + 1; ++i)
        w[i] = p->uv_ctrl[i];
    for (int level = n; level > 0; --level) /* de Casteljau */
        for (int i = 0; i < level; ++i)
            for (int c = 0; c < 2; ++c)
                w[2 * i + c] = (1.0 - s) * w[2 * i + c] + s * w[2 * (i + 1) + c];
    uv[0] = w[0];
    uv[1] = w[1];
}

void pc_fit_surface_point(pc_fit_branch *fb, const double uv[2], double x[3])
{
    pc_vec3 s;
    pc_nurbs_surface_eval(fb->surface, uv[0], uv[1], 0, &fb->hint_u, &fb->hint_v, &s);
    x[0] = s.x;
    x[1] = s.y;
    x[2] = s.z;
}

void pc_fit_sample_at(pc_fit_branch *fb, double t, const double uv[2], pc_fit_sample *out)
{
    pc_vec3 s[3];
    pc_nurbs_surface_eval(fb->surface, uv[0], uv[1], 1, &fb->hint_u, &fb->hint_v, s);
    out->t = t;
    out->uv[0] = uv[0];
    out->uv[1] = uv[1];
    const double x[3] = {s[0].x, s[0].y, s[0].z}, su[3] = {s[1].x, s[1].y, s[1].z},
                 sv[3] = {s[2].x, s[2].y, s[2].z};
    for (int c = 0; c < 3; ++c) {
        out->x[c] = x[c];
        out->su[c] = su[c];
        out->sv[c] = sv[c];
    }
}

/* Index (in increasing t) of the piece whose range holds t. */
static size_t piece_at(const pc_fit_branch *fb, double t)
{
    size_t lo = 0, hi = fb->b->n_pieces; /* answer in [lo, hi) */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        double plo, phi;
        pc_fit_piece_range(pc_fit_piece(fb, mid), &plo, &phi);
        if (plo <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int pc_fit_exact(pc_fit_branch *fb, double t, pc_fit_sample *out)
{
    if (pc_budget_check(fb->budget, fb->progress) != PROJCURVE_OK)
        return 0;
    t = t < fb->t_lo ? fb->t_lo : (t > fb->t_hi ? fb->t_hi : t);
    const pc_piece *p = pc_fit_piece(fb, piece_at(fb, t));
    double uv[2];
    pc_fit_piece_uv(p, t, uv);
    const double guess[2] = {uv[0], uv[1]};
    ++fb->corrections;
    if (!fb->proj->correct(fb->proj, t, uv, NULL) || !isfinite(uv[0]) || !isfinite(uv[1]))
        return 0;
    const double length = hypot(p->uv[2] - p->uv[0], p->uv[3] - p->uv[1]);
    if (hypot(uv[0] - guess[0], uv[1] - guess[1]) > PC_FIT_MAX_JUMP * length + fb->min_move)
        return 0;
    pc_fit_sample_at(fb, t, uv, out);
    return 1;
}

void pc_fit_piece_end(pc_fit_branch *fb, size_t k, int hi, pc_fit_sample *out)
{
    const pc_piece *p = pc_fit_piece(fb, k);
    const int at_t1 = (p->t1 > p->t0) == (hi != 0);
    const double uv[2] = {p->uv[at_t1 ? 2 : 0], p->uv[at_t1 ? 3 : 1]};
    pc_fit_sample_at(fb, at_t1 ? p->t1 : p->t0, uv, out);
}
