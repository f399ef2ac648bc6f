/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Edges split differently by their two faces (brep/sew.h).
 *
 * IGES face sets often trim a face along an edge with one piece where the
 * neighbour uses two (a vertex of a third face lies on the edge). The
 * one-to-one match of sew.c leaves all three pieces of one use, and a curve
 * projected across that edge would not chain there. Each short piece lies
 * along the long one, so it takes the long piece's edge: the chaining then
 * matches ends on the edge by their 3D points, as for any shared edge.
 */
#include "brep/sew.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"

#define SPLIT_SAMPLES 33      /* points along each piece of one use */
#define SPLIT_PROBES 5        /* points of a short piece measured to a long one */
#define SPLIT_GOLDEN_STEPS 60 /* the bracket shrinks by 0.618^60, about 3e-13 */
#define SPLIT_NONE ((size_t)-1)

typedef struct lone_piece {
    const projcurve_face *face;
    pc_face_piece *piece;
    double t0, t1;
    double p[SPLIT_SAMPLES][3];
    double box[6]; /* of the samples, grown by tol and the longest chord */
    double length; /* of the polyline through the samples */
    size_t parent; /* the longer piece it lies along, or SPLIT_NONE */
    int sense;     /* +1: it runs the way its parent's curve runs */
    int has_child; /* some shorter piece lies along it */
} lone_piece;

