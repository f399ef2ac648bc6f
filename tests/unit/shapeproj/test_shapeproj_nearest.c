/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The nearest hits across the faces of a shape (shapeproj/shape_hits.h),
 * against closed forms and brute force:
 *   - two walls as two faces, a front one (x = 1, |y| <= 1/2) and a back
 *     one (x = 3, |y| <= 1), the line (-1, -0.8 + 1.6 t, 0.1 + 0.2 t) along
 *     +x: all hits give the front piece and the whole back one; nearest
 *     keeps the front piece and the back one where the front is missing,
 *     cut exactly where the ray leaves the front wall's edge
 *     (y(t) = -+1/2: t = 0.1875, 0.8125), END_OCCLUDED / START_VISIBLE
 *     there; from the eye (-5, 0, 0.2) the same with the cuts where the
 *     ray through P(t) meets the front's edge (mu = 3/2: y(t) = -+1/3);
 *     with the front as wide as the back, nearest keeps the front only (one
 *     connected curve); MAX_DISTANCE 3 keeps the front alone too; an eye
 *     on the curve is SINGULAR for the whole shape;
 *   - one face on a U-shaped surface trimmed to its back wall: the
 *     untrimmed front wall is no hit and does not occlude (nearest keeps
 *     the back wall's piece whole);
 *   - a unit cube of six planar faces seen along a diagonal, directional
 *     and conical: every kept point is the first hit of its ray against
 *     the cube (the slab test: the oracle), no two kept pieces overlap in
 *     t, and every sampled t whose ray meets the cube is covered.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "brep/face.h"
#include "brep/shape.h"
#include "check.h"
#include "projcurve.h"

/* The plane O + u A + v B over [0, 1]^2 (bilinear: exact). */
static projcurve_surface *plane(const double o[3], const double a[3], const double b[3])
{
    double net[12];
    for (int i = 0; i < 3; ++i) {
        net[i] = o[i];
        net[3 + i] = o[i] + a[i];
        net[6 + i] = o[i] + b[i];
        net[9 + i] = o[i] + a[i] + b[i];
    }
    static const double knots[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

/* The face of s over [u0, u1] x [v0, v1], its sides' edge ids first_id.. */
static projcurve_face *rect_face(const projcurve_surface *s, double u0, double u1, double v0,
                                 double v1, long first_id)
{
    const double c[5][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0}};
    double ctrl[4][4];
    static const double knots[] = {0, 0, 1, 1};
    pc_piece_input pieces[4];
    for (int k = 0; k < 4; ++k) {
        ctrl[k][0] = c[k][0];
        ctrl[k][1] = c[k][1];
        ctrl[k][2] = c[k + 1][0];
        ctrl[k][3] = c[k + 1][1];
        pieces[k] = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl[k], .knots = knots,
                                     .edge = first_id + k, .sense = 1, .edge_sense = 1};
    }
    const pc_loop_input loop = {.pieces = pieces, .n_pieces = 4, .outer = 1};
    const pc_face_params params = {.tol_uv = 1e-9, .tol_model = 0.0, .close_tol = 1e-9,
                                   .same_sense = 1, .id = -1, .kind = "plane", .what = "rect"};
    projcurve_face *f = NULL;
    CHECK_OK(pc_face_build(NULL, s, &loop, 1, &params, &f));
    return f;
}

static projcurve_shape *shape_of(projcurve_face *const *faces, size_t n)
{
    size_t index[8];
    for (size_t i = 0; i < n; ++i)
        index[i] = i;
    projcurve_shape *sh = NULL;
    CHECK_OK(pc_shape_build(NULL, PROJCURVE_SHAPE_OPEN_SHELL, -1,
                            (const projcurve_face *const *)faces, index, n, &sh));
    return sh;
}

static projcurve_curve *line(const double a[3], const double b[3])
{
    const double ctrl[6] = {a[0], a[1], a[2], b[0], b[1], b[2]};
    static const double knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

static projcurve_options *options(int nearest, double max_distance)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS,
                                       nearest ? PROJCURVE_HITS_NEAREST : PROJCURVE_HITS_ALL));
    if (max_distance > 0.0)
        CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE,
                                              max_distance));
    return o;
}

