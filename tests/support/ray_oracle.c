/* SPDX-License-Identifier: BSD-3-Clause */
#include "ray_oracle.h"

#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Triangles are widened by this barycentric margin so that a root near a
 * mesh edge is seeded from both sides, and one that the mesh's chord error
 * moves just past the domain's edge is still seeded. */
#define ORACLE_BARY_MARGIN 0.05
/* In the cells along the domain's edge the margin is wider: a line through
 * a point of the surface's edge meets the mesh's chord just outside the
 * edge's cells whenever the surface curves away there (the polish clamps
 * seeds into the domain). */
#define ORACLE_EDGE_MARGIN 0.5
/* See seed_cell. */
#define ORACLE_NEAR_CELL 0.5
#define ORACLE_NEWTON_ITER 40
/* |S_u x S_v| below this fraction of |S_u| |S_v|: no normal. */
#define ORACLE_NORMAL_REL 1e-10
/* Roots closer than this fraction of the domain are one. */
#define ORACLE_MERGE_REL 1e-7
/* A polished root lies on the line to this fraction of the model. */
#define ORACLE_RESIDUAL_REL 1e-11
#define ORACLE_BLOCK 8
#define ORACLE_GROUP 4 /* blocks per side of a group */

static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}
static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross3(const double *a, const double *b, double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static const double *mesh_point(const pc_oracle_mesh *m, int i, int j)
{
    return m->points + 3 * ((size_t)j * (size_t)(m->cells_u + 1) + (size_t)i);
}

/* The box of the blocks [bi0, bi1) x [bj0, bj1). */
static void group_box(const pc_oracle_mesh *m, int bi0, int bi1, int bj0, int bj1, double box[6])
{
    box[0] = box[1] = box[2] = INFINITY;
    box[3] = box[4] = box[5] = -INFINITY;
    for (int bj = bj0; bj < bj1; ++bj)
        for (int bi = bi0; bi < bi1; ++bi) {
            const double *b = m->block_boxes + 6 * ((size_t)bj * (size_t)m->blocks_u + (size_t)bi);
            for (int k = 0; k < 3; ++k) {
                box[k] = fmin(box[k], b[k]);
                box[k + 3] = fmax(box[k + 3], b[k + 3]);
            }
        }
}

int pc_oracle_mesh_build(pc_oracle_mesh *mesh, pc_oracle_eval_fn eval, void *user,
                         const double domain[4], int cells_u, int cells_v)
{
    double *us = malloc(sizeof(double) * (size_t)(cells_u + 1));
    double *vs = malloc(sizeof(double) * (size_t)(cells_v + 1));
    int ok = us != NULL && vs != NULL;
    if (ok) {
        /* The last sample is the domain's end exactly. */
        for (int i = 0; i <= cells_u; ++i)
            us[i] = i == cells_u ? domain[1] : domain[0] + (domain[1] - domain[0]) * i / cells_u;
        for (int j = 0; j <= cells_v; ++j)
            vs[j] = j == cells_v ? domain[3] : domain[2] + (domain[3] - domain[2]) * j / cells_v;
        ok = pc_oracle_mesh_build_samples(mesh, eval, user, us, cells_u, vs, cells_v);
    }
    free(us);
    free(vs);
    return ok;
}

int pc_oracle_mesh_build_samples(pc_oracle_mesh *mesh, pc_oracle_eval_fn eval, void *user,
                                 const double *us, int cells_u, const double *vs, int cells_v)
{
    memset(mesh, 0, sizeof *mesh);
    mesh->eval = eval;
    mesh->user = user;
    mesh->domain[0] = us[0];
    mesh->domain[1] = us[cells_u];
    mesh->domain[2] = vs[0];
    mesh->domain[3] = vs[cells_v];
    mesh->cells_u = cells_u;
    mesh->cells_v = cells_v;
    mesh->block = ORACLE_BLOCK;
    mesh->blocks_u = (cells_u + ORACLE_BLOCK - 1) / ORACLE_BLOCK;
    mesh->blocks_v = (cells_v + ORACLE_BLOCK - 1) / ORACLE_BLOCK;
    mesh->us = malloc(sizeof(double) * (size_t)(cells_u + 1));
    mesh->vs = malloc(sizeof(double) * (size_t)(cells_v + 1));
    mesh->points = malloc(sizeof(double) * 3 * (size_t)(cells_u + 1) * (size_t)(cells_v + 1));
    mesh->block_boxes = malloc(sizeof(double) * 6 * (size_t)mesh->blocks_u * (size_t)mesh->blocks_v);
    if (!mesh->us || !mesh->vs || !mesh->points || !mesh->block_boxes) {
        pc_oracle_mesh_free(mesh);
        return 0;
    }
    memcpy(mesh->us, us, sizeof(double) * (size_t)(cells_u + 1));
    memcpy(mesh->vs, vs, sizeof(double) * (size_t)(cells_v + 1));
    double all[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (int j = 0; j <= cells_v; ++j) {
        for (int i = 0; i <= cells_u; ++i) {
            double out[9];
            eval(user, us[i], vs[j], 0, out);
            double *p = mesh->points + 3 * ((size_t)j * (size_t)(cells_u + 1) + (size_t)i);
            memcpy(p, out, 3 * sizeof *p);
            for (int k = 0; k < 3; ++k) {
                all[k] = fmin(all[k], p[k]);
                all[k + 3] = fmax(all[k + 3], p[k]);
            }
        }
    }
    for (int k = 0; k < 3; ++k)
        mesh->centre[k] = 0.5 * (all[k] + all[k + 3]);
    mesh->scale = sqrt((all[3] - all[0]) * (all[3] - all[0]) + (all[4] - all[1]) * (all[4] - all[1]) +
                       (all[5] - all[2]) * (all[5] - all[2]));
    mesh->model_size = mesh->scale;
    for (int bj = 0; bj < mesh->blocks_v; ++bj) {
        for (int bi = 0; bi < mesh->blocks_u; ++bi) {
            double *box = mesh->block_boxes + 6 * ((size_t)bj * (size_t)mesh->blocks_u + (size_t)bi);
            box[0] = box[1] = box[2] = INFINITY;
            box[3] = box[4] = box[5] = -INFINITY;
            for (int j = bj * ORACLE_BLOCK; j <= (bj + 1) * ORACLE_BLOCK && j <= cells_v; ++j) {
                for (int i = bi * ORACLE_BLOCK; i <= (bi + 1) * ORACLE_BLOCK && i <= cells_u; ++i) {
                    const double *p = mesh_point(mesh, i, j);
                    for (int k = 0; k < 3; ++k) {
                        box[k] = fmin(box[k], p[k]);
                        box[k + 3] = fmax(box[k + 3], p[k]);
                    }
                }
            }
            /* The widened triangles reach a little past their vertices. */
            for (int k = 0; k < 3; ++k) {
                const double pad = 0.01 * (box[k + 3] - box[k]) + 1e-9 * mesh->scale;
                box[k] -= pad;
                box[k + 3] += pad;
            }
        }
    }
    mesh->groups_u = (mesh->blocks_u + ORACLE_GROUP - 1) / ORACLE_GROUP;
    mesh->groups_v = (mesh->blocks_v + ORACLE_GROUP - 1) / ORACLE_GROUP;
    mesh->group_boxes = malloc(sizeof(double) * 6 * (size_t)mesh->groups_u * (size_t)mesh->groups_v);
    if (!mesh->group_boxes) {
        pc_oracle_mesh_free(mesh);
        return 0;
    }
    for (int gj = 0; gj < mesh->groups_v; ++gj)
        for (int gi = 0; gi < mesh->groups_u; ++gi) {
            const int bi = gi * ORACLE_GROUP, bj = gj * ORACLE_GROUP;
            group_box(mesh, bi, bi + ORACLE_GROUP < mesh->blocks_u ? bi + ORACLE_GROUP : mesh->blocks_u,
                      bj, bj + ORACLE_GROUP < mesh->blocks_v ? bj + ORACLE_GROUP : mesh->blocks_v,
                      mesh->group_boxes + 6 * ((size_t)gj * (size_t)mesh->groups_u + (size_t)gi));
        }
    return 1;
}

void pc_oracle_mesh_free(pc_oracle_mesh *mesh)
{
    free(mesh->us);
    free(mesh->vs);
    mesh->us = mesh->vs = NULL;
    free(mesh->points);
    free(mesh->block_boxes);
    free(mesh->group_boxes);
    mesh->points = NULL;
    mesh->block_boxes = NULL;
    mesh->group_boxes = NULL;
}

static int line_meets_box(const double *box, const double *o, const double *d, int ray_only)
{
    double lo = ray_only ? 0.0 : -INFINITY, hi = INFINITY;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < box[k] || o[k] > box[k + 3])
                return 0;
            continue;
        }
        double a = (box[k] - o[k]) / d[k], b = (box[k + 3] - o[k]) / d[k];
        if (a > b) {
            const double t = a;
            a = b;
            b = t;
        }
        lo = fmax(lo, a);
        hi = fmin(hi, b);
    }
    return lo <= hi;
}

