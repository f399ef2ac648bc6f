/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The march of march.c with cubic Hermite pcurves (cubic.c): from the
 * current vertex, a candidate piece of parameter length h ends at the exact
 * point q(t + h) and interpolates q' at both ends; it is accepted when its
 * composed image is within eps_D of the exact curve (deviation.c). Its
 * distance grows as h^4, so the next h is predicted with a fourth root.
 *
 * No end-tangent bound is needed: both ends carry the exact tangent, so a
 * joint between two cubic pieces is G1 (at a knot line, each side takes
 * the one-sided tangent of its own patch: the joint keeps the corner of the
 * exact curve where S has a crease, and only there). This is checked, not
 * assumed: a joint off the knot lines beyond eps_T hands the piece to the
 * straight march.
 *
 * Where the cubic cannot be used — its control points leave the patch (the
 * curve would leave it: the composition would not be on S), or q' is not
 * available (a fold at a branch end) — the step is halved a few times, and
 * then the rest of the run (to its next fixed vertex) is handed to the
 * straight-segment march (march.c), as is a cubic still beyond eps_D at
 * the step floor; that march holds its pieces to eps_D and their end
 * tangents to eps_T / 2 of the exact ones: a joint between a straight and a
 * cubic piece is then within eps_T / 2.
 */
#include <math.h>

#include "compose/compose.h"
#include "refine/refine_internal.h"

#define PC_CUBIC_GROW_MAX 2.0     /* largest step growth after a success */
#define PC_CUBIC_SHRINK_MIN 0.1   /* largest step cut after a failure */
#define PC_CUBIC_STEP_SAFETY 0.9  /* aim a little inside the bound */
/* A cubic whose end tangent, scaled to the piece (|q'| h), exceeds this
 * multiple of its chord is not used: the speed of q varies too much over
 * the piece for the Hermite form to follow it — near a fold, where q' grows
 * without bound, the cubic would overshoot between the deviation samples. */
#define PC_CUBIC_MAX_TANGENT_RATIO 3.0
/* Rejections in a row before a candidate is taken anyway (see march.c). */
#define PC_CUBIC_MAX_REJECTIONS 60
/* Halvings in a row of a candidate whose cubic cannot be built before the
 * stretch goes to the straight march: 1/64 of the step. */
#define PC_CUBIC_MAX_INVALID 6
/* A run end where no cubic can be built — q' is not available there (a
 * pole of S, where Su = 0 and the (u, v) tangent is singular: the
 * sphere's collapsed edge) or every cubic reaching it is invalid (a fold
 * end of the orthogonal projection, where q' is finite but grows without
 * bound) — is approached by cubics until the rest of the run is this
 * fraction of the step that first reached it; the rest goes to the
 * straight march. Halving alone never got there: every cubic reaching the
 * end was invalid, every halved one was accepted, and the march made
 * pieces of half the distance left, one after another, to the piece limit
 * (a line across a sphere's pole), or down to 5e-9 before a fold, where
 * the cubics failed verification and the corrector its step (the
 * parabolic cylinder of test_ortho_events: 7 branches with FAILED ends,
 * against 3 whole ones with straight pieces). */
#define PC_CUBIC_END_APPROACH (1.0 / 64.0)

/* 1 when the directions a and b are within the angle whose cosine is
 * cos_max (or either is zero: no direction to compare). */
static int within_angle(pc_vec3 a, pc_vec3 b, double cos_max)
{
    const double na = vec3_norm(a), nb = vec3_norm(b);
    return !(na > 0.0 && nb > 0.0) || vec3_dot(a, b) >= cos_max * na * nb;
}

/* The march's state between candidates. */
typedef struct cubic_march {
    pc_rvertex cur;
    const pc_bezier_patch *d0_patch; /* patch d0 was taken in (NULL: none yet) */
    double d0[2];
    int d0_ok;
    pc_vec3 prev_end; /* end direction of the last cubic piece ending at cur */
} cubic_march;

/* Outcome of one cubic candidate. */
typedef enum cubic_verdict { CUBIC_ACCEPT, CUBIC_TOO_FAR, CUBIC_INVALID } cubic_verdict;

/* Builds, composes and measures the cubic for cur-cand in patch; unless
 * CUBIC_INVALID, cand carries the pcurve and *end_dir its end direction.
 * *no_end_tangent gets 1 when q' is not available at cand. */
