/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/classify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"

/* Candidate reference points tried in a cell: a lattice of up to this many
 * a side, the centre first. A cell with none clear of its segments by tol
 * has no reference, and its queries count over every segment. */
#define PC_CLASSIFY_REF_LATTICE 8

static double orient(double ax, double ay, double bx, double by, double cx, double cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static double dist2_segment(const double *s, double x, double y)
{
    const double dx = s[2] - s[0], dy = s[3] - s[1];
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((x - s[0]) * dx + (y - s[1]) * dy) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    const double ex = x - s[0] - t * dx, ey = y - s[1] - t * dy;
    return ex * ex + ey * ey;
}

/* A ray from (x, y) to +x crosses s: +1 going up, -1 going down, 0 not. */
static int ray_crossing(const double *s, double x, double y)
{
    if ((s[1] <= y) == (s[3] <= y))
        return 0;
    const double xc = s[0] + (y - s[1]) * (s[2] - s[0]) / (s[3] - s[1]);
    if (!(xc > x))
        return 0;
    return s[3] > s[1] ? 1 : -1;
}

int pc_winding_brute(const double *seg, size_t n_seg, double x, double y)
{
    int w = 0;
    for (size_t i = 0; i < n_seg; ++i)
        w += ray_crossing(seg + 4 * i, x, y);
    return w;
}

void pc_classifier_free(pc_classifier *c)
{
    free(c->seg);
    free(c->cell_start);
    free(c->cell_seg);
    free(c->ref);
    free(c->ref_winding);
    memset(c, 0, sizeof *c);
}

static size_t cell_of(double t, double t0, double d, size_t n)
{
    const double k = floor((t - t0) / d);
    return k < 0.0 ? 0 : (k >= (double)n ? n - 1 : (size_t)k);
}

static void segment_cells(const pc_classifier *c, const double *s, size_t r[4])
{
    r[0] = cell_of(fmin(s[0], s[2]) - c->tol, c->x0, c->dx, c->nx);
    r[1] = cell_of(fmax(s[0], s[2]) + c->tol, c->x0, c->dx, c->nx);
    r[2] = cell_of(fmin(s[1], s[3]) - c->tol, c->y0, c->dy, c->ny);
    r[3] = cell_of(fmax(s[1], s[3]) + c->tol, c->y0, c->dy, c->ny);
}

/* The cell lists' total length on the current grid. */
static size_t registrations(const pc_classifier *c)
{
    size_t total = 0;
    for (size_t i = 0; i < c->n_seg; ++i) {
        size_t r[4];
        segment_cells(c, c->seg + 4 * i, r);
        total += (r[1] - r[0] + 1) * (r[3] - r[2] + 1);
    }
    return total;
}

/* Long segments across the grid are listed in every cell of their box: a
 * loop of many of them (a zigzag over the face) would list them
 * quadratically often. The grid is coarsened, halving each side, until
 * the lists hold at most PC_CLASSIFY_MAX_LISTED_PER_SEGMENT entries a
 * segment (one cell at worst: then n_seg entries), so memory stays linear
 * and the build ends after at most log2 of the cells halvings. */
static void coarsen_grid(pc_classifier *c)
{
    const size_t limit = PC_CLASSIFY_MAX_LISTED_PER_SEGMENT * (c->n_seg + 1);
    while ((c->nx > 1 || c->ny > 1) && registrations(c) > limit) {
        const double w = c->dx * (double)c->nx, h = c->dy * (double)c->ny;
        c->nx = c->nx > 1 ? (c->nx + 1) / 2 : 1;
        c->ny = c->ny > 1 ? (c->ny + 1) / 2 : 1;
        c->dx = w / (double)c->nx;
        c->dy = h / (double)c->ny;
    }
}

static projcurve_status fill_cells(projcurve_context *ctx, pc_classifier *c)
{
    const size_t n_cells = c->nx * c->ny;
    c->cell_start = calloc(n_cells + 1, sizeof *c->cell_start);
    if (c->cell_start == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory classifying a face");
    size_t total = 0;
    for (size_t i = 0; i < c->n_seg; ++i) {
        size_t r[4];
        segment_cells(c, c->seg + 4 * i, r);
        for (size_t y = r[2]; y <= r[3]; ++y)
            for (size_t x = r[0]; x <= r[1]; ++x)
                ++c->cell_start[y * c->nx + x + 1];
        total += (r[1] - r[0] + 1) * (r[3] - r[2] + 1);
    }
    for (size_t k = 0; k < n_cells; ++k)
        c->cell_start[k + 1] += c->cell_start[k];
    c->cell_seg = malloc((total + 1) * sizeof *c->cell_seg);
    size_t *fill = malloc((n_cells + 1) * sizeof *fill);
    if (c->cell_seg == NULL || fill == NULL) {
        free(fill);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory classifying a face");
    }
    memcpy(fill, c->cell_start, n_cells * sizeof *fill);
    for (size_t i = 0; i < c->n_seg; ++i) {
        size_t r[4];
        segment_cells(c, c->seg + 4 * i, r);
        for (size_t y = r[2]; y <= r[3]; ++y)
            for (size_t x = r[0]; x <= r[1]; ++x)
                c->cell_seg[fill[y * c->nx + x]++] = i;
    }
    free(fill);
    return PROJCURVE_OK;
}

static int clear_of_cell(const pc_classifier *c, size_t cell, double x, double y)
{
    const double t2 = c->tol * c->tol;
    for (size_t k = c->cell_start[cell]; k < c->cell_start[cell + 1]; ++k)
        if (!(dist2_segment(c->seg + 4 * c->cell_seg[k], x, y) > t2))
            return 0;
    return 1;
}

/* A crossing of a row's line: its x and +1 going up, -1 going down. */
typedef struct crossing {
    double x;
    int sign;
} crossing;

static int by_x(const void *a, const void *b)
{
    const crossing *p = a, *q = b;
    return (p->x > q->x) - (p->x < q->x);
}

/* The winding number of (x, row's y): the signs of the crossings with
 * xc > x (the rule of pc_winding_brute), from suffix sums over the sorted
 * crossings: the first crossing beyond x by bisection. */
static int row_winding(const crossing *xs, const int *suffix, size_t n, double x)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (xs[mid].x > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return suffix[lo];
}

/* The crossings of the line y (the middle of row j) with every segment,
 * sorted, with suffix sums; returns their number. A segment that crosses
 * the line does so inside a cell of row j, so it is listed there: only
 * those are looked at, each once (seen[] holds the last row that looked). */
static size_t row_crossings(const pc_classifier *c, size_t j, double y, crossing *xs,
                            int *suffix, size_t *seen)
{
    size_t n = 0;
    for (size_t k = c->cell_start[j * c->nx]; k < c->cell_start[(j + 1) * c->nx]; ++k) {
        const size_t i = c->cell_seg[k];
        if (seen[i] == j)
            continue;
        seen[i] = j;
        const double *s = c->seg + 4 * i;
        if ((s[1] <= y) == (s[3] <= y))
            continue;
        xs[n].x = s[0] + (y - s[1]) * (s[2] - s[0]) / (s[3] - s[1]);
        xs[n++].sign = s[3] > s[1] ? 1 : -1;
    }
    qsort(xs, n, sizeof *xs, by_x);
    suffix[n] = 0;
    for (size_t k = n; k > 0; --k)
        suffix[k - 1] = suffix[k] + xs[k - 1].sign;
    return n;
}

/* Candidate x positions on a cell's row line, the centre first. */
#define PC_CLASSIFY_ROW_CANDIDATES 16

/* References: a point of the cell's row line (the centre, else one of
 * PC_CLASSIFY_ROW_CANDIDATES along it) clear of the cell's segments by
 * tol, its winding number from the row's sorted crossings; failing that a
 * clear lattice point of the cell, counted in full. */
static projcurve_status place_references(projcurve_context *ctx, pc_classifier *c)
{
    const size_t n_cells = c->nx * c->ny;
    c->ref = malloc(2 * n_cells * sizeof *c->ref);
    c->ref_winding = malloc(n_cells * sizeof *c->ref_winding);
    crossing *xs = malloc((c->n_seg + 1) * sizeof *xs);
    int *suffix = malloc((c->n_seg + 1) * sizeof *suffix);
    size_t *seen = malloc((c->n_seg + 1) * sizeof *seen);
    if (c->ref == NULL || c->ref_winding == NULL || xs == NULL || suffix == NULL || seen == NULL) {
        free(xs);
        free(suffix);
        free(seen);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory classifying a face");
    }
    for (size_t i = 0; i <= c->n_seg; ++i)
        seen[i] = (size_t)-1;
    for (size_t j = 0; j < c->ny; ++j) {
        const double y = c->y0 + ((double)j + 0.5) * c->dy;
        const size_t n = row_crossings(c, j, y, xs, suffix, seen);
        for (size_t i = 0; i < c->nx; ++i) {
            const size_t cell = j * c->nx + i;
            c->ref[2 * cell] = NAN;
            for (int a = -1; a < PC_CLASSIFY_ROW_CANDIDATES && isnan(c->ref[2 * cell]); ++a) {
                const double f = a < 0 ? 0.5 : (a + 0.5) / PC_CLASSIFY_ROW_CANDIDATES;
                const double x = c->x0 + ((double)i + f) * c->dx;
                if (!clear_of_cell(c, cell, x, y))
                    continue;
                c->ref[2 * cell] = x;
                c->ref[2 * cell + 1] = y;
                c->ref_winding[cell] = row_winding(xs, suffix, n, x);
            }
        }
    }
    free(xs);
    free(suffix);
    free(seen);
    for (size_t cell = 0; cell < n_cells; ++cell) {
        if (!isnan(c->ref[2 * cell]))
            continue;
        const double cx = c->x0 + (double)(cell % c->nx) * c->dx;
        const double cy = c->y0 + (double)(cell / c->nx) * c->dy;
        int found = 0;
        for (int n = 2; n <= PC_CLASSIFY_REF_LATTICE && !found; n *= 2)
            for (int a = 0; a < n && !found; ++a)
                for (int b = 0; b < n && !found; ++b) {
                    const double x = cx + ((a + 0.5) / n) * c->dx;
                    const double y = cy + ((b + 0.5) / n) * c->dy;
                    if (clear_of_cell(c, cell, x, y)) {
                        found = 1;
                        c->ref[2 * cell] = x;
                        c->ref[2 * cell + 1] = y;
                        c->ref_winding[cell] = pc_winding_brute(c->seg, c->n_seg, x, y);
                    }
                }
        /* none: ref stays NaN, the cell's queries count in full */
    }
    return PROJCURVE_OK;
}

static void size_grid(pc_classifier *c, const double box[4])
{
    const double w = box[1] - box[0], h = box[3] - box[2];
    double target = PC_CLASSIFY_CELLS_PER_SEGMENT * (double)c->n_seg;
    if (target > (double)PC_CLASSIFY_MAX_CELLS)
        target = (double)PC_CLASSIFY_MAX_CELLS;
    double nx = ceil(sqrt(target * w / h)), ny = ceil(target / nx);
    nx = fmax(1.0, fmin(nx, sqrt((double)PC_CLASSIFY_MAX_CELLS)));
    ny = fmax(1.0, fmin(ny, (double)PC_CLASSIFY_MAX_CELLS / nx));
    c->nx = (size_t)nx;
    c->ny = (size_t)ny;
    c->x0 = box[0];
    c->y0 = box[2];
    c->dx = w / (double)c->nx;
    c->dy = h / (double)c->ny;
}

projcurve_status pc_classifier_build(projcurve_context *ctx, pc_classifier *c, size_t n_polys,
                                     const double *const *polys, const size_t *n_pts, double tol)
{
    memset(c, 0, sizeof *c);
    c->tol = tol;
    size_t n = 0;
    for (size_t k = 0; k < n_polys; ++k)
        n += n_pts[k];
    c->seg = malloc((4 * n + 4) * sizeof *c->seg);
    if (c->seg == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory classifying a face");
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (size_t k = 0; k < n_polys; ++k)
        for (size_t i = 0; i < n_pts[k]; ++i) {
            const double *a = polys[k] + 2 * i, *b = polys[k] + 2 * ((i + 1) % n_pts[k]);
            double *s = c->seg + 4 * c->n_seg++;
            s[0] = a[0], s[1] = a[1], s[2] = b[0], s[3] = b[1];
            box[0] = fmin(box[0], a[0]), box[1] = fmax(box[1], a[0]);
            box[2] = fmin(box[2], a[1]), box[3] = fmax(box[3], a[1]);
        }
    if (c->n_seg == 0)
        box[0] = box[2] = 0.0, box[1] = box[3] = 1.0;
    /* grown by 2 tol, so that nothing outside the grid is within tol */
    const double grow = 2.0 * tol + 1e-300;
    box[0] -= grow, box[1] += grow, box[2] -= grow, box[3] += grow;
    size_grid(c, box);
    coarsen_grid(c);
    projcurve_status st = fill_cells(ctx, c);
    if (st == PROJCURVE_OK)
        st = place_references(ctx, c);
    if (st != PROJCURVE_OK)
        pc_classifier_free(c);
    return st;
}

pc_where pc_classify(const pc_classifier *c, double x, double y)
{
    if (!(x >= c->x0 && x <= c->x0 + (double)c->nx * c->dx && y >= c->y0 &&
          y <= c->y0 + (double)c->ny * c->dy))
        return PC_OUT; /* also NaN */
    const size_t cell = cell_of(y, c->y0, c->dy, c->ny) * c->nx + cell_of(x, c->x0, c->dx, c->nx);
    const size_t *first = c->cell_seg + c->cell_start[cell], *last = c->cell_seg + c->cell_start[cell + 1];
    const double t2 = c->tol * c->tol;
    for (const size_t *k = first; k < last; ++k)
        if (dist2_segment(c->seg + 4 * *k, x, y) <= t2)
            return PC_ON;
    const double rx = c->ref[2 * cell], ry = c->ref[2 * cell + 1];
    if (isnan(rx))
        return pc_winding_brute(c->seg, c->n_seg, x, y) != 0 ? PC_IN : PC_OUT;
    int w = c->ref_winding[cell];
    for (const size_t *k = first; k < last; ++k) {
        const double *s = c->seg + 4 * *k;
        const int sa = orient(rx, ry, x, y, s[0], s[1]) > 0.0;
        const int sb = orient(rx, ry, x, y, s[2], s[3]) > 0.0;
        if (sa == sb)
            continue;
        const double o_ref = orient(s[0], s[1], s[2], s[3], rx, ry);
        const double o_pt = orient(s[0], s[1], s[2], s[3], x, y);
        if (o_ref < 0.0 && o_pt > 0.0)
            ++w; /* from the right of the segment to its left */
        else if (o_ref > 0.0 && o_pt < 0.0)
            --w;
    }
    return w != 0 ? PC_IN : PC_OUT;
}
