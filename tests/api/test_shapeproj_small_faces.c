/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Small faces within a long curve's sweep are not skipped: linkrods.step,
 * the line of `projcurve-bench shape` "line dir" (in the plane 5 % of the
 * box diagonal beyond the box on its thinnest axis a, across the longest
 * side b, projected along -a). Oracle, independent of the tracer: the
 * curve sampled at N_T parameters, each ray P(t) - lambda e_a intersected
 * with every face's untrimmed surface, twice:
 * - a dense (u, v) grid over the face's loop box, Newton on the two
 *   equations S_b = P_b(t), S_c = P_c(t) from every cell whose 2D box
 *   holds (P_b, P_c) (the ray is axis-aligned);
 * - projcurve_surface_intersect_line (the library's ray-patch
 *   intersection, a second opinion only);
 * each hit kept when it is IN the face by the library's classifier and by
 * an even-odd test on the loops sampled here. A t whose ray meets a face
 * strictly inside (Newton and the loops agree) must lie in the t range of
 * one of that face's pieces in projcurve_project_shape's result.
 * Projected over the whole curve, faces 19 and 24 (boxes 1/57 of the
 * model) were missed: 23 of the 2,506 (t, face) hits, the faces lying
 * between two full searches of the jump sweep (shapeproj/reach_curve.h).
 * A face missed prints its branches when projected alone, at the default
 * step and at a fine one.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "brep/shape.h"
#include "check.h"

#define N_T 20000      /* t samples of the curve */
/* The slow builds (sanitizers, coverage) check every 4th sample: spaced
 * 2e-4, still 2 or more inside each small face's t range (4e-4 to 6.5e-4). */
#define T_STRIDE (PC_TEST_SLOWDOWN > 1 ? 4 : 1)
#define GRID 96        /* (u, v) grid cells per side, per face */
#define LOOP_SAMPLES 64 /* samples per loop piece for the even-odd test */
#define MAX_HITS 32
/* A Newton root is a hit when it meets the ray to 1e-10 of the model size
 * (the residual of a converged Newton step in double is ~1e-13 of it). */
#define HIT_TOL 1e-10
/* An oracle hit counts as missed only when its t lies more than T_MARGIN
 * outside every piece of its face: a piece's end is located to ~1e-10 of
 * the model on the exact projection, far below the sample spacing 5e-5. */
#define T_MARGIN 1e-4

typedef struct frame {
    double lo[3], hi[3], size;
    int a, b, c;
} frame;

static void frame_of(const projcurve_shape *s, frame *f)
{
    for (int i = 0; i < 3; ++i) {
        f->lo[i] = INFINITY;
        f->hi[i] = -INFINITY;
    }
    for (size_t k = 0; k < s->n_faces; ++k)
        for (int i = 0; i < 3; ++i) {
            f->lo[i] = fmin(f->lo[i], s->boxes[6 * k + i]);
            f->hi[i] = fmax(f->hi[i], s->boxes[6 * k + i + 3]);
        }
    double e[3], sq = 0.0;
    for (int i = 0; i < 3; ++i) {
        e[i] = f->hi[i] - f->lo[i];
        sq += e[i] * e[i];
    }
    f->size = sqrt(sq);
    f->a = 0;
    for (int i = 1; i < 3; ++i)
        if (e[i] < e[f->a])
            f->a = i;
    f->b = (f->a + 1) % 3;
    f->c = (f->a + 2) % 3;
    if (e[f->c] > e[f->b]) {
        const int t = f->b;
        f->b = f->c;
        f->c = t;
    }
}

/* As bench/cmd_shape.c frame_point with y = 0. */
static void frame_point(const frame *f, double x, double p[3])
{
    const double wb = f->hi[f->b] - f->lo[f->b], wc = f->hi[f->c] - f->lo[f->c];
    p[f->a] = f->hi[f->a] + 0.05 * f->size;
    p[f->b] = f->lo[f->b] - 0.05 * wb + 1.1 * wb * x;
    p[f->c] = 0.5 * (f->lo[f->c] + f->hi[f->c]) + 0.0123 * wc;
}

/* The loops of a face sampled into one polygon list (loop k from start[k]). */
typedef struct loops {
    double *uv;
    size_t n, start[64], n_loops;
} loops;