static cubic_verdict try_cubic(pc_refiner *r, cubic_march *m, const pc_bezier_patch *patch,
                               pc_rvertex *cand, double *ratio_d, pc_vec3 *end_dir,
                               int *no_end_tangent)
{
    if (m->d0_patch != patch) {
        m->d0_ok = pc_refine_uv_tangent(r, &m->cur, patch, m->d0);
        m->d0_patch = patch;
    }
    double d1[2], uv[8], cw[PC_PIECE_MAX_CW];
    pc_rvertex end = *cand; /* its q' from before it: one-sided at a corner of P */
    end.t = pc_refine_corner_left(r, cand->t);
    *no_end_tangent = m->d0_ok && !pc_refine_uv_tangent(r, &end, patch, d1);
    if (!m->d0_ok || *no_end_tangent || !pc_refine_hermite(r, patch, &m->cur, cand, m->d0, d1, uv))
        return CUBIC_INVALID;
    /* uv[2..5] hold h q' / 3. The allowance min_move keeps a stationary
     * projection (a point curve, q' = 0 up to rounding, chord 0) from
     * failing the test for ever: a cubic within min_move of its chord cannot
     * overshoot by more. Without it every candidate there was invalid, and
     * the straight march behind it made one rounding-sized piece after
     * another, to the piece limit. */
    const double chord = hypot(cand->u - m->cur.u, cand->v - m->cur.v);
    const double reach = PC_CUBIC_MAX_TANGENT_RATIO * chord / 3.0 + r->min_move;
    if (hypot(uv[2] - uv[0], uv[3] - uv[1]) > reach || hypot(uv[6] - uv[4], uv[7] - uv[5]) > reach)
        return CUBIC_INVALID;
    const int n = pc_compose_poly(patch, 3, uv, cw);
    if (n < 0)
        return CUBIC_INVALID;
    /* G1 by construction off the knot lines: checked */
    if (!pc_refine_at_crease(r, &m->cur) &&
        !within_angle(m->prev_end, pc_refine_end_direction(n, cw, 0), r->cos_eps_t))
        return CUBIC_INVALID;
    cand->in_cubic = 1;
    cand->in_d0[0] = m->d0[0];
    cand->in_d0[1] = m->d0[1];
    cand->in_d1[0] = d1[0];
    cand->in_d1[1] = d1[1];
    *end_dir = pc_refine_end_direction(n, cw, 1);
    double t_far;
    *ratio_d = pc_refine_deviation(r, n, cw, &m->cur, cand, r->eps_d, &t_far) / r->eps_d;
    return *ratio_d <= 1.0 ? CUBIC_ACCEPT : CUBIC_TOO_FAR;
}

/* Step scale from the distance ratio: the distance grows as h^4. */
static double step_factor(double ratio_d)
{
    double f = ratio_d > 0.0 ? PC_CUBIC_STEP_SAFETY / sqrt(sqrt(ratio_d)) : PC_CUBIC_GROW_MAX;
    if (f > PC_CUBIC_GROW_MAX)
        f = PC_CUBIC_GROW_MAX;
    if (f < PC_CUBIC_SHRINK_MIN)
        f = PC_CUBIC_SHRINK_MIN;
    return f;
}

/* Appends the stretch cur-end made by the straight march, its vertices
 * marked straight; *straight_step gets that march's last step. */
static projcurve_status straight_stretch(pc_refiner *r, const pc_rvertex *cur,
                                         const pc_rvertex *end, pc_vertex_list *out,
                                         double *straight_step)
{
    const size_t first = out->count;
    const double step = r->step;
    r->step = 0.0;
    const projcurve_status st = pc_refine_march(r, cur, end, out);
    *straight_step = r->step;
    r->step = step;
    for (size_t k = first; k < out->count; ++k)
        out->items[k].in_cubic = 0;
    return st;
}

/* The rest of the run, m->cur to b, by the straight march. */
static projcurve_status straight_rest(pc_refiner *r, const cubic_march *m, const pc_rvertex *b,
                                      pc_vertex_list *out)
{
    double straight_step = 0.0;
    return straight_stretch(r, &m->cur, b, out, &straight_step);
}

/* Moves the march to v, the vertex just appended. */
static void advance(cubic_march *m, const pc_rvertex *v, pc_vec3 end_dir)
{
    m->cur = *v;
    m->d0_patch = NULL;
    m->prev_end = end_dir;
}

