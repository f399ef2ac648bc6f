/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Sewing by geometry (brep/sew.h) on two unit squares side by side in the
 * plane z = 0, face A at x in [0, 1] and face B at x in [1 + gap, 2 + gap],
 * whose common side the answer is known for:
 *   - B's side split in two pieces (at y = 0.4) against A's one: the three
 *     pieces are one edge (three uses), each with its sense along it;
 *   - B's side one piece parametrised unevenly (its middle by parameter is
 *     at y = 0.6, A's at 0.5): one edge;
 *   - a gap of 50 tolerances: sewn, the gap reported as the tolerance used;
 *   - a gap of 200 tolerances (beyond PC_SEW_GAP_FACTOR): not sewn.
 */
#include <math.h>

#include "brep/sew.h"
#include "brep/shape.h"
#include "check.h"

#define TOL 1e-6

static projcurve_surface *square_at(double x0)
{
    const double net[] = {x0, 0, 0, x0 + 1, 0, 0, x0, 1, 0, x0 + 1, 1, 0}, knots[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

/* A loop of pieces through uv[0..n] (closed: uv[n] == uv[0]); piece k is a
 * line, or with bend[k] != 0 a quadratic whose middle control point slides
 * along the chord (an uneven parametrisation of the same segment). */
typedef struct loop_def {
    double uv[8][2];
    double bend[8];
    size_t n;
    long first_id;
} loop_def;

static projcurve_face *make_face(const projcurve_surface *s, const loop_def *d)
{
    static const double lin_knots[] = {0, 0, 1, 1}, quad_knots[] = {0, 0, 0, 1, 1, 1};
    double ctrl[8][6];
    pc_piece_input pieces[8];
    for (size_t k = 0; k < d->n; ++k) {
        const double *a = d->uv[k], *b = d->uv[k + 1];
        const double m = 0.5 + d->bend[k];
        const double quad[6] = {a[0], a[1], a[0] + m * (b[0] - a[0]), a[1] + m * (b[1] - a[1]),
                                b[0], b[1]};
        for (int i = 0; i < 6; ++i)
            ctrl[k][i] = d->bend[k] != 0.0 ? quad[i] : (i < 4 ? (i < 2 ? a[i] : b[i - 2]) : 0.0);
        pieces[k] = (pc_piece_input){.degree = d->bend[k] != 0.0 ? 2 : 1,
                                     .n_ctrl = d->bend[k] != 0.0 ? 3 : 2,
                                     .ctrl = ctrl[k],
                                     .knots = d->bend[k] != 0.0 ? quad_knots : lin_knots,
                                     .edge = d->first_id + (long)k,
                                     .sense = 1,
                                     .edge_sense = 1};
    }
    const pc_loop_input loop = {.pieces = pieces, .n_pieces = d->n, .outer = 1};
    const pc_face_params fp = {.tol_uv = 1e-9, .tol_model = TOL, .close_tol = 1e-9,
                               .same_sense = 1, .id = -1, .kind = "bspline", .what = "face"};
    projcurve_face *f = NULL;
    CHECK_OK(pc_face_build(NULL, s, &loop, 1, &fp, &f));
    return f;
}

/* The 3D direction of y along piece k of f's outer loop, times its edge
 * sense: +1 or -1, the same for every use of one edge. */
static int along_edge(const projcurve_face *f, size_t k)
{
    const pc_face_piece *p = &f->loops[0].pieces[k];
    double t0, t1, a[2], b[2];
    pc_curve2_domain(&p->curve, &t0, &t1);
    pc_curve2_eval(&p->curve, t0, a);
    pc_curve2_eval(&p->curve, t1, b);
    return (b[1] > a[1] ? 1 : -1) * p->edge_sense;
}

typedef struct sewn {
    projcurve_face *a, *b;
    size_t shared;
    double used_tol;
} sewn;

/* A's right side is piece 1; B's left side is pieces 3.. of its loop. */
static sewn sew_pair(const projcurve_surface *sa, const projcurve_surface *sb, int split,
                     double bend)
{
    const loop_def da = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, {0}, 4, 1};
    loop_def db = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.4}, {0, 0}}, {0}, 5, 11};
    if (!split) {
        db.uv[4][1] = 0.0;
        db.n = 4;
        db.bend[3] = bend;
    }
    sewn r = {make_face(sa, &da), make_face(sb, &db), 0, 0.0};
    projcurve_face *faces[2] = {r.a, r.b};
    CHECK_OK(pc_sew_faces(NULL, faces, 2, TOL, &r.shared, &r.used_tol));
    return r;
}