static double dist3(const double *a, const double *b)
{
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

static int by_id(const void *a, const void *b)
{
    const long x = *(const long *)a, y = *(const long *)b;
    return (x > y) - (x < y);
}

static int by_length_down(const void *a, const void *b)
{
    const lone_piece *x = a, *y = b;
    return (x->length < y->length) - (x->length > y->length);
}

static size_t id_uses(const long *ids, size_t n, long id)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (ids[mid] < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t k = lo;
    while (k < n && ids[k] == id)
        ++k;
    return k - lo;
}

/* Samples the piece; 0 when its surface cannot be evaluated on it. The
 * box grows by the longest chord so that it holds the curve between
 * samples as well as the samples (the piece bends little between 33 of
 * its points). */
static int sample_piece(lone_piece *lp, double tol)
{
    pc_curve2_domain(&lp->piece->curve, &lp->t0, &lp->t1);
    double chord = 0.0;
    lp->length = 0.0;
    for (int k = 0; k < SPLIT_SAMPLES; ++k) {
        const double t = lp->t0 + (lp->t1 - lp->t0) * k / (SPLIT_SAMPLES - 1);
        if (!pc_sew_piece_point(lp->face, lp->piece, t, lp->p[k]))
            return 0;
        if (k > 0) {
            const double c = dist3(lp->p[k - 1], lp->p[k]);
            lp->length += c;
            chord = fmax(chord, c);
        }
    }
    for (int a = 0; a < 3; ++a) {
        lp->box[a] = INFINITY;
        lp->box[3 + a] = -INFINITY;
        for (int k = 0; k < SPLIT_SAMPLES; ++k) {
            lp->box[a] = fmin(lp->box[a], lp->p[k][a]);
            lp->box[3 + a] = fmax(lp->box[3 + a], lp->p[k][a]);
        }
        lp->box[a] -= tol + chord;
        lp->box[3 + a] += tol + chord;
    }
    lp->parent = SPLIT_NONE;
    lp->sense = 1;
    return 1;
}

static double dist_at(const lone_piece *a, double t, const double x[3])
{
    double p[3];
    return pc_sew_piece_point(a->face, a->piece, t, p) ? dist3(p, x) : INFINITY;
}

/* The distance from x to a's image and the parameter there: the nearest
 * sample, then a golden-section search over the two chords beside it. */
static double dist_to_piece(const lone_piece *a, const double x[3], double *t_at)
{
    size_t best = 0;
    double best_d = INFINITY;
    for (size_t k = 0; k < SPLIT_SAMPLES; ++k) {
        const double d = dist3(a->p[k], x);
        if (d < best_d)
            best = k, best_d = d;
    }
    const double h = (a->t1 - a->t0) / (SPLIT_SAMPLES - 1);
    double lo = a->t0 + h * (double)(best > 0 ? best - 1 : 0);
    double hi = a->t0 + h * (double)(best + 1 < SPLIT_SAMPLES ? best + 1 : best);
    *t_at = a->t0 + h * (double)best;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    double fc = dist_at(a, c, x), fd = dist_at(a, d, x);
    for (int i = 0; i < SPLIT_GOLDEN_STEPS; ++i) {
        if (fc < fd) {
            hi = d, d = c, fd = fc;
            c = hi - g * (hi - lo);
            fc = dist_at(a, c, x);
        } else {
            lo = c, c = d, fc = fd;
            d = lo + g * (hi - lo);
            fd = dist_at(a, d, x);
        }
    }
    const double f = fmin(fc, fd);
    if (f < best_d) {
        *t_at = fc < fd ? c : d;
        return f;
    }
    return best_d;
}

static int in_box(const double box[6], const double p[3])
{
    for (int a = 0; a < 3; ++a)
        if (p[a] < box[a] || p[a] > box[3 + a])
            return 0;
    return 1;
}

/* 1 when b, of another face, lies along a (a no shorter than b): SPLIT_PROBES points
 * of b within tol of a's image (*gap the farthest), at parameters of a that
 * move one way (b does not fold back along a); *sense +1 when they grow. */
static int lies_along(const lone_piece *b, const lone_piece *a, double tol, int *sense,
                      double *gap)
{
    if (b->face == a->face)
        return 0;
    double t[SPLIT_PROBES], worst = 0.0;
    for (int k = 0; k < SPLIT_PROBES; ++k) {
        const double *x = b->p[k * (SPLIT_SAMPLES - 1) / (SPLIT_PROBES - 1)];
        const double d = in_box(a->box, x) ? dist_to_piece(a, x, &t[k]) : INFINITY;
        if (!(d <= tol))
            return 0;
        worst = fmax(worst, d);
    }
    const int up = t[SPLIT_PROBES - 1] > t[0];
    for (int k = 1; k < SPLIT_PROBES; ++k)
        if ((t[k] > t[k - 1]) != up)
            return 0;
    *sense = up ? 1 : -1;
    *gap = worst;
    return 1;
}

/* The pieces whose edge has one use, sampled; longest first. A piece
 * shorter than 2 tol is left out: near a vertex it would lie "along" any
 * edge through it. */
static size_t collect_lone(projcurve_face *const *faces, size_t n, const long *ids, size_t n_ids,
                           double tol, lone_piece *out)
{
    size_t m = 0;
    for (size_t f = 0; f < n; ++f)
        for (size_t l = 0; l < faces[f]->n_loops; ++l)
            for (size_t k = 0; k < faces[f]->loops[l].n_pieces; ++k) {
                pc_face_piece *p = &faces[f]->loops[l].pieces[k];
                if (p->edge < 0 || (p->flags & PC_PIECE_DEGENERATE) ||
                    id_uses(ids, n_ids, p->edge) != 1)
                    continue;
                out[m] = (lone_piece){.face = faces[f], .piece = p};
                if (sample_piece(&out[m], tol) && out[m].length > 2.0 * tol)
                    ++m;
            }
    qsort(out, m, sizeof *out, by_length_down);
    return m;
}

/* Each group (a long piece and the pieces along it) takes its smallest id. */
static size_t join_groups(lone_piece *lp, size_t m)
{
    size_t shared = 0;
    for (size_t j = 0; j < m; ++j) {
        const size_t i = lp[j].parent;
        if (i != SPLIT_NONE && lp[j].piece->edge < lp[i].piece->edge)
            lp[i].piece->edge = lp[j].piece->edge;
    }
    for (size_t j = 0; j < m; ++j) {
        const size_t i = lp[j].parent;
        if (i == SPLIT_NONE)
            continue;
        lp[j].piece->edge = lp[i].piece->edge;
        lp[j].piece->edge_sense = lp[j].sense * lp[i].piece->edge_sense;
        shared += !lp[i].has_child;
        lp[i].has_child = 1;
    }
    return shared;
}

projcurve_status pc_sew_split_pieces(projcurve_context *ctx, projcurve_face *const *faces,
                                     size_t n, double tol, size_t *shared, double *gap)
{
    *shared = 0;
    *gap = 0.0;
    size_t total = 0;
    for (size_t f = 0; f < n; ++f)
        for (size_t l = 0; l < faces[f]->n_loops; ++l)
            total += faces[f]->loops[l].n_pieces;
    long *ids = malloc((total + 1) * sizeof *ids);
    lone_piece *lp = malloc((total + 1) * sizeof *lp);
    if (ids == NULL || lp == NULL) {
        free(ids);
        free(lp);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory sewing split edges");
    }
    size_t n_ids = 0;
    for (size_t f = 0; f < n; ++f)
        for (size_t l = 0; l < faces[f]->n_loops; ++l)
            for (size_t k = 0; k < faces[f]->loops[l].n_pieces; ++k)
                if (faces[f]->loops[l].pieces[k].edge >= 0)
                    ids[n_ids++] = faces[f]->loops[l].pieces[k].edge;
    qsort(ids, n_ids, sizeof *ids, by_id);
    const size_t m = collect_lone(faces, n, ids, n_ids, tol, lp);
    /* a piece lies along a longer one that lies along none: the loop over
     * i < j sees only longer pieces, whose parents are already known */
    for (size_t j = 0; j < m; ++j)
        for (size_t i = 0; i < j; ++i) {
            double d;
            if (lp[i].parent == SPLIT_NONE && lies_along(&lp[j], &lp[i], tol, &lp[j].sense, &d)) {
                lp[j].parent = i;
                *gap = fmax(*gap, d);
                break;
            }
        }
    *shared = join_groups(lp, m);
    free(ids);
    free(lp);
    return PROJCURVE_OK;
}