/* The 3D point of every traced point of a piece, with its t. */
typedef struct piece_view {
    size_t face;
    double t0, t1;
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n;
    double *t, *xyz;
} piece_view;

static size_t read_pieces(const projcurve_shape *shape, const projcurve_shape_result *sr,
                          piece_view *out, size_t max)
{
    size_t n = 0;
    for (size_t c = 0; c < projcurve_shape_result_curve_count(sr); ++c) {
        size_t np = 0;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, c, &np, NULL, NULL));
        for (size_t k = 0; k < np && n < max; ++k, ++n) {
            piece_view *v = &out[n];
            const projcurve_result *r = NULL;
            size_t b = 0;
            double tr[2];
            CHECK_OK(projcurve_shape_result_piece(NULL, sr, c, k, &v->face, &r, &b, tr,
                                                  &v->start, &v->end));
            v->t0 = tr[0];
            v->t1 = tr[1];
            static double pts[3 * 8192];
            CHECK_OK(projcurve_result_branch_points(NULL, r, b, 8192, pts, &v->n));
            v->t = malloc(v->n * sizeof *v->t);
            v->xyz = malloc(3 * v->n * sizeof *v->xyz);
            const projcurve_surface *s =
                projcurve_face_surface(projcurve_shape_face(shape, v->face));
            for (size_t i = 0; i < v->n; ++i) {
                v->t[i] = pts[3 * i];
                CHECK_OK(projcurve_surface_eval(NULL, s, pts[3 * i + 1], pts[3 * i + 2], 0,
                                                v->xyz + 3 * i));
            }
        }
    }
    return n;
}

static void free_pieces(piece_view *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        free(v[i].t);
        free(v[i].xyz);
    }
}

/* Piece views sorted by t0 (few: insertion sort). */
static void sort_pieces(piece_view *v, size_t n)
{
    for (size_t i = 1; i < n; ++i)
        for (size_t j = i; j > 0 && v[j].t0 < v[j - 1].t0; --j) {
            const piece_view tmp = v[j];
            v[j] = v[j - 1];
            v[j - 1] = tmp;
        }
}

/* The cuts are located to 1e-10 of the model size (~5) in the distance
 * difference, and the trims to 1e-10 of it in 3D; the curve moves 1.6
 * per unit t and the distances change at most ~1.6 per unit t: 2e-9
 * bounds both in t. */
#define CUT_TOL 2e-9

