/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/sew.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"

typedef struct sew_piece {
    pc_face_piece *piece;
    double p[3][3]; /* 3D start, middle, end along the curve's parameter */
    size_t parent;  /* union-find */
    int sense;      /* relative to the parent: +1 same direction */
} sew_piece;

static double dist3(const double *a, const double *b)
{
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

int pc_sew_piece_point(const projcurve_face *f, const pc_face_piece *piece, double t,
                       double out[3])
{
    double uv[2], d[4];
    pc_curve2_eval(&piece->curve, t, uv);
    projcurve_surface_domain(NULL, f->surface, d);
    return projcurve_surface_eval(NULL, f->surface, fmin(fmax(uv[0], d[0]), d[1]),
                                  fmin(fmax(uv[1], d[2]), d[3]), 0, out) == PROJCURVE_OK;
}

static int sample(const projcurve_face *f, pc_face_piece *piece, sew_piece *out)
{
    double t0, t1;
    pc_curve2_domain(&piece->curve, &t0, &t1);
    for (int k = 0; k < 3; ++k)
        if (!pc_sew_piece_point(f, piece, t0 + 0.5 * k * (t1 - t0), out->p[k]))
            return 0;
    out->piece = piece;
    return 1;
}

/* Root of i and the sense of i relative to it (path halving keeps the
 * senses composed). */
static size_t find(sew_piece *s, size_t i, int *sense)
{
    int acc = 1;
    while (s[i].parent != i) {
        acc *= s[i].sense;
        i = s[i].parent;
    }
    *sense = acc;
    return i;
}

static int by_middle_x(const void *a, const void *b)
{
    const sew_piece *x = a, *y = b;
    return (x->p[1][0] > y->p[1][0]) - (x->p[1][0] < y->p[1][0]);
}

/* +1 / -1 when a and b run along one edge (the same way / the opposite
 * way), 0 when they do not. */
static int match(const sew_piece *a, const sew_piece *b, double tol)
{
    if (dist3(a->p[1], b->p[1]) > tol)
        return 0;
    if (dist3(a->p[0], b->p[0]) <= tol && dist3(a->p[2], b->p[2]) <= tol)
        return 1;
    if (dist3(a->p[0], b->p[2]) <= tol && dist3(a->p[2], b->p[0]) <= tol)
        return -1;
    return 0;
}

/* The split and gap passes over the pieces the one-to-one match left. */
static projcurve_status sew_lone_pieces(projcurve_context *ctx, projcurve_face *const *faces,
                                        size_t n, double tol, size_t *shared, double *used_tol)
{
    size_t split = 0, gapped = 0;
    double gap = 0.0;
    projcurve_status st = pc_sew_split_pieces(ctx, faces, n, tol, &split, &gap);
    if (st == PROJCURVE_OK)
        st = pc_sew_split_pieces(ctx, faces, n, PC_SEW_GAP_FACTOR * tol, &gapped, &gap);
    *shared += split + gapped;
    *used_tol = fmax(tol, gap);
    return st;
}

projcurve_status pc_sew_faces(projcurve_context *ctx, projcurve_face *const *faces, size_t n,
                              double tol, size_t *shared, double *used_tol)
{
    *used_tol = tol;
    size_t total = 0;
    for (size_t f = 0; f < n; ++f)
        for (size_t l = 0; l < faces[f]->n_loops; ++l)
            total += faces[f]->loops[l].n_pieces;
    sew_piece *s = malloc((total + 1) * sizeof *s);
    if (s == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory sewing faces");
    size_t m = 0;
    for (size_t f = 0; f < n; ++f)
        for (size_t l = 0; l < faces[f]->n_loops; ++l)
            for (size_t k = 0; k < faces[f]->loops[l].n_pieces; ++k) {
                pc_face_piece *p = &faces[f]->loops[l].pieces[k];
                if (p->edge < 0 || !sample(faces[f], p, &s[m]))
                    continue;
                if (dist3(s[m].p[0], s[m].p[1]) + dist3(s[m].p[1], s[m].p[2]) <= tol)
                    continue; /* a pole */
                ++m;
            }
    qsort(s, m, sizeof *s, by_middle_x);
    for (size_t i = 0; i < m; ++i)
        s[i].parent = i, s[i].sense = 1;
    /* candidates: middles within tol in x (a sweep over the sorted list) */
    for (size_t i = 0; i < m; ++i)
        for (size_t j = i + 1; j < m && s[j].p[1][0] - s[i].p[1][0] <= tol; ++j) {
            const int how = match(&s[i], &s[j], tol);
            int si, sj;
            const size_t ri = find(s, i, &si), rj = find(s, j, &sj);
            if (how == 0 || ri == rj)
                continue;
            /* j runs `how` relative to i: rj's sense relative to ri */
            s[rj].parent = ri;
            s[rj].sense = si * how * sj;
        }
    /* each group: the smallest original id, senses relative to the root */
    long *group_id = malloc((m + 1) * sizeof *group_id);
    size_t *group_size = calloc(m + 1, sizeof *group_size);
    if (group_id == NULL || group_size == NULL) {
        free(s);
        free(group_id);
        free(group_size);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory sewing faces");
    }
    for (size_t i = 0; i < m; ++i)
        group_id[i] = -1;
    for (size_t i = 0; i < m; ++i) {
        int sense;
        const size_t r = find(s, i, &sense);
        ++group_size[r];
        if (group_id[r] < 0 || s[i].piece->edge < group_id[r])
            group_id[r] = s[i].piece->edge;
    }
    *shared = 0;
    for (size_t i = 0; i < m; ++i)
        *shared += group_size[i] > 1;
    for (size_t i = 0; i < m; ++i) {
        int sense;
        const size_t r = find(s, i, &sense);
        if (group_size[r] < 2)
            continue;
        s[i].piece->edge = group_id[r];
        s[i].piece->edge_sense = sense;
    }
    free(group_id);
    free(group_size);
    free(s);
    return sew_lone_pieces(ctx, faces, n, tol, shared, used_tol);
}