static void sample_loops(const projcurve_face *face, loops *L)
{
    size_t total = 0, cap = 0;
    L->uv = NULL;
    L->n_loops = projcurve_face_loop_count(face);
    CHECK(L->n_loops < 64);
    for (size_t k = 0; k < L->n_loops && k < 64; ++k) {
        L->start[k] = total;
        size_t np = 0;
        CHECK_OK(projcurve_face_loop_piece_count(NULL, face, k, &np));
        for (size_t j = 0; j < np; ++j) {
            int deg = 0, sense = 1;
            size_t nc = 0;
            const double *ctrl = NULL, *w = NULL, *kn = NULL;
            CHECK_OK(projcurve_face_piece_curve(NULL, face, k, j, &deg, &nc, &ctrl, &w, &kn,
                                                &sense));
            projcurve_curve *c = NULL;
            double c3[3 * 4096];
            CHECK(nc <= 4096);
            for (size_t i = 0; i < nc && i < 4096; ++i) {
                c3[3 * i] = ctrl[2 * i];
                c3[3 * i + 1] = ctrl[2 * i + 1];
                c3[3 * i + 2] = 0.0;
            }
            CHECK_OK(projcurve_curve_create_nurbs(NULL, deg, nc, c3, w, kn, &c));
            double t0 = 0, t1 = 1;
            CHECK_OK(projcurve_curve_domain(NULL, c, &t0, &t1));
            for (int i = 0; i < LOOP_SAMPLES; ++i) {
                const double s = (double)i / LOOP_SAMPLES;
                const double t = sense > 0 ? t0 + (t1 - t0) * s : t1 - (t1 - t0) * s;
                double p[3];
                CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
                if (total == cap) {
                    cap = cap ? 2 * cap : 1024;
                    L->uv = realloc(L->uv, 2 * cap * sizeof *L->uv);
                    CHECK(L->uv != NULL);
                }
                L->uv[2 * total] = p[0];
                L->uv[2 * total + 1] = p[1];
                ++total;
            }
            projcurve_curve_destroy(c);
        }
    }
    L->n = total;
}

static int even_odd_in(const loops *L, double u, double v)
{
    int in = 0;
    for (size_t k = 0; k < L->n_loops; ++k) {
        const size_t s = L->start[k], e = k + 1 < L->n_loops ? L->start[k + 1] : L->n;
        for (size_t i = s; i < e; ++i) {
            const size_t j = i + 1 < e ? i + 1 : s;
            const double u1 = L->uv[2 * i], v1 = L->uv[2 * i + 1];
            const double u2 = L->uv[2 * j], v2 = L->uv[2 * j + 1];
            if ((v1 > v) != (v2 > v) && u < u1 + (v - v1) * (u2 - u1) / (v2 - v1))
                in = !in;
        }
    }
    return in;
}

/* The (u, v) grid of a face: S at the nodes. */
typedef struct grid {
    double uv[4];
    double *p; /* (GRID + 1)^2 points */
} grid;

static void grid_of(const projcurve_face *face, grid *g)
{
    double dom[4];
    CHECK_OK(projcurve_face_bounds(NULL, face, g->uv, NULL));
    CHECK_OK(projcurve_surface_domain(NULL, projcurve_face_surface(face), dom));
    /* the loops' box may pass the domain by their tolerance */
    g->uv[0] = fmax(g->uv[0], dom[0]);
    g->uv[1] = fmin(g->uv[1], dom[1]);
    g->uv[2] = fmax(g->uv[2], dom[2]);
    g->uv[3] = fmin(g->uv[3], dom[3]);
    g->p = malloc(3 * (GRID + 1) * (GRID + 1) * sizeof *g->p);
    CHECK(g->p != NULL);
    const projcurve_surface *s = projcurve_face_surface(face);
    for (int i = 0; i <= GRID; ++i)
        for (int j = 0; j <= GRID; ++j) {
            const double u = g->uv[0] + (g->uv[1] - g->uv[0]) * i / GRID;
            const double v = g->uv[2] + (g->uv[3] - g->uv[2]) * j / GRID;
            CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 0, g->p + 3 * (i * (GRID + 1) + j)));
        }
}

/* Newton on S_b = P_b, S_c = P_c from (u, v), kept in the grid's box. */
static int newton(const projcurve_surface *s, const frame *f, const grid *g, const double P[3],
                  double *u, double *v)
{
    for (int it = 0; it < 30; ++it) {
        double d[9];
        if (projcurve_surface_eval(NULL, s, *u, *v, 1, d) != PROJCURVE_OK)
            return 0;
        const double rb = d[f->b] - P[f->b], rc = d[f->c] - P[f->c];
        if (fabs(rb) + fabs(rc) < HIT_TOL * f->size)
            return 1;
        const double a11 = d[3 + f->b], a12 = d[6 + f->b], a21 = d[3 + f->c], a22 = d[6 + f->c];
        const double det = a11 * a22 - a12 * a21;
        if (det == 0.0)
            return 0;
        *u = fmin(fmax(*u - (a22 * rb - a12 * rc) / det, g->uv[0]), g->uv[1]);
        *v = fmin(fmax(*v - (a11 * rc - a21 * rb) / det, g->uv[2]), g->uv[3]);
    }
    return 0;
}