static void check_walls(int conical)
{
    const double of[3] = {1, -0.5, -1}, ob[3] = {3, -1, -1}, ow[3] = {1, -1, -1};
    const double y1[3] = {0, 1, 0}, y2[3] = {0, 2, 0}, z2[3] = {0, 0, 2};
    projcurve_surface *sf = plane(of, y1, z2), *sb = plane(ob, y2, z2), *sw = plane(ow, y2, z2);
    projcurve_face *faces[2] = {rect_face(sf, 0, 1, 0, 1, 1), rect_face(sb, 0, 1, 0, 1, 5)};
    projcurve_face *wide[2] = {rect_face(sw, 0, 1, 0, 1, 1), faces[1]};
    projcurve_shape *shape = shape_of(faces, 2), *wshape = shape_of(wide, 2);
    const double a[3] = {-1, -0.8, 0.1}, b[3] = {-1, 0.8, 0.3};
    projcurve_curve *c = line(a, b);
    const double dir[3] = {1, 0, 0}, eye[3] = {-5, 0, 0.2};
    const projcurve_projection_kind kind =
        conical ? PROJCURVE_PROJECT_CONICAL : PROJCURVE_PROJECT_DIRECTIONAL;
    const double *vec = conical ? eye : dir;
    /* where the ray of P(t) meets the front's edges y = -+1/2 */
    const double ye = conical ? 1.0 / 3.0 : 0.5;
    const double ta = (0.8 - ye) / 1.6, tb = (0.8 + ye) / 1.6;
    /* the back wall's own ends (conical: mu = 2, 2 y(t) = -+1) */
    const double b0 = conical ? 0.1875 : 0.0, b1 = conical ? 0.8125 : 1.0;

    projcurve_options *all = options(0, 0.0), *near = options(1, 0.0);
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c, kind, vec, all, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 2);
    projcurve_shape_result_destroy(sr);

    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c, kind, vec, near, &sr));
    piece_view v[8];
    size_t n = read_pieces(shape, sr, v, 8);
    CHECK(n == 3);
    if (n == 3) {
        sort_pieces(v, n);
        const size_t face[3] = {1, 0, 1};
        const double t0[3] = {b0, ta, tb}, t1[3] = {ta, tb, b1};
        for (size_t k = 0; k < 3; ++k) {
            CHECK(v[k].face == face[k]);
            CHECK_NEAR(v[k].t0, t0[k], CUT_TOL);
            CHECK_NEAR(v[k].t1, t1[k], CUT_TOL);
            for (size_t i = 0; i < v[k].n; ++i) {
                CHECK_NEAR(v[k].xyz[3 * i], face[k] == 0 ? 1.0 : 3.0, 1e-12);
                CHECK(v[k].t[i] >= v[k].t0 && v[k].t[i] <= v[k].t1);
            }
        }
        CHECK(v[0].end == PROJCURVE_END_OCCLUDED);
        CHECK(v[1].start == PROJCURVE_START_TRIM && v[1].end == PROJCURVE_END_TRIM);
        CHECK(v[2].start == PROJCURVE_START_VISIBLE);
    }
    free_pieces(v, n);
    projcurve_shape_result_destroy(sr);

    /* a front as wide as the back: only the front, one connected curve */
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, wshape, c, kind, vec, near, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    n = read_pieces(wshape, sr, v, 8);
    CHECK(n == 1 && v[0].face == 0);
    free_pieces(v, n);
    projcurve_shape_result_destroy(sr);

    /* MAX_DISTANCE between the walls (front 2, back 4 from the curve;
     * conical about 2.0 and 4.0 along the ray): the front alone, already
     * per face */
    projcurve_options *close = options(0, 3.0);
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, wshape, c, kind, vec, close, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    n = read_pieces(wshape, sr, v, 8);
    CHECK(n == 1 && v[0].face == 0);
    free_pieces(v, n);
    projcurve_shape_result_destroy(sr);

    if (conical) {
        /* an eye on the curve (P(1/2)): refused once for the shape */
        const double on[3] = {-1, 0, 0.2};
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        sr = NULL;
        CHECK_STATUS(projcurve_project_shape(ctx, shape, c, kind, on, near, &sr),
                     PROJCURVE_ERR_SINGULAR);
        CHECK(sr == NULL);
        CHECK(projcurve_context_message(ctx)[0] != '\0');
        projcurve_context_destroy(ctx);
    }
    projcurve_options_destroy(close);
    projcurve_options_destroy(all);
    projcurve_options_destroy(near);
    projcurve_curve_destroy(c);
    pc_shape_free(shape);
    pc_shape_free(wshape);
    pc_face_free(faces[0]);
    pc_face_free(faces[1]);
    pc_face_free(wide[0]);
    projcurve_surface_destroy(sf);
    projcurve_surface_destroy(sb);
    projcurve_surface_destroy(sw);
}

/* A degree-1 U in (x, y) extruded along z: u in [0, 1] the wall x = 1,
 * [1, 2] the bottom y = 1.5, [2, 3] the wall x = 3; the face keeps
 * u in [1.5, 3]: the back wall only. */