projcurve_status pc_refine_march_cubic(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                       pc_vertex_list *out)
{
    cubic_march m = {*a, NULL, {0.0, 0.0}, 0, vec3(0.0, 0.0, 0.0)};
    double h = r->step > 0.0 ? pc_refine_march_start_step(r, r->step) : b->t - a->t;
    int rejections = 0, invalid = 0;
    pc_rvertex first_invalid = *a; /* the candidate before the current invalid halvings */
    double end_step = 0.0; /* step of the first candidate at b found without q' (0: none) */
    while (m.cur.t < b->t) {
        pc_rvertex cand;
        int reached = pc_refine_march_candidate(r, &m.cur, b, h, &cand);
        if (reached && pc_refine_common_patch(r, &m.cur, &cand) == NULL)
            reached = pc_refine_knot_crossing(r, &m.cur, &cand, &cand);
        /* a knot-line crossing found at cur itself is no step: taken, it
         * was output again and again, to the piece limit (as march.c) */
        reached = reached && cand.t > m.cur.t;
        if (!reached) {
            h *= 0.5; /* the corrector failed: come closer */
            if (++rejections < PC_CUBIC_MAX_REJECTIONS && h > r->min_dt)
                continue;
            /* the exact curve is out of reach here: a gap (refine.c) up to
             * the next exact point known, never a vertex off the projection */
            cand = pc_refine_next_known(r, &m.cur, b);
            cand.in_cubic = 0;
            const projcurve_status st = pc_refine_output_gap(r, out, &cand, PC_GAP_FAILED);
            if (st != PROJCURVE_OK)
                return st;
            advance(&m, &out->items[out->count - 1], vec3(0.0, 0.0, 0.0));
            rejections = invalid = 0;
            continue;
        }
        cand.in_cubic = 0;
        const pc_bezier_patch *patch = pc_refine_common_patch(r, &m.cur, &cand);
        const double hh = cand.t - m.cur.t;
        const int can_shrink = hh > r->min_dt && rejections + 1 < PC_CUBIC_MAX_REJECTIONS;
        double ratio_d = 0.0;
        pc_vec3 end_dir = vec3(0.0, 0.0, 0.0);
        int no_end_tangent = 0;
        const cubic_verdict v =
            patch != NULL ? try_cubic(r, &m, patch, &cand, &ratio_d, &end_dir, &no_end_tangent)
                          : CUBIC_INVALID;
        /* an end without q', or with one no cubic can use (a fold end of
         * the orthogonal projection, where q' is finite but huge: every
         * cubic reaching it fails the reach test) */
        const int at_unusable_end = cand.t == b->t && (no_end_tangent || v == CUBIC_INVALID);
        if (at_unusable_end && end_step == 0.0)
            end_step = hh;
        if (at_unusable_end && hh <= PC_CUBIC_END_APPROACH * end_step) {
            const projcurve_status st = straight_rest(r, &m, b, out);
            if (st != PROJCURVE_OK)
                return st;
            break;
        }
        if (v == CUBIC_TOO_FAR && can_shrink) {
            ++rejections;
            h = hh * step_factor(ratio_d);
            continue;
        }
        if (v == CUBIC_INVALID && invalid == 0)
            first_invalid = cand;
        if (v == CUBIC_INVALID && can_shrink && ++invalid < PC_CUBIC_MAX_INVALID) {
            ++rejections;
            h = 0.5 * hh;
            continue;
        }
        projcurve_status st;
        if (v != CUBIC_ACCEPT) {
            /* The straight march takes over where the cubic stays invalid
             * (near a fold, where q' grows without bound) or is still too
             * far at the step floor: the stretch cur-cand. Where that
             * stretch ends beside a fold, its last straight piece, held to
             * the exact tangent there, can miss the angle bound down to
             * the step floor and become a gap (the bumpy sheet of
             * test_trace_far 1e8 from the origin: 181 FAILED ends): then
             * the stretch is undone and the straight march takes the rest
             * of the run, as it would with straight pcurves throughout.
             * The march then goes on from the step tried before the
             * halvings: going on from the halved one, 1/32 of it, made
             * every later candidate there invalid too and the step 32
             * times shorter again at each stretch, down to rounding-sized
             * stretches one after another to the call's limit
             * (linkrods.step surface 15, lifted diagonal, t = 0.9827). */
            const int whole = v == CUBIC_INVALID && first_invalid.t > cand.t;
            const size_t first = out->count, gaps = r->gaps, forced = r->forced;
            const int cur_gap = first > 0 ? out->items[first - 1].gap : 0; /* (a gap marks
                                                                     the vertex before it) */
            double straight_step = 0.0;
            st = straight_stretch(r, &m.cur, &cand, out, &straight_step);
            if (st == PROJCURVE_OK && r->gaps > gaps && cand.t < b->t) {
                out->count = first;
                if (first > 0)
                    out->items[first - 1].gap = cur_gap;
                r->gaps = gaps;
                r->forced = forced;
                st = straight_stretch(r, &m.cur, b, out, &straight_step);
            }
            h = fmax(h, fmax(whole ? first_invalid.t - m.cur.t : hh, straight_step));
        } else {
            st = pc_refine_output(r, out, &cand);
            /* A step cut short by the run end or a knot line says nothing
             * against the old h. */
            const double f = step_factor(ratio_d);
            h = hh * f > h || hh >= h ? hh * f : h;
        }
        if (st != PROJCURVE_OK)
            return st;
        advance(&m, &out->items[out->count - 1], end_dir);
        rejections = invalid = 0;
    }
    r->step = h;
    return PROJCURVE_OK;
}
