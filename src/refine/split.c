/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The subdivision loop shared by every stage: a segment is split at the
 * first knot line its chord crosses (so that each piece lies in one patch),
 * then at the farthest point of the exact projection while its Hausdorff
 * distance exceeds eps_D; where no vertex on the projection can be found,
 * the segment becomes a gap. Pending right ends wait on an explicit stack, so
 * the vertices come out in order and the output can stop at the piece
 * budget with a valid prefix.
 */
#include <math.h>

#include "refine/refine_internal.h"

/* Bound of pending vertices. A Hausdorff split keeps both parts at least
 * PC_SPLIT_MIN_FRACTION of the segment, so depth 200 means intervals of
 * 0.8^200 ~ 1e-19 of the first: never the binding limit before min_dt. */
#define PC_SPLIT_STACK 200
#define PC_SPLIT_MIN_FRACTION 0.2
/* Past this depth a segment that still crosses a knot line is a gap: the
 * crossings found so far did not converge to one (never seen on a curve the
 * corrector can follow). */
#define PC_SPLIT_EXACT_DEPTH 100

typedef enum split_action { SPLIT_ACCEPT, SPLIT_AT, SPLIT_GAP } split_action;

/* Decides what to do with the segment a-b; on SPLIT_AT, *c is the vertex;
 * SPLIT_GAP when no vertex on the projection can be found inside. */
static split_action decide(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                           int hausdorff, size_t depth, pc_rvertex *c)
{
    const double dt = fabs(b->t - a->t);
    const pc_bezier_patch *patch = pc_refine_common_patch(r, a, b);
    /* Split at the first knot line crossed from a; failing that, at the
     * last one, reached from b: so a gap is left only between the lines
     * the projection cannot be followed across (a run of thin spans whose
     * nets rounding blew up, linkrods.step surface 16), not over the whole
     * traced segment that stepped over them. */
    if (patch == NULL)
        return depth < PC_SPLIT_EXACT_DEPTH &&
                       (pc_refine_knot_crossing(r, a, b, c) || pc_refine_knot_crossing(r, b, a, c))
                   ? SPLIT_AT
                   : SPLIT_GAP;
    if (!hausdorff || dt <= r->min_dt || depth + 1 >= PC_SPLIT_STACK)
        return SPLIT_ACCEPT;
    double t_far, cw[PC_PIECE_MAX_CW];
    const int n = pc_refine_compose(patch, a, b, cw);
    const double dist = pc_refine_deviation(r, n, cw, a, b, r->eps_d, &t_far);
    if (dist <= r->eps_d)
        return SPLIT_ACCEPT;
    /* Split at the farthest point, kept away from the ends so that both
     * parts shrink. */
    const double lo = a->t + PC_SPLIT_MIN_FRACTION * (b->t - a->t);
    const double hi = b->t - PC_SPLIT_MIN_FRACTION * (b->t - a->t);
    double t = t_far;
    if ((t - lo) * (t - hi) > 0.0)
        t = fabs(t - lo) < fabs(t - hi) ? lo : hi;
    /* the corrector fails inside: the exact curve is out of reach here */
    return pc_refine_exact_point(r, a, b, t, c) ? SPLIT_AT : SPLIT_GAP;
}

projcurve_status pc_refine_split(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                 int hausdorff, pc_vertex_list *out)
{
    pc_rvertex stack[PC_SPLIT_STACK];
    size_t top = 0;
    pc_rvertex cur = *a;
    stack[top++] = *b;
    while (top > 0) {
        pc_rvertex c;
        const pc_rvertex next = stack[top - 1];
        const split_action action =
            top < PC_SPLIT_STACK ? decide(r, &cur, &next, hausdorff, top, &c) : SPLIT_ACCEPT;
        if (action == SPLIT_AT) {
            stack[top++] = c;
            continue;
        }
        const projcurve_status st = action == SPLIT_GAP ? pc_refine_output_gap(r, out, &next, PC_GAP_FAILED)
                                                        : pc_refine_output(r, out, &next);
        if (st != PROJCURVE_OK)
            return st;
        cur = next;
        --top;
    }
    return PROJCURVE_OK;
}
