/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The checks of the verification pass (verify.h) for one vertex and one
 * composed piece.
 *
 * (a) A vertex passes when the projector's residual — the distance of
 *     S(u, v) from the projection condition in model units, measured with
 *     the limit normal at collapsed edges (ortho_projector.c) — is within
 *     the vertex tolerance.
 *
 * (b) How many samples. Both the piece C and the exact projection Q start
 *     and end at the same exact vertices, so their distance over the piece
 *     vanishes at both ends and is, to leading order, the interpolation
 *     remainder of the pcurve: s (1 - s) h^2 q'' / 2 for a straight pcurve
 *     (degree d = 1 in s: a quadratic bump), s^2 (1 - s)^2 h^4 q'''' / 24 for
 *     the cubic Hermite one (d = 3: a quartic bump), mapped to 3-space by
 *     S's first derivatives. The next term of the remainder, one degree
 *     higher, makes the bump asymmetric. 2 d + 1 equally spaced interior
 *     samples (s = k / (2 d + 2)) put one on the symmetric peak (s = 1/2)
 *     and two on each flank of the bump's leading 2 d + 1 degrees of
 *     freedom — 3 for straight pieces, 7 for cubic ones, which are 10-20
 *     times fewer. For each sample s the exact point is the corrector's
 *     solution at the matching curve parameter t = t0 + s (t1 - t0) (the
 *     parameter the cubic Hermite interpolates at, and the chord's own to
 *     first order), started from the pcurve's point at s; its distance to C
 *     is the distance to C(s) when that is already within eps_D, else the
 *     distance to its foot on C (deviation.c's Newton, an upper bound of the
 *     true distance, so nothing is passed that is not within eps_D).
 *
 * (c) A piece's first control point (S at its start) is within eps_D of the
 *     previous piece's last, and its pcurve's control points, hence the
 *     pcurve, lie in the domain of S (to rounding).
 */
#include <math.h>

#include "refine/refine_internal.h"
#include "verify/verify_internal.h"

/* The corrector stops when its step, or the residual, is below its
 * tolerance; its last step then leaves the residual below a small multiple
 * of it, and the refinement puts knot-line crossings exactly on their line
 * (a move below 1e-9 of the domain: cells.c), which the residual sees as up
 * to ~1e-9 of the model size. The bound takes the larger of the two, with
 * a margin of 10; anything beyond it is not a point of the projection at
 * the precision this library promises. */
#define PC_VERIFY_NEWTON_MARGIN 10.0
#define PC_VERIFY_SNAP_REL 1e-8
/* (u, v) outside the domain by this fraction of its diagonal is rounding
 * (cubic.c clamps Hermite control points to 1e-11 of it). */
#define PC_VERIFY_DOMAIN_REL 1e-10
/* A sample's corrected (u, v) farther than this many pcurve chords from
 * its guess has left the branch: it cannot verify the piece. */
#define PC_VERIFY_MAX_JUMP 2.0

double pc_verify_vertex_tolerance(const pc_projector *proj)
{
    return fmax(PC_VERIFY_NEWTON_MARGIN * proj->newton_tol,
                PC_VERIFY_SNAP_REL * proj->model_size);
}

int pc_verify_vertex(pc_verifier *v, double t, double u, double w)
{
    const double res = v->proj->residual(v->proj, t, u, w);
    if (res > v->worst_vertex)
        v->worst_vertex = res;
    return res <= v->vertex_tol; /* NaN and INFINITY fail */
}

/* A vertex on a knot line where S is only C0 (a crease) is a point of the
 * projection onto the patch its piece lies in, whose derivatives at the
 * line are the one-sided ones: evaluated there the residual sees the other
 * patch's normal (linkrods.step surface 9, whose every knot in v has
 * multiplicity = degree: 4e-4 at a branch start on the crease v = -0.2789,
 * 6e-15 on its own side), and the branch's only piece was dropped. One ulp
 * towards the piece is on its side of any knot line, and moves the point
 * by rounding only. */
int pc_verify_vertex_of_pieces(pc_verifier *v, double t, double u, double w,
                               const double *const toward[2])
{
    double res = v->proj->residual(v->proj, t, u, w);
    for (int k = 0; k < 2 && !(res <= v->vertex_tol); ++k)
        if (toward[k] != NULL)
            res = fmin(res, v->proj->residual(v->proj, t, nextafter(u, toward[k][0]),
                                              nextafter(w, toward[k][1])));
    if (res > v->worst_vertex)
        v->worst_vertex = res;
    return res <= v->vertex_tol; /* NaN and INFINITY fail */
}

/* The pcurve of p at s (de Casteljau on its uv_degree + 1 points). */
static void pcurve_point(const pc_piece *p, double s, double uv[2])
{
    double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
    const int n = p->uv_degree;
    for (int k = 0; k < 2 * (n + 1); ++k)
        w[k] = p->uv_ctrl[k];
    for (int level = n; level > 0; --level)
        for (int i = 0; i < level; ++i)
            for (int c = 0; c < 2; ++c)
                w[2 * i + c] = (1.0 - s) * w[2 * i + c] + s * w[2 * (i + 1) + c];
    uv[0] = w[0];
    uv[1] = w[1];
}

static int in_domain(const pc_verifier *v, const pc_piece *p)
{
    const double *dom = v->proj->surface->nurbs.domain;
    for (int k = 0; k <= p->uv_degree; ++k) {
        const double u = p->uv_ctrl[2 * k], w = p->uv_ctrl[2 * k + 1];
        if (!(u >= dom[0] - v->domain_tol && u <= dom[1] + v->domain_tol &&
              w >= dom[2] - v->domain_tol && w <= dom[3] + v->domain_tol))
            return 0;
    }
    return 1;
}

/* Newton steps on the foot parameter of a parabola (below). */
#define PC_VERIFY_FOOT_ITER 8

/* Distance of y from the parabola through a, b, c parametrised by chord
 * length (tau = -|b - a|, 0, |c - b|; the t spacing would not do: near a
 * fold or a centre of curvature q moves as a square root of t, and a
 * parabola in t overshoots there by many eps_D), tau between a and c:
 * Newton on (P - y).P' = 0 from tau = 0, and the two ends. */
static double parabola_distance(pc_vec3 y, pc_vec3 a, pc_vec3 b, pc_vec3 c)
{
    const double l1 = vec3_dist(a, b), l2 = vec3_dist(b, c);
    double d = fmin(vec3_dist(a, y), fmin(vec3_dist(b, y), vec3_dist(c, y)));
    if (!(l1 > 0.0 && l2 > 0.0))
        return d;
    const pc_vec3 fab = vec3_scale(vec3_sub(b, a), 1.0 / l1);
    const pc_vec3 fbc = vec3_scale(vec3_sub(c, b), 1.0 / l2);
    const pc_vec3 f2 = vec3_scale(vec3_sub(fbc, fab), 1.0 / (l1 + l2)); /* P'' / 2 */
    const pc_vec3 d1 = vec3_axpy(fbc, -l2, f2);                       /* P'(0) */
    double tau = 0.0;
    for (int it = 0; it < PC_VERIFY_FOOT_ITER; ++it) {
        const pc_vec3 pt = vec3_add(b, vec3_add(vec3_scale(d1, tau), vec3_scale(f2, tau * tau)));
        const pc_vec3 dp = vec3_axpy(d1, 2.0 * tau, f2);
        const pc_vec3 e = vec3_sub(pt, y);
        const double g = vec3_dot(e, dp), h = vec3_dot(dp, dp) + 2.0 * vec3_dot(e, f2);
        if (!(h > 0.0))
            break;
        tau -= g / h;
        tau = tau < -l1 ? -l1 : tau > l2 ? l2 : tau;
    }
    const pc_vec3 pt = vec3_add(b, vec3_add(vec3_scale(d1, tau), vec3_scale(f2, tau * tau)));
    return fmin(d, vec3_dist(pt, y));
}

/* The samples of one piece: exact points x[k] at t[k] (uv[k] on S) and
 * the piece's points c[k] at s = k / (m + 1), k = 0 .. m + 1 (the ends
 * shared). */
typedef struct piece_samples {
    int m;
    double t[2 * PROJCURVE_MAX_PCURVE_POINTS + 1], uv[2 * PROJCURVE_MAX_PCURVE_POINTS + 1][2];
    pc_vec3 x[2 * PROJCURVE_MAX_PCURVE_POINTS + 1], c[2 * PROJCURVE_MAX_PCURVE_POINTS + 1];
} piece_samples;

/* The exact point at t from the guess uv (updated), on S into *x; 0 when
 * the corrector fails or moves farther than max_move from the guess (it
 * left the branch). */
static int exact_point(const pc_verifier *v, double t, double uv[2], double max_move, pc_vec3 *x)
{
    const pc_projector *proj = v->proj;
    const double guess[2] = {uv[0], uv[1]};
    if (!proj->correct(proj, t, uv, NULL) || !isfinite(uv[0]) || !isfinite(uv[1]))
        return 0;
    if (hypot(uv[0] - guess[0], uv[1] - guess[1]) > max_move)
        return 0;
    size_t hu = 0, hv = 0;
    pc_nurbs_surface_eval(&proj->surface->nurbs, uv[0], uv[1], 0, &hu, &hv, x);
    return 1;
}

/* Sample k of the piece (cw: its homogeneous control points) into sp, and
 * the distance of its exact point from the piece; INFINITY when the
 * corrector cannot give that point on this branch. */
static double sample_distance(pc_verifier *v, const pc_piece *p, const double *cw, int k,
                              piece_samples *sp)
{
    const double s = (double)k / (double)(sp->m + 1);
    pcurve_point(p, s, sp->uv[k]);
    sp->t[k] = p->t0 + s * (p->t1 - p->t0);
    const double chord = hypot(p->uv[2] - p->uv[0], p->uv[3] - p->uv[1]);
    if (!exact_point(v, sp->t[k], sp->uv[k], PC_VERIFY_MAX_JUMP * chord + v->min_move,
                     &sp->x[k]))
        return INFINITY;
    pc_vec3 c[3];
    pc_piece_eval(p->degree, cw, s, c);
    sp->c[k] = c[0];
    const double near = vec3_dist(sp->x[k], c[0]);
    if (near <= v->eps_d)
        return near;
    /* the foot's parameter is near the exact point's place along the
     * chord (the piece's parametrisation need not follow t); often that
     * point is already within eps_D, and Newton is not needed */
    const pc_vec3 a = sp->c[0], ab = vec3_sub(sp->c[sp->m + 1], a);
    const double len2 = vec3_dot(ab, ab);
    double s0 = len2 > 0.0 ? vec3_dot(vec3_sub(sp->x[k], a), ab) / len2 : s;
    s0 = s0 < 0.0 ? 0.0 : s0 > 1.0 ? 1.0 : s0;
    pc_piece_eval(p->degree, cw, s0, c);
    const double near0 = fmin(near, vec3_dist(sp->x[k], c[0]));
    if (near0 <= v->eps_d)
        return near0;
    return fmin(near0, pc_piece_distance(p->degree, cw, sp->x[k], s0, NULL));
}

/* Golden-section steps of the fallback foot search (a bracket of 1e-6 of
 * its start, far below any feature a piece within eps_D can have). */
#define PC_VERIFY_GOLDEN_ITER 30

/* Distance of y from the exact curve over [t[j-1], t[j+1]] around the
 * exact sample j nearest y, by golden section on t with corrected points:
 * every value is a true distance to a point of the exact curve, so the
 * result is an upper bound. */
static double exact_curve_distance(const pc_verifier *v, const piece_samples *sp, pc_vec3 y,
                                   double chord)
{
    int j = 0;
    for (int k = 1; k <= sp->m + 1; ++k)
        if (vec3_dist(sp->x[k], y) < vec3_dist(sp->x[j], y))
            j = k;
    const int lo = j > 0 ? j - 1 : 0, hi = j <= sp->m ? j + 1 : sp->m + 1;
    double best = vec3_dist(sp->x[j], y);
    double a = sp->t[lo], b = sp->t[hi];
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int it = 0; it < PC_VERIFY_GOLDEN_ITER; ++it) {
        const double t1 = b - g * (b - a), t2 = a + g * (b - a);
        double d[2];
        const double ts[2] = {t1, t2};
        for (int q = 0; q < 2; ++q) {
            /* guess: the exact samples' (u, v), linear in t */
            const int i0 = ts[q] <= sp->t[j] ? lo : j, i1 = ts[q] <= sp->t[j] ? j : hi;
            const double span = sp->t[i1] - sp->t[i0];
            const double w = span != 0.0 ? (ts[q] - sp->t[i0]) / span : 0.0;
            double uv[2] = {sp->uv[i0][0] + w * (sp->uv[i1][0] - sp->uv[i0][0]),
                            sp->uv[i0][1] + w * (sp->uv[i1][1] - sp->uv[i0][1])};
            pc_vec3 x;
            d[q] = exact_point(v, ts[q], uv, PC_VERIFY_MAX_JUMP * chord + v->min_move, &x)
                       ? vec3_dist(x, y)
                       : INFINITY;
            best = fmin(best, d[q]);
        }
        if (d[0] <= d[1])
            b = t2;
        else
            a = t1;
    }
    return best;
}

/* The other side of the Hausdorff distance: the largest distance of the
 * piece's points at the samples, c[1..m], from the exact curve. First
 * cheaply against the chain of parabolas through the exact points x[j-1],
 * x[j], x[j+1], each parametrised by chord length (error third order in the
 * sample spacing); where that is above eps_D — a bulge of the piece that
 * the feet of the exact points on it do not see, or exact samples too
 * sparse for the parabolas, as next to a fold, where q moves as a square
 * root of t — by a foot search on the exact curve itself. */
static double piece_to_exact(const pc_verifier *v, const piece_samples *sp, double chord)
{
    double worst = 0.0;
    for (int k = 1; k <= sp->m; ++k) {
        /* the exact point of the same sample is a point of the curve */
        double d = vec3_dist(sp->c[k], sp->x[k]);
        for (int j = 1; j <= sp->m && !(d <= v->eps_d); ++j)
            d = fmin(d, parabola_distance(sp->c[k], sp->x[j - 1], sp->x[j], sp->x[j + 1]));
        if (!(d <= v->eps_d))
            d = fmin(d, exact_curve_distance(v, sp, sp->c[k], chord));
        worst = fmax(worst, d);
    }
    return worst;
}

int pc_verify_piece(pc_verifier *v, const pc_piece *p, const pc_piece *prev)
{
    v->samples = 0;
    const int n = p->degree;
    if (n < 2 || n > PC_PIECE_MAX_DEGREE || !in_domain(v, p))
        return 0;
    if (prev != NULL) {
        const double *e = prev->ctrl + 3 * prev->degree, *f = p->ctrl;
        if (!(vec3_dist(vec3(e[0], e[1], e[2]), vec3(f[0], f[1], f[2])) <= v->eps_d))
            return 0;
    }
    double cw[PC_PIECE_MAX_CW];
    for (int k = 0; k <= n; ++k) {
        const double w = p->weights[k];
        for (int c = 0; c < 3; ++c)
            cw[4 * k + c] = w * p->ctrl[3 * k + c];
        cw[4 * k + 3] = w;
    }
    piece_samples sp;
    const int m = sp.m = 2 * p->uv_degree + 1;
    sp.t[0] = p->t0;
    sp.t[m + 1] = p->t1;
    for (int e = 0; e < 2; ++e) {
        const int k = e ? m + 1 : 0;
        sp.uv[k][0] = p->uv[2 * e];
        sp.uv[k][1] = p->uv[2 * e + 1];
        sp.x[k] = sp.c[k] = vec3(p->ctrl[3 * n * e], p->ctrl[3 * n * e + 1], p->ctrl[3 * n * e + 2]);
    }
    for (int k = 1; k <= m; ++k) {
        const double d = sample_distance(v, p, cw, k, &sp);
        ++v->samples;
        if (d > v->worst_piece)
            v->worst_piece = d;
        if (!(d <= v->eps_d))
            return 0;
    }
    const double back = piece_to_exact(v, &sp, hypot(p->uv[2] - p->uv[0], p->uv[3] - p->uv[1]));
    if (back > v->worst_piece)
        v->worst_piece = back;
    return back <= v->eps_d;
}