static void check_split(void)
{
    projcurve_surface *sa = square_at(0.0), *sb = square_at(1.0);
    sewn r = sew_pair(sa, sb, 1, 0.0);
    CHECK(r.shared == 1);
    CHECK(r.used_tol == TOL);
    CHECK(r.a->loops[0].pieces[1].edge == 2);
    CHECK(r.b->loops[0].pieces[3].edge == 2);
    CHECK(r.b->loops[0].pieces[4].edge == 2);
    /* the pieces of B run down, A's up: opposite edge senses, one direction */
    CHECK(along_edge(r.a, 1) == along_edge(r.b, 3));
    CHECK(along_edge(r.a, 1) == along_edge(r.b, 4));
    /* the other sides stay edges of one use */
    CHECK(r.a->loops[0].pieces[0].edge == 1 && r.b->loops[0].pieces[1].edge == 12);
    const projcurve_face *faces[2] = {r.a, r.b};
    const size_t index[2] = {0, 1};
    projcurve_shape *shape = NULL;
    CHECK_OK(pc_shape_build(NULL, PROJCURVE_SHAPE_FACE_SET, -1, faces, index, 2, &shape));
    size_t uses = 0, three = 0;
    for (size_t e = 0; e < projcurve_shape_edge_count(shape); ++e) {
        long id = 0;
        CHECK_OK(projcurve_shape_edge(NULL, shape, e, &id, &uses));
        three += id == 2 && uses == 3;
    }
    CHECK(three == 1);
    pc_shape_free(shape);
    pc_face_free(r.a);
    pc_face_free(r.b);
    projcurve_surface_destroy(sa);
    projcurve_surface_destroy(sb);
}

static void check_uneven(void)
{
    projcurve_surface *sa = square_at(0.0), *sb = square_at(1.0);
    /* a middle control point at 0.3 of the chord from (0, 1): the point at
     * t = 0.5 is at y = 0.25 + 0.5 * 0.7 = 0.6, 0.1 from A's middle */
    sewn r = sew_pair(sa, sb, 0, -0.2);
    CHECK(r.shared == 1);
    CHECK(r.a->loops[0].pieces[1].edge == 2 && r.b->loops[0].pieces[3].edge == 2);
    CHECK(along_edge(r.a, 1) == along_edge(r.b, 3));
    pc_face_free(r.a);
    pc_face_free(r.b);
    projcurve_surface_destroy(sa);
    projcurve_surface_destroy(sb);
}

static void check_gap(double gap, int sewn_expected)
{
    projcurve_surface *sa = square_at(0.0), *sb = square_at(1.0 + gap);
    sewn r = sew_pair(sa, sb, 1, 0.0);
    if (sewn_expected) {
        CHECK(r.shared == 1);
        CHECK(r.b->loops[0].pieces[3].edge == 2 && r.b->loops[0].pieces[4].edge == 2);
        /* the farthest probe is gap away, found to the golden search's
         * 3e-13 of a piece's parameter step (1/32) */
        CHECK(fabs(r.used_tol - gap) <= 1e-12);
    } else {
        CHECK(r.shared == 0);
        CHECK(r.used_tol == TOL);
        CHECK(r.b->loops[0].pieces[3].edge == 14 && r.b->loops[0].pieces[4].edge == 15);
    }
    pc_face_free(r.a);
    pc_face_free(r.b);
    projcurve_surface_destroy(sa);
    projcurve_surface_destroy(sb);
}

int main(void)
{
    check_split();
    check_uneven();
    check_gap(50.0 * TOL, 1);
    check_gap(2.0 * PC_SEW_GAP_FACTOR * TOL, 0);
    return pc_test_finish("test_brep_sew");
}