/* Does the ray from P along -e_a meet the face inside (grid + Newton,
 * classifier and even-odd agreeing)? */
static int grid_hit(const projcurve_face *face, const frame *f, const grid *g, const loops *L,
                    const double P[3])
{
    const projcurve_surface *s = projcurve_face_surface(face);
    const double pad = 1e-9 * f->size;
    for (int i = 0; i < GRID; ++i)
        for (int j = 0; j < GRID; ++j) {
            double lb = INFINITY, hb = -INFINITY, lc = INFINITY, hc = -INFINITY;
            for (int k = 0; k < 4; ++k) {
                const double *q = g->p + 3 * ((i + k / 2) * (GRID + 1) + j + k % 2);
                lb = fmin(lb, q[f->b]);
                hb = fmax(hb, q[f->b]);
                lc = fmin(lc, q[f->c]);
                hc = fmax(hc, q[f->c]);
            }
            /* a cell's image is within 1/4 of its box width of its corners'
             * box (smooth surface, fine grid): widen by that */
            const double wb = 0.25 * (hb - lb) + pad, wc = 0.25 * (hc - lc) + pad;
            if (P[f->b] < lb - wb || P[f->b] > hb + wb || P[f->c] < lc - wc || P[f->c] > hc + wc)
                continue;
            double u = g->uv[0] + (g->uv[1] - g->uv[0]) * (i + 0.5) / GRID;
            double v = g->uv[2] + (g->uv[3] - g->uv[2]) * (j + 0.5) / GRID;
            if (!newton(s, f, g, P, &u, &v))
                continue;
            double q[3];
            CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 0, q));
            if (q[f->a] >= P[f->a])
                continue; /* behind the curve */
            projcurve_where w = PROJCURVE_OUT;
            CHECK_OK(projcurve_face_classify(NULL, face, u, v, &w));
            if (w == PROJCURVE_IN && even_odd_in(L, u, v))
                return 1;
        }
    return 0;
}

/* The library's ray intersection, classified the same way. */
static int lib_hit(const projcurve_face *face, const frame *f, const loops *L, const double P[3])
{
    double dir[3] = {0, 0, 0}, hits[3 * MAX_HITS];
    dir[f->a] = -1.0;
    size_t n = 0;
    CHECK_OK(projcurve_surface_intersect_line(NULL, projcurve_face_surface(face), P, dir, 1,
                                              MAX_HITS, hits, NULL, &n));
    for (size_t k = 0; k < n && k < MAX_HITS; ++k) {
        projcurve_where w = PROJCURVE_OUT;
        CHECK_OK(projcurve_face_classify(NULL, face, hits[3 * k], hits[3 * k + 1], &w));
        if (w == PROJCURVE_IN && even_odd_in(L, hits[3 * k], hits[3 * k + 1]))
            return 1;
    }
    return 0;
}

/* Is t within T_MARGIN of a piece of shape face fi? */
static int covered(const projcurve_shape_result *r, size_t fi, double t)
{
    const size_t nc = projcurve_shape_result_curve_count(r);
    for (size_t c = 0; c < nc; ++c) {
        size_t np = 0;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, r, c, &np, NULL, NULL));
        for (size_t k = 0; k < np; ++k) {
            size_t face = 0;
            double tr[2];
            CHECK_OK(projcurve_shape_result_piece(NULL, r, c, k, &face, NULL, NULL, tr, NULL,
                                                  NULL));
            if (face == fi && t >= fmin(tr[0], tr[1]) - T_MARGIN &&
                t <= fmax(tr[0], tr[1]) + T_MARGIN)
                return 1;
        }
    }
    return 0;
}

/* Branches of face fi projected alone over the whole curve, at an
 * arc-length step fraction (0: the default), and the CPU seconds taken. */
static size_t face_alone(const projcurve_face *face, const projcurve_curve *curve,
                         const double dir[3], double fraction, double *seconds)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    if (fraction > 0.0)
        CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_ARC_STEP_FRACTION, fraction));
    projcurve_shape_result *r = NULL;
    const clock_t c0 = clock();
    CHECK_OK(projcurve_project_face(NULL, face, curve, PROJCURVE_PROJECT_DIRECTIONAL, dir, o, &r));
    *seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    const projcurve_result *fr = NULL;
    if (r != NULL && projcurve_shape_result_face_count(r) > 0)
        CHECK_OK(projcurve_shape_result_face(NULL, r, 0, NULL, &fr, NULL, NULL));
    const size_t n = fr != NULL ? projcurve_result_branch_count(fr) : 0;
    projcurve_shape_result_destroy(r);
    projcurve_options_destroy(o);
    return n;
}