static void check_trimmed_not_occluding(void)
{
    const double xy[4][2] = {{1, -1}, {1, 1.5}, {3, 1.5}, {3, -1}};
    double net[3 * 8];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) {
            net[3 * (4 * j + i)] = xy[i][0];
            net[3 * (4 * j + i) + 1] = xy[i][1];
            net[3 * (4 * j + i) + 2] = j ? 1.0 : -1.0;
        }
    static const double ku[] = {0, 0, 1, 2, 3, 3}, kv[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 4, 2, net, NULL, ku, kv, &s));
    projcurve_face *f = rect_face(s, 1.5, 3, 0, 1, 1);
    const double a[3] = {-1, -0.8, 0.1}, b[3] = {-1, 0.8, 0.3}, dir[3] = {1, 0, 0};
    projcurve_curve *c = line(a, b);
    projcurve_options *near = options(1, 0.0);
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_face(NULL, f, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, near, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    double tr[2] = {-1, -1};
    if (projcurve_shape_result_curve_count(sr) == 1)
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, NULL, tr, NULL));
    CHECK_NEAR(tr[0], 0.0, 1e-14);
    CHECK_NEAR(tr[1], 1.0, 1e-14);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(near);
    projcurve_curve_destroy(c);
    pc_face_free(f);
    projcurve_surface_destroy(s);
}

/* The entry distance of the ray p + lambda d (|d| = 1) into the unit cube
 * (slab test); INFINITY when it misses. */
static double cube_entry(const double p[3], const double d[3])
{
    double lo = 0.0, hi = INFINITY;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (p[i] < 0.0 || p[i] > 1.0)
                return INFINITY;
            continue;
        }
        double a = (0.0 - p[i]) / d[i], b = (1.0 - p[i]) / d[i];
        if (a > b) {
            const double tmp = a;
            a = b;
            b = tmp;
        }
        lo = fmax(lo, a);
        hi = fmin(hi, b);
    }
    /* a ray through an edge or corner meets it: lo = hi to rounding, and
     * grazing the silhouette a point 1e-12 off the edge moves lo past hi
     * by that over the sine of the grazing angle */
    return lo <= hi + 1e-9 ? lo : INFINITY;
}

static void ray_of(int conical, const double eye[3], const double dir[3], const double p[3],
                   double d[3])
{
    for (int i = 0; i < 3; ++i)
        d[i] = conical ? p[i] - eye[i] : dir[i];
    const double m = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; ++i)
        d[i] /= m;
}