/* Moller-Trumbore with a barycentric range widened by margin: (t, b1, b2). */
static int ray_triangle(const double *o, const double *d, const double *p0, const double *p1,
                        const double *p2, double margin, double *t, double *b1, double *b2)
{
    double e1[3], e2[3], pv[3], tv[3], qv[3];
    sub3(p1, p0, e1);
    sub3(p2, p0, e2);
    cross3(d, e2, pv);
    const double det = dot3(e1, pv);
    if (det == 0.0)
        return 0;
    const double inv = 1.0 / det;
    sub3(o, p0, tv);
    *b1 = dot3(tv, pv) * inv;
    if (*b1 < -margin || *b1 > 1.0 + margin)
        return 0;
    cross3(tv, e1, qv);
    *b2 = dot3(d, qv) * inv;
    if (*b2 < -margin || *b1 + *b2 > 1.0 + margin)
        return 0;
    *t = dot3(e2, qv) * inv;
    return 1;
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* Newton on S(u, v) - o - lambda d = 0 (3 x 3, Cramer), clamped to the
 * domain. Returns 1 when the point lies on the line to the tolerance. */
static int polish(const pc_oracle_mesh *m, const double *o, const double *d, double u, double v,
                  double lambda, pc_oracle_hit *out)
{
    double f[9];
    /* A seed from a widened triangle may lie just outside the domain. */
    u = clampd(u, m->domain[0], m->domain[1]);
    v = clampd(v, m->domain[2], m->domain[3]);
    for (int it = 0; it < ORACLE_NEWTON_ITER; ++it) {
        m->eval(m->user, u, v, 1, f);
        double r[3];
        for (int k = 0; k < 3; ++k)
            r[k] = f[k] - o[k] - lambda * d[k];
        const double *su = f + 3, *sv = f + 6;
        const double nd[3] = {-d[0], -d[1], -d[2]};
        double c[3];
        cross3(sv, nd, c);
        const double det = dot3(su, c);
        if (det == 0.0)
            break;
        /* Cramer: columns su, sv, -d; right side -r. */
        double t1[3], t2[3], t3[3], mr[3] = {-r[0], -r[1], -r[2]};
        cross3(sv, nd, t1);
        cross3(mr, nd, t2);
        cross3(sv, mr, t3);
        const double du = dot3(mr, t1) / det;
        const double dv = dot3(su, t2) / det;
        const double dl = dot3(su, t3) / det;
        u = clampd(u + du, m->domain[0], m->domain[1]);
        v = clampd(v + dv, m->domain[2], m->domain[3]);
        lambda += dl;
        if (fabs(du) + fabs(dv) < 1e-15 * (m->domain[1] - m->domain[0] + m->domain[3] - m->domain[2]))
            break;
    }
    m->eval(m->user, u, v, 1, f);
    double w[3], c[3];
    sub3(f, o, w);
    const double dn = sqrt(dot3(d, d));
    cross3(w, d, c);
    const double dist = sqrt(dot3(c, c)) / dn;
    if (!(dist <= ORACLE_RESIDUAL_REL * m->scale + pc_oracle_resolution(u, v, f)))
        return 0;
    double n[3];
    cross3(f + 3, f + 6, n);
    const double nn = sqrt(dot3(n, n));
    out->u = u;
    out->v = v;
    out->lambda = dot3(w, d) / (dn * dn);
    out->lambda_lo = out->lambda_hi = out->lambda;
    /* Where S_u x S_v degenerates (a pole, a span of zero width) the
     * normal, hence grazing, is undecided: NaN, which every test of it
     * below treats as possibly grazing. */
    const double nu = sqrt(dot3(f + 3, f + 3)) * sqrt(dot3(f + 6, f + 6));
    out->cos_dir = nn > ORACLE_NORMAL_REL * nu ? fabs(dot3(n, d)) / (nn * dn) : NAN;
    const double span_u = m->domain[1] - m->domain[0], span_v = m->domain[3] - m->domain[2];
    out->edge = fmin(fmin(u - m->domain[0], m->domain[1] - u) / span_u,
                     fmin(v - m->domain[2], m->domain[3] - v) / span_v);
    return 1;
}

double pc_oracle_resolution(double u, double v, const double f[9])
{
    const double ulp_u = nextafter(fabs(u), INFINITY) - fabs(u);
    const double ulp_v = nextafter(fabs(v), INFINITY) - fabs(v);
    return sqrt(dot3(f + 3, f + 3)) * ulp_u + sqrt(dot3(f + 6, f + 6)) * ulp_v;
}

/* Fraction of the model's size plus its coordinates' magnitude within
 * which two points of a line are one. */
#define ORACLE_SAME_POINT_REL 1e-8

double pc_oracle_same_point(const pc_oracle_mesh *m, const double origin[3], const double dir[3])
{
    double oc[3];
    sub3(origin, m->centre, oc);
    const double magnitude = sqrt(dot3(m->centre, m->centre)) + sqrt(dot3(oc, oc));
    return ORACLE_SAME_POINT_REL * (m->model_size + magnitude) / sqrt(dot3(dir, dir));
}

static int same_root(const pc_oracle_mesh *m, const pc_oracle_hit *a, const pc_oracle_hit *b)
{
    return fabs(a->u - b->u) <= ORACLE_MERGE_REL * (m->domain[1] - m->domain[0]) &&
           fabs(a->v - b->v) <= ORACLE_MERGE_REL * (m->domain[3] - m->domain[2]);
}

/* Polishes a seed and records the root unless it is a copy of one found. */
static int add_seed(const pc_oracle_mesh *m, const double *o, const double *d, int ray_only,
                    double u, double v, double lambda, pc_oracle_hit *hits, size_t capacity,
                    size_t *count)
{
    pc_oracle_hit h;
    if (!polish(m, o, d, u, v, lambda, &h))
        return 0;
    if (ray_only && !(h.lambda > 0.0))
        return 0;
    for (size_t q = 0; q < *count && q < capacity; ++q)
        if (same_root(m, &hits[q], &h)) { /* a copy: its flags count too */
            hits[q].cos_dir = fmin(hits[q].cos_dir, h.cos_dir);
            hits[q].edge = fmin(hits[q].edge, h.edge);
            return 1;
        }
    if (*count < capacity)
        hits[*count] = h;
    ++*count;
    return 1;
}

static void seed_cell(const pc_oracle_mesh *m, const double *o, const double *d, int ray_only,
                      int i, int j, pc_oracle_hit *hits, size_t capacity, size_t *count)
{
    const double u0 = m->us[i], du = m->us[i + 1] - m->us[i];
    const double v0 = m->vs[j], dv = m->vs[j + 1] - m->vs[j];
    const double *p00 = mesh_point(m, i, j), *p10 = mesh_point(m, i + 1, j);
    const double *p01 = mesh_point(m, i, j + 1), *p11 = mesh_point(m, i + 1, j + 1);
    /* Two triangles: (00, 10, 11) and (00, 11, 01), with their (u, v). */
    const double *tri[2][3] = {{p00, p10, p11}, {p00, p11, p01}};
    const double uv[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
    const int edge = i == 0 || j == 0 || i == m->cells_u - 1 || j == m->cells_v - 1;
    const double margin = edge ? ORACLE_EDGE_MARGIN : ORACLE_BARY_MARGIN;
    int seeded = 0;
    for (int k = 0; k < 2; ++k) {
        double t, b1, b2;
        if (!ray_triangle(o, d, tri[k][0], tri[k][1], tri[k][2], margin, &t, &b1, &b2))
            continue;
        const double b0 = 1.0 - b1 - b2;
        const double lu = b0 * uv[k][0][0] + b1 * uv[k][1][0] + b2 * uv[k][2][0];
        const double lv = b0 * uv[k][0][1] + b1 * uv[k][1][1] + b2 * uv[k][2][1];
        seeded |= add_seed(m, o, d, ray_only, u0 + lu * du, v0 + lv * dv, t, hits, capacity, count);
    }
    if (seeded)
        return;
    /* A line nearly parallel to the surface can pass between the chords and
     * the surface, missing every triangle: a cell whose centre is within
     * ORACLE_NEAR_CELL of its diagonal from the line seeds Newton too. */
    double c[3], diag[3], w[3], x[3];
    for (int k = 0; k < 3; ++k)
        c[k] = 0.25 * (p00[k] + p10[k] + p01[k] + p11[k]);
    sub3(p11, p00, diag);
    sub3(p01, p10, w);
    const double size2 = fmax(dot3(diag, diag), dot3(w, w));
    sub3(c, o, w);
    const double lambda = dot3(w, d) / dot3(d, d);
    for (int k = 0; k < 3; ++k)
        x[k] = w[k] - lambda * d[k];
    if (dot3(x, x) <= ORACLE_NEAR_CELL * ORACLE_NEAR_CELL * size2)
        add_seed(m, o, d, ray_only, u0 + 0.5 * du, v0 + 0.5 * dv, lambda, hits, capacity, count);
}

static size_t block_hits(const pc_oracle_mesh *m, const double origin[3], const double dir[3],
                         int ray_only, int bi0, int bi1, int bj0, int bj1, pc_oracle_hit *hits,
                         size_t capacity, size_t count);

static int by_lambda(const void *a, const void *b)
{
    const double x = ((const pc_oracle_hit *)a)->lambda, y = ((const pc_oracle_hit *)b)->lambda;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* Hits each within same_lambda of the next along the line are one run:
 * one point of space (the sheets of a surface folded onto itself spread a
 * little wider than that). The first of a run is kept, with the run's
 * range of lambda. */
static size_t chain_runs(pc_oracle_hit *hits, size_t n, double same_lambda)
{
    qsort(hits, n, sizeof *hits, by_lambda);
    size_t kept = 0;
    double prev = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const pc_oracle_hit h = hits[k];
        if (kept > 0 && h.lambda - prev <= same_lambda) {
            hits[kept - 1].lambda_hi = h.lambda;
            hits[kept - 1].cos_dir = fmin(hits[kept - 1].cos_dir, h.cos_dir);
            hits[kept - 1].edge = fmin(hits[kept - 1].edge, h.edge);
        } else {
            hits[kept++] = h;
        }
        prev = h.lambda;
    }
    return kept;
}

size_t pc_oracle_line_hits(const pc_oracle_mesh *m, const double origin[3], const double dir[3],
                           int ray_only, pc_oracle_hit *hits, size_t capacity)
{
    size_t count = 0;
    const double same_lambda = pc_oracle_same_point(m, origin, dir);
    /* Groups of ORACLE_GROUP x ORACLE_GROUP blocks first, then blocks. */
    for (int gj = 0; gj < m->blocks_v; gj += ORACLE_GROUP) {
        for (int gi = 0; gi < m->blocks_u; gi += ORACLE_GROUP) {
            const int gi1 = gi + ORACLE_GROUP < m->blocks_u ? gi + ORACLE_GROUP : m->blocks_u;
            const int gj1 = gj + ORACLE_GROUP < m->blocks_v ? gj + ORACLE_GROUP : m->blocks_v;
            const double *gbox = m->group_boxes + 6 * ((size_t)(gj / ORACLE_GROUP) * (size_t)m->groups_u +
                                                      (size_t)(gi / ORACLE_GROUP));
            if (line_meets_box(gbox, origin, dir, ray_only))
                count = block_hits(m, origin, dir, ray_only, gi, gi1, gj, gj1, hits, capacity,
                                   count);
        }
    }
    return count <= capacity ? chain_runs(hits, count, same_lambda) : count;
}

static size_t block_hits(const pc_oracle_mesh *m, const double origin[3], const double dir[3],
                         int ray_only, int bi0, int bi1, int bj0, int bj1, pc_oracle_hit *hits,
                         size_t capacity, size_t count)
{
    for (int bj = bj0; bj < bj1; ++bj) {
        for (int bi = bi0; bi < bi1; ++bi) {
            const double *box = m->block_boxes + 6 * ((size_t)bj * (size_t)m->blocks_u + (size_t)bi);
            if (!line_meets_box(box, origin, dir, ray_only))
                continue;
            for (int j = bj * m->block; j < (bj + 1) * m->block && j < m->cells_v; ++j)
                for (int i = bi * m->block; i < (bi + 1) * m->block && i < m->cells_u; ++i)
                    seed_cell(m, origin, dir, ray_only, i, j, hits, capacity, &count);
        }
    }
    return count;
}

int pc_oracle_check_hit(const pc_oracle_mesh *mesh, const double origin[3], const double dir[3],
                        double u, double v, double param_tol, pc_oracle_hit *polished)
{
    double f[9];
    mesh->eval(mesh->user, u, v, 1, f);
    double w[3];
    sub3(f, origin, w);
    const double lambda = dot3(w, dir) / dot3(dir, dir);
    pc_oracle_hit h;
    if (!polish(mesh, origin, dir, u, v, lambda, &h))
        return 0;
    if (polished)
        *polished = h;
    return fabs(h.u - u) <= param_tol * (mesh->domain[1] - mesh->domain[0]) &&
           fabs(h.v - v) <= param_tol * (mesh->domain[3] - mesh->domain[2]);
}

/* Claimed and oracle hits are the same within this fraction of the domain
 * (both are Newton-polished; grazing ones are only known to ~sqrt(eps)). */
#define ORACLE_MATCH_REL 1e-8
#define ORACLE_MATCH_TANGENT_REL 1e-5
/* A hit the mesh may miss is one where the line is this close to tangent. */
#define ORACLE_GRAZING_COS 0.05
#define ORACLE_MAX_HITS 256
/* See pc_oracle_compare: 1e-6 of the model's scale, a point to the eye. */
#define ORACLE_RUN_REACH 100.0

/* A claimed hit is an oracle hit when their parameters agree, or their
 * lambda (one point of space: another copy of it, e.g. the other side of a
 * seam). */
static int matches(const pc_oracle_mesh *m, double u, double v, double lambda, unsigned flags,
                   const pc_oracle_hit *e, double same_lambda)
{
    const double rel = (flags & PROJCURVE_HIT_TANGENT) || !(e->cos_dir >= 1e-4)
                           ? ORACLE_MATCH_TANGENT_REL
                           : ORACLE_MATCH_REL;
    return (fabs(u - e->u) <= rel * (m->domain[1] - m->domain[0]) &&
            fabs(v - e->v) <= rel * (m->domain[3] - m->domain[2])) ||
           (lambda >= e->lambda_lo - same_lambda && lambda <= e->lambda_hi + same_lambda);
}

/* The cell of the samples xs[0..n] holding x (binary search). */
static int cell_of(const double *xs, int n, double x)
{
    int lo = 0, hi = n;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (xs[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Whether the parametrisation at (u, v) is stretched beyond what doubles
 * resolve (pc_oracle_resolution above 1e-12 of the model: one ulp of a
 * parameter moves S that far, as in a knot cluster whose spans 1e-8 wide
 * fold the surface into many sheets). There neither the mesh nor the
 * library can claim to see every sheet, and a sheet seen by one only is
 * counted (stats->cluster_sheets), not failed; every claimed hit is still
 * checked to lie on the line. */
static int stretched_at(const pc_oracle_mesh *m, double u, double v)
{
    double f[9];
    m->eval(m->user, u, v, 1, f);
    return pc_oracle_resolution(u, v, f) > 1e-12 * m->scale;
}

/* Flags the oracle can decide (see ray_oracle.h), checked against the
 * claimed ones. */
#define ORACLE_EDGE_ON 1e-12
#define ORACLE_EDGE_OFF 1e-7
#define ORACLE_TANGENT_ON 1e-9
#define ORACLE_TANGENT_OFF 1e-3

static void check_flags(const pc_oracle_hit *e, unsigned flags, const double *o, const double *d,
                        pc_oracle_stats *stats)
{
    const int boundary = (flags & PROJCURVE_HIT_BOUNDARY) != 0;
    const int tangent = (flags & PROJCURVE_HIT_TANGENT) != 0;
    if (e->edge <= ORACLE_EDGE_ON || e->edge >= ORACLE_EDGE_OFF) {
        ++stats->flags_checked;
        ++pc_test_checks;
        if (boundary != (e->edge <= ORACLE_EDGE_ON))
            pc_test_fail_at(__FILE__, __LINE__,
                            "hit (%.17g, %.17g, lambda %.17g) %s flagged boundary, oracle's "
                            "distance to the edge %.3g; line o = (%.17g, %.17g, %.17g) d = "
                            "(%.17g, %.17g, %.17g)",
                            e->u, e->v, e->lambda, boundary ? "is" : "is not", e->edge, o[0],
                            o[1], o[2], d[0], d[1], d[2]);
    }
    if (e->cos_dir <= ORACLE_TANGENT_ON || e->cos_dir >= ORACLE_TANGENT_OFF) {
        ++stats->flags_checked;
        ++pc_test_checks;
        if (tangent != (e->cos_dir <= ORACLE_TANGENT_ON))
            pc_test_fail_at(__FILE__, __LINE__,
                            "hit (%.17g, %.17g, lambda %.17g) %s flagged tangent, oracle's cos "
                            "%.3g; line o = (%.17g, %.17g, %.17g) d = (%.17g, %.17g, %.17g)",
                            e->u, e->v, e->lambda, tangent ? "is" : "is not", e->cos_dir, o[0],
                            o[1], o[2], d[0], d[1], d[2]);
    }
}

void pc_oracle_compare(const pc_oracle_mesh *mesh, const double origin[3], const double dir[3],
                       int ray_only, size_t n, const double *hits, const unsigned *flags,
                       pc_oracle_stats *stats)
{
    static pc_oracle_hit expected[ORACLE_MAX_HITS];
    const size_t n_exp = pc_oracle_line_hits(mesh, origin, dir, ray_only, expected, ORACLE_MAX_HITS);
    ++stats->lines;
    stats->hits += (long)n;
    stats->oracle_hits += (long)n_exp;
    ++pc_test_checks;
    if (n_exp > ORACLE_MAX_HITS) {
        pc_test_fail_at(__FILE__, __LINE__, "oracle found %zu hits, more than it keeps", n_exp);
        return;
    }
    const double *o = origin, *d = dir;
    const double same_lambda = pc_oracle_same_point(mesh, origin, dir);
    for (size_t e = 0; e < n_exp; ++e) {
        int found = 0, split = 1;
        size_t which = 0;
        for (size_t k = 0; k < n; ++k)
            if (matches(mesh, hits[3 * k], hits[3 * k + 1], hits[3 * k + 2], flags[k],
                        &expected[e], same_lambda)) {
                /* Several claimed hits in one run of sheets are distinct
                 * points when each is farther than the same-point distance
                 * from the previous (the mesh found sheets between them
                 * that chain the run; counted, not failed). */
                if (found > 0 && !(hits[3 * k + 2] - hits[3 * which + 2] > same_lambda))
                    split = 0;
                ++found;
                which = k;
            }
        if (found > 1 && split && expected[e].lambda_hi > expected[e].lambda_lo) {
            ++stats->run_split;
            continue;
        }
        if (found == 0 && stretched_at(mesh, expected[e].u, expected[e].v)) {
            ++stats->cluster_sheets;
            continue;
        }
        if (found == 0) {
            /* A run of sheets found partly by the mesh and partly by the
             * library: their runs can be cut differently. One claimed hit
             * within ORACLE_RUN_REACH times the same-point distance stands
             * for the run (counted); none, or several, fail. */
            int near = 0;
            for (size_t k = 0; k < n; ++k)
                near += fabs(hits[3 * k + 2] - expected[e].lambda) <= ORACLE_RUN_REACH * same_lambda;
            if (near == 1) {
                ++stats->in_run;
                continue;
            }
        }
        ++pc_test_checks;
        if (found == 1)
            check_flags(&expected[e], flags[which], o, d, stats);
        else if (found == 0)
            ++stats->missed;
        else
            ++stats->duplicated;
        if (found != 1)
            pc_test_fail_at(__FILE__, __LINE__,
                            "oracle hit (%.17g, %.17g, lambda %.17g, cos %.3g) found %d times; "
                            "line o = (%.17g, %.17g, %.17g) d = (%.17g, %.17g, %.17g)",
                            expected[e].u, expected[e].v, expected[e].lambda, expected[e].cos_dir,
                            found, o[0], o[1], o[2], d[0], d[1], d[2]);
    }
    for (size_t k = 0; k < n; ++k) {
        const double u = hits[3 * k], v = hits[3 * k + 1], lambda = hits[3 * k + 2];
        pc_oracle_hit p;
        ++pc_test_checks;
        if (!pc_oracle_check_hit(mesh, o, d, u, v, 1e-6, &p)) {
            pc_test_fail_at(__FILE__, __LINE__,
                            "hit (%.17g, %.17g, lambda %.17g) is not on the line o = (%.17g, "
                            "%.17g, %.17g) d = (%.17g, %.17g, %.17g)",
                            u, v, lambda, o[0], o[1], o[2], d[0], d[1], d[2]);
            continue;
        }
        const double dn = sqrt(dot3(d, d));
        {
            /* The claimed (u, v) and lambda themselves: how far S is from
             * the line's point, against the accuracy promised. */
            double f[9], w[3];
            mesh->eval(mesh->user, u, v, 1, f);
            for (int c = 0; c < 3; ++c)
                w[c] = f[c] - o[c] - lambda * d[c];
            const double r = sqrt(dot3(w, w));
            stats->max_residual = fmax(stats->max_residual, r);
            stats->max_excess =
                fmax(stats->max_excess, r / (1e-12 * mesh->scale + pc_oracle_resolution(u, v, f)));
        }
        /* lambda to the accuracy of the point along the line: 1e-9 of the
         * model for a transversal hit, ~sqrt(eps) for a grazing one. */
        double fp[9];
        mesh->eval(mesh->user, p.u, p.v, 1, fp);
        /* (plus twice the parameters' resolution: the claimed and the
         * polished points are each that far off where it matters) */
        const double tol = (((flags[k] & PROJCURVE_HIT_TANGENT) ? 1e-6 : 1e-9) * mesh->scale +
                            2.0 * pc_oracle_resolution(p.u, p.v, fp)) / dn;
        ++pc_test_checks;
        if (!(fabs(lambda - p.lambda) <= tol + 1e-12 * fabs(p.lambda)))
            pc_test_fail_at(__FILE__, __LINE__, "hit (%.17g, %.17g): lambda %.17g, oracle %.17g",
                            u, v, lambda, p.lambda);
        ++pc_test_checks;
        if (k > 0 && !(lambda >= hits[3 * (k - 1) + 2]))
            pc_test_fail_at(__FILE__, __LINE__, "hits not sorted by lambda at %zu", k);
        ++pc_test_checks;
        if (ray_only && !(lambda > 0.0))
            pc_test_fail_at(__FILE__, __LINE__, "ray hit with lambda %.17g <= 0", lambda);
        int in_oracle = 0;
        for (size_t e = 0; e < n_exp; ++e)
            in_oracle |= matches(mesh, u, v, lambda, flags[k] | PROJCURVE_HIT_TANGENT,
                                 &expected[e], same_lambda);
        /* The mesh cannot see two crossings inside one of its cells: a hit
         * with a distinct neighbour within two cells is a pair it may miss. */
        int paired = 0;
        const int ci = cell_of(mesh->us, mesh->cells_u, u), cj = cell_of(mesh->vs, mesh->cells_v, v);
        for (size_t q = 0; q < n; ++q) {
            const double du = fabs(hits[3 * q] - u), dv = fabs(hits[3 * q + 1] - v);
            const int qi = cell_of(mesh->us, mesh->cells_u, hits[3 * q]);
            const int qj = cell_of(mesh->vs, mesh->cells_v, hits[3 * q + 1]);
            paired |= q != k && abs(qi - ci) <= 2 && abs(qj - cj) <= 2 &&
                      (du > 1e-6 * (mesh->domain[1] - mesh->domain[0]) ||
                       dv > 1e-6 * (mesh->domain[3] - mesh->domain[2]));
        }
        /* A sheet among sheets that the mesh saw partly (two or more oracle
         * hits within ORACLE_RUN_REACH same-point distances: a fold of
         * several sheets close together): on the line (checked above) and
         * farther than the same-point distance from the other claimed hits
         * (the order check and the library's merging), so a distinct point;
         * counted. */
        int sheets_near = 0;
        for (size_t e = 0; e < n_exp && !in_oracle; ++e)
            sheets_near += lambda >= expected[e].lambda_lo - ORACLE_RUN_REACH * same_lambda &&
                           lambda <= expected[e].lambda_hi + ORACLE_RUN_REACH * same_lambda;
        const int beside_run = sheets_near >= 2;
        if (!in_oracle && beside_run) {
            ++stats->extra_sheets;
        } else if (!in_oracle && stretched_at(mesh, u, v)) {
            ++stats->cluster_sheets;
        } else if (!in_oracle) {
            ++stats->grazing_extra;
            ++pc_test_checks;
            if (p.cos_dir >= ORACLE_GRAZING_COS && !paired)
                pc_test_fail_at(__FILE__, __LINE__,
                                "hit (%.17g, %.17g, lambda %.17g, cos %.3g) unknown to the oracle; "
                                "line o = (%.17g, %.17g, %.17g) d = (%.17g, %.17g, %.17g)",
                                u, v, lambda, p.cos_dir, o[0], o[1], o[2], d[0], d[1], d[2]);
        }
    }
}