typedef struct tally {
    size_t grid_hits, lib_hits, missed, faces_missed;
} tally;

static void check_face(const projcurve_shape *shape, size_t fi, const frame *f,
                       const projcurve_curve *curve, const projcurve_shape_result *r, tally *T)
{
    const projcurve_face *face = projcurve_shape_face(shape, fi);
    const double *bx = shape->boxes + 6 * fi;
    double box_diag = 0.0;
    for (int i = 0; i < 3; ++i)
        box_diag += (bx[i + 3] - bx[i]) * (bx[i + 3] - bx[i]);
    box_diag = sqrt(box_diag);
    grid g;
    loops L;
    grid_of(face, &g);
    sample_loops(face, &L);
    size_t gh = 0, lh = 0, miss = 0;
    double t_first = NAN, t_last = NAN;
    for (int k = 0; k <= N_T; k += T_STRIDE) {
        const double t = (double)k / N_T;
        double P[3];
        CHECK_OK(projcurve_curve_eval(NULL, curve, t, 0, P));
        if (P[f->b] < bx[f->b] || P[f->b] > bx[f->b + 3] || P[f->c] < bx[f->c] ||
            P[f->c] > bx[f->c + 3])
            continue;
        const int gi = grid_hit(face, f, &g, &L, P), li = lib_hit(face, f, &L, P);
        gh += (size_t)gi;
        lh += (size_t)li;
        if (gi && !covered(r, fi, t)) {
            if (miss == 0)
                t_first = t;
            t_last = t;
            ++miss;
        }
    }
    if (gh || lh || miss)
        printf("face %zu (box diagonal %.3g of the model): %zu t with a hit (grid + Newton), "
               "%zu (intersect_line), %zu not covered by a piece [%.5f, %.5f]\n",
               fi, box_diag / f->size, gh, lh, miss, t_first, t_last);
    if (miss > 0) {
        double d[3] = {0, 0, 0}, s0 = 0, s1 = 0;
        d[f->a] = -1.0;
        const size_t n0 = face_alone(face, curve, d, 0.0, &s0);
        const size_t n1 = face_alone(face, curve, d, 1.0 / 4096, &s1);
        printf("  face %zu alone: %zu branches (%.3f s) at the default step, %zu (%.3f s) at "
               "ARC_STEP_FRACTION 1/4096\n",
               fi, n0, s0, n1, s1);
    }
    T->grid_hits += gh;
    T->lib_hits += lh;
    T->missed += miss;
    T->faces_missed += miss > 0;
    free(g.p);
    free(L.uv);
}

int main(void)
{
    pc_test_hang_guard(600 * PC_TEST_SLOWDOWN);
    projcurve_model *model = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &model));
    if (model == NULL)
        return pc_test_finish("test_shapeproj_small_faces");
    const projcurve_shape *shape = projcurve_model_shape(model, 0);
    CHECK(shape != NULL);
    frame f;
    frame_of(shape, &f);
    double ctrl[6];
    const double knots[] = {0, 0, 1, 1};
    frame_point(&f, 0.0, ctrl);
    frame_point(&f, 1.0, ctrl + 3);
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &curve));
    double dir[3] = {0, 0, 0};
    dir[f.a] = -1.0;
    projcurve_shape_result *r = NULL;
    const clock_t c0 = clock();
    CHECK_OK(projcurve_project_shape(NULL, shape, curve, PROJCURVE_PROJECT_DIRECTIONAL, dir,
                                     NULL, &r));
    printf("shape projection: %.3f s CPU, %zu connected curves\n",
           (double)(clock() - c0) / CLOCKS_PER_SEC, projcurve_shape_result_curve_count(r));
    tally T = {0, 0, 0, 0};
    for (size_t fi = 0; fi < projcurve_shape_face_count(shape); ++fi)
        check_face(shape, fi, &f, curve, r, &T);
    printf("%zu t-face hits (grid + Newton), %zu (intersect_line); %zu missed by the shape "
           "projection on %zu faces\n",
           T.grid_hits, T.lib_hits, T.missed, T.faces_missed);
    CHECK(T.grid_hits > 0); /* not vacuous */
    CHECK(T.missed == 0);
    projcurve_shape_result_destroy(r);
    projcurve_curve_destroy(curve);
    projcurve_model_destroy(model);
    return pc_test_finish("test_shapeproj_small_faces");
}