static void check_cube(int conical)
{
    /* faces x = 0, x = 1, y = 0, y = 1, z = 0, z = 1 */
    const double o0[3] = {0, 0, 0}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    const double ox[3] = {1, 0, 0}, oy[3] = {0, 1, 0}, oz[3] = {0, 0, 1};
    projcurve_surface *s[6] = {plane(o0, ey, ez), plane(ox, ey, ez), plane(o0, ex, ez),
                               plane(oy, ex, ez), plane(o0, ex, ey), plane(oz, ex, ey)};
    projcurve_face *f[6];
    for (int i = 0; i < 6; ++i)
        f[i] = rect_face(s[i], 0, 1, 0, 1, 10 * i + 1);
    projcurve_shape *shape = shape_of(f, 6);
    const double dn = sqrt(1.0 + 0.81 + 0.49);
    const double dir[3] = {1 / dn, 0.9 / dn, 0.7 / dn};
    /* a bent curve 3 behind the centre, across the cube's silhouette: the
     * perpendicular w = (0.9, -1, 0) / |.|, and a bend along d x w */
    const double wn = sqrt(0.81 + 1.0);
    const double w[3] = {0.9 / wn, -1.0 / wn, 0.0};
    const double bend[3] = {dir[1] * w[2] - dir[2] * w[1], dir[2] * w[0] - dir[0] * w[2],
                            dir[0] * w[1] - dir[1] * w[0]};
    double ctrl[9];
    for (int i = 0; i < 3; ++i) {
        const double c0 = 0.5 - 3.0 * dir[i];
        ctrl[i] = c0 - 1.2 * w[i] - 0.2 * bend[i];
        ctrl[3 + i] = c0 + 0.6 * bend[i];
        ctrl[6 + i] = c0 + 1.2 * w[i] - 0.2 * bend[i];
    }
    static const double knots[] = {0, 0, 0, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 3, ctrl, NULL, knots, &c));
    double eye[3];
    for (int i = 0; i < 3; ++i)
        eye[i] = 0.5 - 9.0 * dir[i];
    projcurve_options *near = options(1, 0.0);
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c,
                                     conical ? PROJCURVE_PROJECT_CONICAL
                                             : PROJCURVE_PROJECT_DIRECTIONAL,
                                     conical ? eye : dir, near, &sr));
    piece_view v[32];
    const size_t n = read_pieces(shape, sr, v, 32);
    CHECK(n >= 3);
    size_t faces_seen = 0;
    for (size_t k = 0; k < n; ++k) {
        /* the three front faces only: x = 0, y = 0, z = 0 */
        CHECK(v[k].face % 2 == 0);
        /* convex: the back faces are hidden whole, no piece is cut by
         * another (the ends are trims on the silhouette or curve ends) */
        CHECK(v[k].start != PROJCURVE_START_VISIBLE && v[k].end != PROJCURVE_END_OCCLUDED);
        faces_seen |= (size_t)1 << v[k].face;
        for (size_t i = 0; i < v[k].n; ++i) {
            double p[3], d[3];
            CHECK_OK(projcurve_curve_eval(NULL, c, v[k].t[i], 0, p));
            ray_of(conical, eye, dir, p, d);
            const double *x = v[k].xyz + 3 * i;
            const double sp[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
            const double lambda = sp[0] * d[0] + sp[1] * d[1] + sp[2] * d[2];
            /* the first hit of the ray: traced and cut points are exact
             * projections (Newton to ~1e-12 of the size, ~6) */
            CHECK_NEAR(lambda, cube_entry(p, d), 1e-9);
            if (!(fabs(lambda - cube_entry(p, d)) <= 1e-9))
                fprintf(stderr, "  %s face %zu piece t [%.17g, %.17g] point %zu/%zu t %.17g at "
                                "(%.17g, %.17g, %.17g) start %d end %d\n",
                        conical ? "conical" : "directional", v[k].face, v[k].t0, v[k].t1, i,
                        v[k].n, v[k].t[i], x[0], x[1], x[2], (int)v[k].start, (int)v[k].end);
            const double off[3] = {sp[0] - lambda * d[0], sp[1] - lambda * d[1],
                                   sp[2] - lambda * d[2]};
            CHECK_NEAR(sqrt(off[0] * off[0] + off[1] * off[1] + off[2] * off[2]), 0.0, 1e-9);
        }
    }
    CHECK(faces_seen == ((1u << 0) | (1u << 2) | (1u << 4)));
    /* one piece per t (the cube is convex: one first hit), and every ray
     * that meets the cube is covered */
    sort_pieces(v, n);
    for (size_t k = 0; k + 1 < n; ++k)
        CHECK(v[k].t1 <= v[k + 1].t0 + CUT_TOL);
    size_t uncovered = 0;
    for (int i = 0; i <= 1000; ++i) {
        const double t = i / 1000.0;
        double p[3], d[3];
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
        ray_of(conical, eye, dir, p, d);
        if (!isfinite(cube_entry(p, d)))
            continue;
        int covered = 0;
        for (size_t k = 0; k < n && !covered; ++k)
            covered = t >= v[k].t0 - CUT_TOL && t <= v[k].t1 + CUT_TOL;
        uncovered += !covered;
    }
    CHECK(uncovered == 0);
    if (uncovered)
        fprintf(stderr, "cube (%s): %zu sampled rays meet the cube with no piece\n",
                conical ? "conical" : "directional", uncovered);
    free_pieces(v, n);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(near);
    projcurve_curve_destroy(c);
    pc_shape_free(shape);
    for (int i = 0; i < 6; ++i) {
        pc_face_free(f[i]);
        projcurve_surface_destroy(s[i]);
    }
}

int main(void)
{
    check_walls(0);
    check_walls(1);
    check_trimmed_not_occluding();
    check_cube(0);
    check_cube(1);
    return pc_test_finish("test_shapeproj_nearest");
}
