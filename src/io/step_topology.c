/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP topology: ADVANCED_FACE (its surface, same_sense, FACE_OUTER_BOUND /
 * FACE_BOUND with their orientation), EDGE_LOOP of ORIENTED_EDGEs, each an
 * EDGE_CURVE between VERTEX_POINTs whose geometry is a SURFACE_CURVE or
 * SEAM_CURVE with PCURVEs (a DEFINITIONAL_REPRESENTATION of a 2D B-spline
 * or LINE), or a bare 3D curve; shapes from MANIFOLD_SOLID_BREP,
 * BREP_WITH_VOIDS, SHELL_BASED_SURFACE_MODEL and the CLOSED_SHELL /
 * OPEN_SHELL no solid or model holds. Edges are shared by EDGE_CURVE id.
 *
 * A loop piece is the face's own PCURVE when the edge has one on the face's
 * surface; otherwise the 3D edge is projected onto the surface point by
 * point with the library's closest-point projection ([Ook]), sampled
 * until the chords' midpoints are within the file's precision of the edge
 * (edge_projection below). A face that cannot be built is listed on the
 * model with the reason; the rest of the file still loads. Placements of
 * assemblies are not applied, as for the geometry (step_read.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "brep/face.h"
#include "brep/shape.h"
#include "common/error.h"
#include "io/step.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The precision when the file gives no UNCERTAINTY_MEASURE_WITH_UNIT, as
 * a fraction of the surface's size. */
#define PC_STEP_DEFAULT_PRECISION_REL 1e-7
/* Pieces of a loop may miss each other by this many ON tolerances: files
 * keep edges to their own tolerance, often above the global one. */
#define PC_STEP_CLOSE_FACTOR 100.0
/* A pcurve whose ends are farther than this many precisions from its
 * edge's vertices is reported. */
#define PC_STEP_PCURVE_CHECK_FACTOR 100.0
/* Projection of an edge without pcurve: samples to start with and the
 * most; the chord midpoints must be within the precision. */
#define PC_STEP_PROJECT_SAMPLES 16
#define PC_STEP_PROJECT_MAX_SAMPLES 4096
#define PC_STEP_REASON 200

typedef struct stopo {
    pc_step_file *f;
    projcurve_model *model;
    pc_arena *arena;
    double precision;  /* 0: none in the file */
    long *face_of;     /* per instance: the model's face index, -1 */
    char *reason;      /* why the face being read cannot be built */
} stopo;

typedef struct inst_node {
    const pc_step_instance *inst;
    const pc_step_node *node;
} inst_node;

/* Sets the face's reason (the first one only) and returns OK: the face is
 * skipped, the file goes on. */
static projcurve_status give_up(const stopo *t, const char *fmt, long id, const char *what)
{
    if (!t->reason[0])
        snprintf(t->reason, PC_STEP_REASON, fmt, id, what);
    return PROJCURVE_OK;
}

static projcurve_status fetch(const stopo *t, const pc_step_node *ref, long from, inst_node *out)
{
    out->inst = NULL;
    out->node = NULL;
    if (ref == NULL || ref->kind != PC_STEP_REF)
        return give_up(t, "#%ld: a reference is missing%s", from, "");
    const pc_step_instance *inst = pc_step_find(t->f, ref->ref);
    if (inst == NULL) {
        char what[48];
        snprintf(what, sizeof what, " #%ld, which is not defined", ref->ref);
        return give_up(t, "#%ld refers to%s", from, what);
    }
    pc_step_node *node;
    projcurve_status st = pc_step_parse(t->f, inst, t->arena, &node);
    if (st != PROJCURVE_OK)
        return st;
    out->inst = inst;
    out->node = node;
    return PROJCURVE_OK;
}

static int is_true(const pc_step_node *n)
{
    return !(n && n->kind == PC_STEP_ENUM && n->len == 1 && n->text[0] == 'F');
}

static const char *surface_kind(const pc_step_node *n)
{
    static const char *const names[][2] = {
        {"PLANE", "plane"},           {"CYLINDRICAL_SURFACE", "cylinder"},
        {"CONICAL_SURFACE", "cone"},  {"SPHERICAL_SURFACE", "sphere"},
        {"TOROIDAL_SURFACE", "torus"}, {"SURFACE_OF_REVOLUTION", "revolution"},
        {"SURFACE_OF_LINEAR_EXTRUSION", "extrusion"}, {"OFFSET_SURFACE", "offset"},
        {"DEGENERATE_TOROIDAL_SURFACE", "torus"}};
    for (size_t k = 0; k < sizeof names / sizeof *names; ++k)
        if (pc_step_is(n, names[k][0]) || pc_step_part(n, names[k][0]) != NULL)
            return names[k][1];
    if (pc_step_part(n, "B_SPLINE_SURFACE") != NULL || pc_step_is(n, "B_SPLINE_SURFACE_WITH_KNOTS") ||
        pc_step_is(n, "BEZIER_SURFACE") || pc_step_is(n, "UNIFORM_SURFACE") ||
        pc_step_is(n, "QUASI_UNIFORM_SURFACE"))
        return "bspline";
    return "other";
}

/* The model surface of the surface instance ref: the one place where a
 * file's surface becomes the surface of a face. B-spline surfaces are the
 * model surfaces read by step_read.c; any other kind gives its name in
 * *kind and the reason. */
static projcurve_status face_surface(const stopo *t, const pc_step_node *ref, long from,
                                     const projcurve_surface **out, const char **kind)
{
    *out = NULL;
    *kind = "other";
    inst_node s;
    projcurve_status st = fetch(t, ref, from, &s);
    if (st != PROJCURVE_OK || s.inst == NULL)
        return st;
    *kind = surface_kind(s.node);
    const long index = t->f->surface_of[s.inst - t->f->instances];
    if (index < 0)
        return give_up(t, "surface #%ld: surface kind %s not built", s.inst->id, *kind);
    *out = t->model->surfaces[index];
    return PROJCURVE_OK;
}

/* Pieces of the face being read. */
typedef struct pieces {
    pc_piece_input *items;
    size_t count, capacity;
    pc_loop_input *loops;
    size_t n_loops, cap_loops;
    int has_outer;
} pieces;

static pc_piece_input *new_piece(const stopo *t, pieces *p)
{
    if (p->count == p->capacity) {
        const size_t fresh = p->capacity ? 2 * p->capacity : 16;
        pc_piece_input *items = pc_arena_calloc(t->arena, fresh, sizeof *items);
        if (items == NULL)
            return NULL;
        if (p->count)
            memcpy(items, p->items, p->count * sizeof *items);
        p->items = items;
        p->capacity = fresh;
    }
    return &p->items[p->count++];
}

/* The vertices of an EDGE_CURVE as 3D points. */
static projcurve_status vertices(const stopo *t, const inst_node *edge, double a[3], double b[3])
{
    for (int k = 0; k < 2; ++k) {
        inst_node v;
        projcurve_status st = fetch(t, pc_step_child(edge->node, 1 + (size_t)k), edge->inst->id, &v);
        if (st != PROJCURVE_OK || v.inst == NULL)
            return st;
        if (!pc_step_is(v.node, "VERTEX_POINT"))
            return give_up(t, "#%ld: an edge vertex is not a VERTEX_POINT%s", v.inst->id, "");
        st = pc_step_point(t->f, t->arena, v.inst, pc_step_child(v.node, 1), k ? b : a);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

static double dist3(const double a[3], const double b[3])
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* A 2D LINE pcurve between the (u, v) of the edge's vertices. */
static projcurve_status line_piece(const stopo *t, const inst_node *curve,
                                   const projcurve_surface *s, const double va[3],
                                   const double vb[3], pc_piece_input *out)
{
    double o[3], d[3], uv[2][2];
    projcurve_status st = pc_step_line(t->f, t->arena, curve->inst, o, d);
    if (st != PROJCURVE_OK)
        return st;
    const double dd = d[0] * d[0] + d[1] * d[1];
    if (!(dd > 0.0))
        return give_up(t, "#%ld: a LINE of no length%s", curve->inst->id, "");
    double par[2];
    for (int k = 0; k < 2; ++k) {
        if (projcurve_surface_closest_point(NULL, s, k ? vb : va, uv[k], NULL, NULL) != PROJCURVE_OK)
            return give_up(t, "#%ld: a vertex cannot be placed on the surface%s", curve->inst->id, "");
        par[k] = ((uv[k][0] - o[0]) * d[0] + (uv[k][1] - o[1]) * d[1]) / dd;
    }
    const double lo = fmin(par[0], par[1]), hi = fmax(par[0], par[1]);
    if (!(hi > lo))
        return give_up(t, "#%ld: its edge has no length on the LINE%s", curve->inst->id, "");
    double *ctrl = pc_arena_calloc(t->arena, 4, sizeof *ctrl);
    double *knots = pc_arena_calloc(t->arena, 4, sizeof *knots);
    if (ctrl == NULL || knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    ctrl[0] = o[0] + lo * d[0], ctrl[1] = o[1] + lo * d[1];
    ctrl[2] = o[0] + hi * d[0], ctrl[3] = o[1] + hi * d[1];
    knots[0] = knots[1] = lo;
    knots[2] = knots[3] = hi;
    *out = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl, .knots = knots};
    return PROJCURVE_OK;
}

/* A 2D B-spline pcurve over its whole domain. */
static projcurve_status bspline_piece(const stopo *t, const inst_node *curve, pc_piece_input *out)
{
    pc_io_curve c;
    const char *skip = NULL;
    int planar = 0;
    projcurve_status st = pc_step_curve_geometry(t->f, t->arena, curve->inst, &c, &skip, &planar);
    if (st != PROJCURVE_OK)
        return st;
    if (skip != NULL || !planar)
        return give_up(t, "pcurve #%ld: %s", curve->inst->id, skip ? skip : "not a 2D curve");
    double *uv = pc_arena_calloc(t->arena, 2 * c.n_ctrl, sizeof *uv);
    if (uv == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < c.n_ctrl; ++i)
        uv[2 * i] = c.ctrl[3 * i], uv[2 * i + 1] = c.ctrl[3 * i + 1];
    *out = (pc_piece_input){.degree = c.degree, .n_ctrl = c.n_ctrl, .ctrl = uv,
                            .weights = c.weights, .knots = c.knots};
    return PROJCURVE_OK;
}

/* The PCURVEs of a SURFACE_CURVE / SEAM_CURVE on the surface #surface_id:
 * their 2D curves, at most two. */
static projcurve_status pcurves_on(const stopo *t, const inst_node *geom, long surface_id,
                                   inst_node found[2], size_t *n)
{
    *n = 0;
    const pc_step_node *list = pc_step_child(geom->node, 2);
    if (list == NULL || list->kind != PC_STEP_LIST)
        return PROJCURVE_OK;
    for (const pc_step_node *r = list->first; r != NULL && *n < 2; r = r->next) {
        inst_node pc, rep, curve;
        projcurve_status st = fetch(t, r, geom->inst->id, &pc);
        if (st != PROJCURVE_OK || pc.inst == NULL)
            return st;
        const pc_step_node *surf = pc_step_child(pc.node, 1);
        if (!pc_step_is(pc.node, "PCURVE") || surf == NULL || surf->kind != PC_STEP_REF ||
            surf->ref != surface_id)
            continue;
        if ((st = fetch(t, pc_step_child(pc.node, 2), pc.inst->id, &rep)) != PROJCURVE_OK ||
            rep.inst == NULL)
            return st;
        const pc_step_node *items = pc_step_child(rep.node, 1);
        if (items == NULL || items->kind != PC_STEP_LIST || items->first == NULL)
            return give_up(t, "#%ld: a representation without items%s", rep.inst->id, "");
        if ((st = fetch(t, items->first, rep.inst->id, &curve)) != PROJCURVE_OK || curve.inst == NULL)
            return st;
        found[(*n)++] = curve;
    }
    return PROJCURVE_OK;
}

/* The precision of a face on surface s: the file's, else a fraction of
 * the surface's size. */
static double precision_of(const stopo *t, const projcurve_surface *s)
{
    if (t->precision > 0.0 || s == NULL)
        return t->precision;
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    return PC_STEP_DEFAULT_PRECISION_REL * dist3(box, box + 3);
}

/* Evaluates a piece (as given, along its parameter) at fraction a of its
 * domain; 0 when it is not a valid curve. */
static int piece_at(const pc_piece_input *p, double a, double uv[2])
{
    pc_curve2 c;
    if (pc_curve2_init(NULL, &c, p->degree, p->n_ctrl, p->ctrl, p->weights, p->knots, "") != PROJCURVE_OK)
        return 0;
    double t0, t1;
    pc_curve2_domain(&c, &t0, &t1);
    pc_curve2_eval(&c, t0 + a * (t1 - t0), uv);
    pc_curve2_free(&c);
    return 1;
}

static int surface_point(const projcurve_surface *s, const double uv[2], double p[3])
{
    double d[4];
    projcurve_surface_domain(NULL, s, d);
    return projcurve_surface_eval(NULL, s, fmin(fmax(uv[0], d[0]), d[1]),
                                  fmin(fmax(uv[1], d[2]), d[3]), 0, p) == PROJCURVE_OK;
}

/* A pcurve whose ends land away from its edge's vertices is reported
 * (listed on the model); a piece whose 3D image is one point is a pole. */
static projcurve_status check_piece(const stopo *t, const projcurve_surface *s, long surface_id,
                                    long edge_id, pc_piece_input *piece, const double v0[3],
                                    const double v1[3], unsigned *flags)
{
    double uv[3][2], p[3][3];
    if (!piece_at(piece, 0.0, uv[0]) || !piece_at(piece, 1.0, uv[1]) || !piece_at(piece, 0.5, uv[2]))
        return give_up(t, "#%ld: its pcurve is not a valid curve%s", edge_id, "");
    for (int k = 0; k < 3; ++k)
        if (!surface_point(s, uv[k], p[k]))
            return give_up(t, "#%ld: its pcurve leaves the surface%s", edge_id, "");
    const double prec = precision_of(t, s);
    const double off = fmax(dist3(p[0], v0), dist3(p[1], v1));
    if (off > PC_STEP_PCURVE_CHECK_FACTOR * prec) {
        projcurve_status st = pc_model_add_skipped(
            t->f->ctx, t->model,
            "STEP #%ld EDGE_CURVE: its pcurve on surface #%ld ends %.3g from its vertices "
            "(precision %.3g)", edge_id, surface_id, off, prec);
        if (st != PROJCURVE_OK)
            return st;
    }
    if (dist3(p[0], p[1]) <= prec && dist3(p[0], p[2]) <= prec && hypot(uv[0][0] - uv[1][0], uv[0][1] - uv[1][1]) > 0.0)
        *flags |= PC_PIECE_DEGENERATE;
    return PROJCURVE_OK;
}

/* The distance of p from the 3D curve of an edge (LINE: the unbounded
 * line; B-spline, CIRCLE, TRIMMED_CURVE: their closest point), or -1
 * when the curve is of another kind. */
static double curve_distance(const stopo *t, const inst_node *curve, const double p[3])
{
    if (pc_step_is(curve->node, "LINE")) {
        double o[3], d[3];
        if (pc_step_line(t->f, t->arena, curve->inst, o, d) != PROJCURVE_OK)
            return -1.0;
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double a = dd > 0.0 ? ((p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1] + (p[2] - o[2]) * d[2]) / dd : 0.0;
        const double q[3] = {o[0] + a * d[0], o[1] + a * d[1], o[2] + a * d[2]};
        return dist3(p, q);
    }
    pc_io_curve c;
    const char *skip = NULL;
    int planar = 0;
    projcurve_curve *h = NULL;
    if (pc_step_curve_geometry(t->f, t->arena, curve->inst, &c, &skip, &planar) != PROJCURVE_OK ||
        skip != NULL || planar ||
        projcurve_curve_create_nurbs(NULL, c.degree, c.n_ctrl, c.ctrl, c.weights, c.knots, &h) != PROJCURVE_OK)
        return -1.0;
    double tt = 0.0, d = -1.0;
    if (projcurve_curve_closest_point(NULL, h, p, &tt, NULL, &d) != PROJCURVE_OK)
        d = -1.0;
    projcurve_curve_destroy(h);
    return d;
}

/* A pcurve whose surface image leaves its edge's 3D curve by more than
 * PC_STEP_PCURVE_CHECK_FACTOR precisions (at a quarter, half and three
 * quarters of it) is reported on the model. */
static projcurve_status check_against_curve(const stopo *t, const projcurve_surface *s,
                                            long surface_id, long edge_id,
                                            const pc_piece_input *piece, const inst_node *curve)
{
    double worst = 0.0;
    for (int k = 1; k <= 3; ++k) {
        double uv[2], p[3];
        if (!piece_at(piece, 0.25 * k, uv) || !surface_point(s, uv, p))
            return PROJCURVE_OK;
        const double d = curve_distance(t, curve, p);
        if (d < 0.0)
            return PROJCURVE_OK; /* a curve kind not read: nothing to compare with */
        worst = fmax(worst, d);
    }
    const double prec = precision_of(t, s);
    if (worst <= PC_STEP_PCURVE_CHECK_FACTOR * prec)
        return PROJCURVE_OK;
    return pc_model_add_skipped(t->f->ctx, t->model,
                                "STEP #%ld EDGE_CURVE: its pcurve on surface #%ld is %.3g from "
                                "its 3D curve (precision %.3g)", edge_id, surface_id, worst, prec);
}

/* The parameter of a pcurve whose surface point is nearest v: the best
 * of PC_STEP_RANGE_SAMPLES samples per control point, then golden-section
 * steps (a fixed number) between its neighbours. */
#define PC_STEP_RANGE_SAMPLES 16
#define PC_STEP_RANGE_REFINE 60
static double nearest_parameter(const projcurve_surface *s, const pc_curve2 *c, const double v[3])
{
    double t0, t1, uv[2], p[3];
    pc_curve2_domain(c, &t0, &t1);
    const size_t n = PC_STEP_RANGE_SAMPLES * c->n_ctrl;
    size_t best = 0;
    double best_d = INFINITY;
    for (size_t i = 0; i <= n; ++i) {
        pc_curve2_eval(c, t0 + (t1 - t0) * (double)i / (double)n, uv);
        if (surface_point(s, uv, p) && dist3(p, v) < best_d)
            best_d = dist3(p, v), best = i;
    }
    double a = t0 + (t1 - t0) * (double)(best > 0 ? best - 1 : 0) / (double)n;
    double b = t0 + (t1 - t0) * (double)(best < n ? best + 1 : n) / (double)n;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int k = 0; k < PC_STEP_RANGE_REFINE; ++k) {
        const double x = b - g * (b - a), y = a + g * (b - a);
        double px[3], py[3];
        pc_curve2_eval(c, x, uv);
        const int okx = surface_point(s, uv, px);
        pc_curve2_eval(c, y, uv);
        const int oky = surface_point(s, uv, py);
        if (okx && oky && dist3(px, v) < dist3(py, v))
            b = y;
        else
            a = x;
    }
    return 0.5 * (a + b);
}

/* The parameter of v on the edge's 3D curve, which the pcurve shares
 * (ISO 10303-42 SURFACE_CURVE): a LINE's and a CIRCLE's (its angle, moved
 * by turns into [t0, t1] of the pcurve) in closed form, a B-spline's by
 * closest point. 0 when the curve is of another kind. */
static int curve3_parameter(const stopo *t, const inst_node *curve, const double v[3], double t0,
                            double t1, double *out)
{
    if (pc_step_is(curve->node, "LINE")) {
        double o[3], d[3];
        if (pc_step_line(t->f, t->arena, curve->inst, o, d) != PROJCURVE_OK)
            return 0;
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        *out = ((v[0] - o[0]) * d[0] + (v[1] - o[1]) * d[1] + (v[2] - o[2]) * d[2]) / dd;
        return dd > 0.0;
    }
    if (pc_step_is(curve->node, "CIRCLE")) {
        double o[3], x[3], y[3];
        const char *skip = NULL;
        if (pc_step_circle(t->f, t->arena, curve->inst, o, x, y, &skip) != PROJCURVE_OK || skip)
            return 0;
        const double r[3] = {v[0] - o[0], v[1] - o[1], v[2] - o[2]};
        double a = atan2(r[0] * y[0] + r[1] * y[1] + r[2] * y[2], r[0] * x[0] + r[1] * x[1] + r[2] * x[2]);
        const double turn = 2.0 * M_PI, slack = 1e-9 * turn;
        while (a < t0 - slack)
            a += turn;
        while (a > t1 + slack && a - turn >= t0 - slack)
            a -= turn;
        *out = a;
        return 1;
    }
    pc_io_curve c;
    const char *skip = NULL;
    int planar = 0;
    projcurve_curve *h = NULL;
    if (pc_step_curve_geometry(t->f, t->arena, curve->inst, &c, &skip, &planar) != PROJCURVE_OK ||
        skip != NULL || planar ||
        projcurve_curve_create_nurbs(NULL, c.degree, c.n_ctrl, c.ctrl, c.weights, c.knots, &h) != PROJCURVE_OK)
        return 0;
    const int ok = projcurve_curve_closest_point(NULL, h, v, out, NULL, NULL) == PROJCURVE_OK;
    projcurve_curve_destroy(h);
    return ok;
}

/* A pcurve may run past its edge (it shares the 3D curve's parameter, and
 * the vertices bound the edge): when its ends are not at the vertices it
 * is cut, exactly (knot insertion), to the parameters nearest them. */
static projcurve_status restrict_to_edge(const stopo *t, const projcurve_surface *s,
                                         pc_piece_input *piece, const double v0[3],
                                         const double v1[3], const inst_node *curve3)
{
    pc_curve2 c;
    if (pc_curve2_init(NULL, &c, piece->degree, piece->n_ctrl, piece->ctrl, piece->weights,
                       piece->knots, "") != PROJCURVE_OK)
        return PROJCURVE_OK; /* check_piece names it */
    double t0, t1, uv[2], p0[3], p1[3];
    pc_curve2_domain(&c, &t0, &t1);
    pc_curve2_eval(&c, t0, uv);
    int ok = surface_point(s, uv, p0);
    pc_curve2_eval(&c, t1, uv);
    ok = ok && surface_point(s, uv, p1);
    const double prec = PC_STEP_PCURVE_CHECK_FACTOR * precision_of(t, s);
    if (!ok || (dist3(p0, v0) <= prec && dist3(p1, v1) <= prec) || dist3(v0, v1) <= prec) {
        pc_curve2_free(&c);
        return PROJCURVE_OK;
    }
    /* the 3D curve's parameter first (well conditioned where the surface
     * is not: near a pole every u is nearly the same point) */
    double a = 0.0, b = 0.0;
    const double slack = 1e-9 * (t1 - t0);
    if (curve3->inst == NULL || !curve3_parameter(t, curve3, v0, t0, t1, &a) ||
        !curve3_parameter(t, curve3, v1, t0, t1, &b) || a < t0 - slack || b > t1 + slack) {
        a = nearest_parameter(s, &c, v0);
        b = nearest_parameter(s, &c, v1);
    }
    a = fmax(a, t0);
    b = fmin(b, t1);
    pc_curve2_free(&c);
    if (!(b > a))
        return PROJCURVE_OK; /* left whole: check_piece reports the mismatch */
    pc_io_curve whole = {.degree = piece->degree, .n_ctrl = piece->n_ctrl,
                         .weights = (double *)piece->weights, .knots = (double *)piece->knots};
    whole.ctrl = pc_arena_calloc(t->arena, 3 * piece->n_ctrl, sizeof *whole.ctrl);
    if (whole.ctrl == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < piece->n_ctrl; ++i)
        whole.ctrl[3 * i] = piece->ctrl[2 * i], whole.ctrl[3 * i + 1] = piece->ctrl[2 * i + 1];
    pc_io_curve part;
    projcurve_status st = pc_io_curve_restrict(t->f->ctx, t->arena, &whole, a, b, &part);
    if (st != PROJCURVE_OK)
        return st;
    double *ctrl = pc_arena_calloc(t->arena, 2 * part.n_ctrl, sizeof *ctrl);
    if (ctrl == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < part.n_ctrl; ++i)
        ctrl[2 * i] = part.ctrl[3 * i], ctrl[2 * i + 1] = part.ctrl[3 * i + 1];
    piece->n_ctrl = part.n_ctrl;
    piece->ctrl = ctrl;
    piece->weights = part.weights;
    piece->knots = part.knots;
    return PROJCURVE_OK;
}

/* The 3D curve of an edge without pcurve, from v0 to v1 along its
 * parameter, as a curve handle over [*t0, *t1]. */
static projcurve_status edge_curve3(const stopo *t, const inst_node *curve, const double v0[3],
                                    const double v1[3], projcurve_curve **out, double *t0,
                                    double *t1, int *closed)
{
    pc_io_curve c;
    double ends[6];
    const char *skip = NULL;
    int planar = 0;
    projcurve_status st;
    if (pc_step_is(curve->node, "LINE")) {
        memcpy(ends, v0, 3 * sizeof *ends);
        memcpy(ends + 3, v1, 3 * sizeof *ends);
        st = pc_io_line_curve(t->f->ctx, t->arena, ends, ends + 3, &c);
    } else {
        st = pc_step_curve_geometry(t->f, t->arena, curve->inst, &c, &skip, &planar);
    }
    if (st != PROJCURVE_OK)
        return st;
    if (skip != NULL || planar)
        return give_up(t, "edge curve #%ld: %s, and no pcurve", curve->inst->id,
                       skip ? skip : "a 2D curve");
    if (projcurve_curve_create_nurbs(NULL, c.degree, c.n_ctrl, c.ctrl, c.weights, c.knots, out) != PROJCURVE_OK)
        return give_up(t, "edge curve #%ld: %s", curve->inst->id, "not a valid curve");
    projcurve_curve_domain(NULL, *out, t0, t1);
    /* a closed curve whose vertices meet within the check's tolerance is
     * a closed edge (files keep vertices to their edge tolerance) */
    double c0[3], c1[3];
    projcurve_curve_eval(NULL, *out, *t0, 0, c0);
    projcurve_curve_eval(NULL, *out, *t1, 0, c1);
    const double near = PC_STEP_PCURVE_CHECK_FACTOR * precision_of(t, NULL);
    *closed = dist3(v0, v1) <= near && dist3(c0, c1) <= near;
    if (!*closed) { /* an open edge: between its vertices */
        double a = *t0, b = *t1;
        projcurve_curve_closest_point(NULL, *out, v0, &a, NULL, NULL);
        projcurve_curve_closest_point(NULL, *out, v1, &b, NULL, NULL);
        *t0 = a, *t1 = b;
    }
    if (!(*t1 > *t0)) {
        projcurve_curve_destroy(*out);
        *out = NULL;
        return give_up(t, "edge curve #%ld: its vertices do not bound a %s", curve->inst->id,
                       "range of it");
    }
    return PROJCURVE_OK;
}

/* Projects samples C(t_i) onto s ([Ook] closest points) and returns the
 * largest distance, over the chords, of S at a chord's midpoint from the
 * curve's point half way (the polyline's error in 3D). */
static double project_samples(const projcurve_surface *s, const projcurve_curve *c, double t0,
                              double t1, size_t n, double *uv, double *off)
{
    double err = 0.0;
    *off = 0.0;
    for (size_t i = 0; i <= n; ++i) {
        double p[3], q[3], d = 0.0;
        projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * (double)i / (double)n, 0, p);
        projcurve_surface_closest_point(NULL, s, p, uv + 2 * i, q, &d);
        *off = fmax(*off, d);
        if (i == 0)
            continue;
        double m[3], sm[3];
        const double mid[2] = {0.5 * (uv[2 * i - 2] + uv[2 * i]), 0.5 * (uv[2 * i - 1] + uv[2 * i + 1])};
        projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * ((double)i - 0.5) / (double)n, 0, m);
        if (surface_point(s, mid, sm))
            err = fmax(err, dist3(m, sm));
    }
    return err;
}

/* The pcurve of an edge that has none: its 3D curve projected onto the
 * surface at n + 1 samples, n doubling from PC_STEP_PROJECT_SAMPLES until
 * the chords are within the precision or n reaches
 * PC_STEP_PROJECT_MAX_SAMPLES, or the error no longer halves (the edge
 * lies off the surface); the error reached is then reported. A degree-1
 * piece over the edge's parameters. */
static projcurve_status edge_projection(const stopo *t, const inst_node *curve,
                                        const projcurve_surface *s, const double v0[3],
                                        const double v1[3], pc_piece_input *out)
{
    projcurve_curve *c = NULL;
    double t0 = 0.0, t1 = 1.0;
    int closed = 0;
    projcurve_status st = edge_curve3(t, curve, v0, v1, &c, &t0, &t1, &closed);
    if (st != PROJCURVE_OK || c == NULL)
        return st;
    const double prec = precision_of(t, s);
    double *uv = NULL, err = INFINITY, off = 0.0;
    size_t n = PC_STEP_PROJECT_SAMPLES;
    for (;; n *= 2) {
        uv = pc_arena_calloc(t->arena, 2 * (n + 1), sizeof *uv);
        if (uv == NULL)
            break;
        const double before = err;
        err = project_samples(s, c, t0, t1, n, uv, &off);
        if (closed) /* a closed edge: one point, one (u, v) */
            uv[2 * n] = uv[0], uv[2 * n + 1] = uv[1];
        /* chords shrink the error 4 times a doubling; when it stops
         * halving, the edge's own distance from the surface dominates */
        if (err <= prec || n >= PC_STEP_PROJECT_MAX_SAMPLES || err > 0.5 * before)
            break;
    }
    projcurve_curve_destroy(c);
    double *knots = uv ? pc_arena_calloc(t->arena, n + 3, sizeof *knots) : NULL;
    if (knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    knots[0] = t0;
    for (size_t i = 0; i <= n; ++i)
        knots[i + 1] = t0 + (t1 - t0) * (double)i / (double)n;
    knots[n + 2] = t1;
    *out = (pc_piece_input){.degree = 1, .n_ctrl = n + 1, .ctrl = uv, .knots = knots};
    if (err > prec || off > PC_STEP_PCURVE_CHECK_FACTOR * prec)
        return pc_model_add_skipped(t->f->ctx, t->model,
                                    "STEP #%ld: the edge projected onto its face at %zu samples "
                                    "is within %.3g (precision %.3g); the edge is up to %.3g "
                                    "from the surface", curve->inst->id, n + 1, err, prec, off);
    return PROJCURVE_OK;
}

/* One ORIENTED_EDGE of a loop as a piece. */
static projcurve_status edge_piece(const stopo *t, const pc_step_node *ref, long loop_id,
                                   int bound_sense, const projcurve_surface *s, long surface_id,
                                   pieces *p)
{
    inst_node oe, edge, geom;
    projcurve_status st = fetch(t, ref, loop_id, &oe);
    if (st != PROJCURVE_OK || oe.inst == NULL)
        return st;
    if (!pc_step_is(oe.node, "ORIENTED_EDGE"))
        return give_up(t, "#%ld: a loop member is not an ORIENTED_EDGE%s", oe.inst->id, "");
    if ((st = fetch(t, pc_step_child(oe.node, 3), oe.inst->id, &edge)) != PROJCURVE_OK || edge.inst == NULL)
        return st;
    if (!pc_step_is(edge.node, "EDGE_CURVE"))
        return give_up(t, "#%ld: an oriented edge's element is not an EDGE_CURVE%s", edge.inst->id, "");
    if ((st = fetch(t, pc_step_child(edge.node, 3), edge.inst->id, &geom)) != PROJCURVE_OK || geom.inst == NULL)
        return st;
    const int oe_sense = is_true(pc_step_child(oe.node, 4)) ? 1 : -1;
    const int same = is_true(pc_step_child(edge.node, 4)) ? 1 : -1;
    double va[3], vb[3];
    if ((st = vertices(t, &edge, va, vb)) != PROJCURVE_OK || t->reason[0])
        return st;
    pc_piece_input *piece = new_piece(t, p);
    if (piece == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    unsigned flags = 0;
    const int seam = pc_step_is(geom.node, "SEAM_CURVE");
    inst_node found[2];
    size_t n_found = 0;
    if (seam || pc_step_is(geom.node, "SURFACE_CURVE"))
        st = pcurves_on(t, &geom, surface_id, found, &n_found);
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if (n_found > 0) {
        /* a seam's first pcurve for the edge used forwards, the second backwards */
        const inst_node *c = &found[(seam && n_found == 2 && oe_sense < 0) ? 1 : 0];
        st = pc_step_is(c->node, "LINE") ? line_piece(t, c, s, same > 0 ? va : vb, same > 0 ? vb : va, piece)
                                         : bspline_piece(t, c, piece);
        inst_node curve3 = {NULL, NULL};
        if (st == PROJCURVE_OK && !t->reason[0])
            st = fetch(t, pc_step_child(geom.node, 1), geom.inst->id, &curve3);
        if (st == PROJCURVE_OK && !t->reason[0] && !pc_step_is(c->node, "LINE"))
            st = restrict_to_edge(t, s, piece, same > 0 ? va : vb, same > 0 ? vb : va, &curve3);
        if (st == PROJCURVE_OK && !t->reason[0] && curve3.inst != NULL)
            st = check_against_curve(t, s, surface_id, edge.inst->id, piece, &curve3);
        flags |= seam ? PC_PIECE_SEAM : 0u;
    } else {
        inst_node curve3 = geom;
        if (seam || pc_step_is(geom.node, "SURFACE_CURVE"))
            st = fetch(t, pc_step_child(geom.node, 1), geom.inst->id, &curve3);
        if (st == PROJCURVE_OK && curve3.inst != NULL)
            st = edge_projection(t, &curve3, s, same > 0 ? va : vb, same > 0 ? vb : va, piece);
    }
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if ((st = check_piece(t, s, surface_id, edge.inst->id, piece, same > 0 ? va : vb,
                          same > 0 ? vb : va, &flags)) != PROJCURVE_OK)
        return st;
    piece->edge = edge.inst->id;
    piece->edge_sense = same;
    piece->sense = bound_sense * oe_sense * same;
    piece->flags = flags;
    return PROJCURVE_OK;
}

static int push_loop(const stopo *t, pieces *p, size_t first, int outer)
{
    if (p->n_loops == p->cap_loops) {
        const size_t fresh = p->cap_loops ? 2 * p->cap_loops : 8;
        pc_loop_input *loops = pc_arena_calloc(t->arena, fresh, sizeof *loops);
        if (loops == NULL)
            return 0;
        if (p->n_loops)
            memcpy(loops, p->loops, p->n_loops * sizeof *loops);
        p->loops = loops;
        p->cap_loops = fresh;
    }
    p->loops[p->n_loops++] = (pc_loop_input){.n_pieces = p->count - first, .outer = outer};
    return 1;
}

/* A FACE_OUTER_BOUND / FACE_BOUND and its EDGE_LOOP. */
static projcurve_status read_bound(const stopo *t, const pc_step_node *ref, long face_id,
                                   const projcurve_surface *s, long surface_id, pieces *p)
{
    inst_node bound, loop;
    projcurve_status st = fetch(t, ref, face_id, &bound);
    if (st != PROJCURVE_OK || bound.inst == NULL)
        return st;
    const int outer = pc_step_is(bound.node, "FACE_OUTER_BOUND");
    if (!outer && !pc_step_is(bound.node, "FACE_BOUND"))
        return give_up(t, "#%ld: a bound is not a FACE_BOUND%s", bound.inst->id, "");
    if ((st = fetch(t, pc_step_child(bound.node, 1), bound.inst->id, &loop)) != PROJCURVE_OK ||
        loop.inst == NULL)
        return st;
    if (pc_step_is(loop.node, "VERTEX_LOOP"))
        return give_up(t, "#%ld: a VERTEX_LOOP (a pole as a loop) is not built%s", loop.inst->id, "");
    const pc_step_node *edges = pc_step_child(loop.node, 1);
    if (!pc_step_is(loop.node, "EDGE_LOOP") || edges == NULL || edges->kind != PC_STEP_LIST ||
        edges->first == NULL)
        return give_up(t, "#%ld: not an EDGE_LOOP with edges%s", loop.inst->id, "");
    const int sense = is_true(pc_step_child(bound.node, 2)) ? 1 : -1;
    const size_t first = p->count;
    for (const pc_step_node *e = edges->first; e != NULL && st == PROJCURVE_OK && !t->reason[0]; e = e->next)
        st = edge_piece(t, e, loop.inst->id, sense, s, surface_id, p);
    if (st != PROJCURVE_OK || t->reason[0])
        return st;
    if (sense < 0) /* the bound runs the loop backwards: its edges in reverse order */
        for (size_t i = first, j = p->count - 1; i < j; ++i, --j) {
            const pc_piece_input tmp = p->items[i];
            p->items[i] = p->items[j];
            p->items[j] = tmp;
        }
    p->has_outer |= outer;
    return push_loop(t, p, first, outer)
               ? PROJCURVE_OK
               : pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
}

/* Marks pieces whose edge appears twice in one loop as seams. */
static void mark_seams(pieces *p)
{
    size_t at = 0;
    for (size_t l = 0; l < p->n_loops; ++l) {
        for (size_t i = at; i < at + p->loops[l].n_pieces; ++i)
            for (size_t j = i + 1; j < at + p->loops[l].n_pieces; ++j)
                if (p->items[i].edge == p->items[j].edge) {
                    p->items[i].flags |= PC_PIECE_SEAM;
                    p->items[j].flags |= PC_PIECE_SEAM;
                }
        at += p->loops[l].n_pieces;
    }
}

static projcurve_status read_face(stopo *t, const inst_node *face)
{
    char reason[PC_STEP_REASON] = "";
    t->reason = reason;
    const projcurve_surface *s = NULL;
    const char *kind = "other";
    const pc_step_node *sref = pc_step_child(face->node, 2);
    projcurve_status st = face_surface(t, sref, face->inst->id, &s, &kind);
    pieces p = {0};
    const pc_step_node *bounds = pc_step_child(face->node, 1);
    if (st == PROJCURVE_OK && !reason[0] && (bounds == NULL || bounds->kind != PC_STEP_LIST))
        give_up(t, "#%ld: its bounds are not a list%s", face->inst->id, "");
    for (const pc_step_node *b = reason[0] ? NULL : bounds->first; b != NULL && st == PROJCURVE_OK && !reason[0]; b = b->next)
        st = read_bound(t, b, face->inst->id, s, sref->ref, &p);
    if (st != PROJCURVE_OK)
        return st;
    char what[64];
    snprintf(what, sizeof what, "STEP #%ld ADVANCED_FACE", face->inst->id);
    if (reason[0])
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s: %s", what, reason);
    mark_seams(&p);
    size_t at = 0;
    for (size_t l = 0; l < p.n_loops; ++l) {
        p.loops[l].pieces = p.items + at;
        at += p.loops[l].n_pieces;
    }
    const double tol_model = precision_of(t, s);
    const double tol_uv = pc_face_uv_tolerance(s, tol_model);
    const pc_face_params fp = {.tol_uv = tol_uv, .tol_model = tol_model,
                               .close_tol = PC_STEP_CLOSE_FACTOR * tol_uv,
                               .same_sense = is_true(pc_step_child(face->node, 3)) ? 1 : -1,
                               .pick_outer = !p.has_outer, .id = face->inst->id, .kind = kind,
                               .what = what};
    projcurve_context scratch = {.magic = PC_CONTEXT_MAGIC};
    projcurve_face *f = NULL;
    st = pc_face_build(&scratch, s, p.loops, p.n_loops, &fp, &f);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(t->f->ctx, st, "%s", scratch.last_message);
    if (st != PROJCURVE_OK)
        return pc_model_add_unbuilt(t->f->ctx, t->model, kind, "%s", scratch.last_message);
    t->face_of[face->inst - t->f->instances] = (long)t->model->n_faces;
    return pc_model_add_face(t->f->ctx, t->model, f);
}

/* 1 when a simple instance is of one of the names (NULL-terminated list),
 * read from its text without parsing it: the passes below look at a few
 * kinds among thousands of points. */
static int named(const pc_step_file *f, const pc_step_instance *inst, const char *const *names)
{
    size_t pos = inst->begin;
    while (pos < inst->end && (f->text[pos] == ' ' || f->text[pos] == '\n' ||
                               f->text[pos] == '\r' || f->text[pos] == '\t'))
        ++pos;
    size_t len = 0;
    while (pos + len < inst->end && (f->text[pos + len] == '_' ||
                                     (f->text[pos + len] >= 'A' && f->text[pos + len] <= 'Z') ||
                                     (f->text[pos + len] >= '0' && f->text[pos + len] <= '9')))
        ++len;
    for (; *names != NULL; ++names)
        if (strlen(*names) == len && strncmp(f->text + pos, *names, len) == 0)
            return 1;
    return 0;
}

static const char *const face_names[] = {"ADVANCED_FACE", "FACE_SURFACE", NULL};
static const char *const shape_names[] = {"MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS",
                                          "SHELL_BASED_SURFACE_MODEL", "CLOSED_SHELL",
                                          "OPEN_SHELL", NULL};
static const char *const precision_names[] = {"UNCERTAINTY_MEASURE_WITH_UNIT", NULL};

/* The largest UNCERTAINTY_MEASURE_WITH_UNIT length (0 if none). */
static double file_precision(const stopo *t, const pc_step_node *node)
{
    if (!pc_step_is(node, "UNCERTAINTY_MEASURE_WITH_UNIT"))
        return t->precision;
    const pc_step_node *m = pc_step_child(node, 0);
    const pc_step_node *v = m && m->kind == PC_STEP_TYPED ? pc_step_child(m, 0) : m;
    if (v && v->kind == PC_STEP_NUMBER && v->number > 0.0 && isfinite(v->number))
        return fmax(t->precision, v->number);
    return t->precision;
}

/* Model face indices of the faces of a shell, appended to idx. */
static projcurve_status shell_faces(stopo *t, const pc_step_node *ref, long from, size_t *idx,
                                    size_t *n, size_t cap, unsigned char *used,
                                    projcurve_shape_kind *kind)
{
    char reason[PC_STEP_REASON] = "";
    t->reason = reason;
    inst_node shell;
    projcurve_status st = fetch(t, ref, from, &shell);
    if (st != PROJCURVE_OK || shell.inst == NULL)
        return st;
    used[shell.inst - t->f->instances] = 1;
    if (kind != NULL)
        *kind = pc_step_is(shell.node, "CLOSED_SHELL") ? PROJCURVE_SHAPE_CLOSED_SHELL
                                                       : PROJCURVE_SHAPE_OPEN_SHELL;
    const pc_step_node *faces = pc_step_child(shell.node, 1);
    if (faces == NULL || faces->kind != PC_STEP_LIST)
        return PROJCURVE_OK;
    for (const pc_step_node *r = faces->first; r != NULL && *n < cap; r = r->next) {
        const pc_step_instance *fi = r->kind == PC_STEP_REF ? pc_step_find(t->f, r->ref) : NULL;
        const long index = fi ? t->face_of[fi - t->f->instances] : -1;
        if (index >= 0)
            idx[(*n)++] = (size_t)index;
    }
    return PROJCURVE_OK;
}

static projcurve_status add_shape(stopo *t, projcurve_shape_kind kind, long id, size_t *idx,
                                  size_t n)
{
    if (n == 0)
        return PROJCURVE_OK;
    const projcurve_face **faces = malloc(n * sizeof *faces);
    if (faces == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < n; ++i)
        faces[i] = t->model->faces[idx[i]];
    projcurve_shape *shape = NULL;
    projcurve_status st = pc_shape_build(t->f->ctx, kind, id, faces, idx, n, &shape);
    free(faces);
    return st == PROJCURVE_OK ? pc_model_add_shape(t->f->ctx, t->model, shape) : st;
}

/* Solids and surface models first, then the shells none of them holds. */
static projcurve_status read_shapes(stopo *t, size_t *idx, unsigned char *used)
{
    const size_t cap = t->model->n_faces;
    projcurve_status st = PROJCURVE_OK;
    for (int pass = 0; pass < 2 && st == PROJCURVE_OK; ++pass)
        for (size_t i = 0; i < t->f->n_instances && st == PROJCURVE_OK; ++i) {
            const pc_step_instance *inst = &t->f->instances[i];
            pc_step_node *node;
            if (!named(t->f, inst, shape_names))
                continue;
            if ((st = pc_step_parse(t->f, inst, t->arena, &node)) != PROJCURVE_OK)
                break;
            size_t n = 0;
            projcurve_shape_kind kind = PROJCURVE_SHAPE_SOLID;
            const int solid = pc_step_is(node, "MANIFOLD_SOLID_BREP") || pc_step_is(node, "BREP_WITH_VOIDS");
            const int model = pc_step_is(node, "SHELL_BASED_SURFACE_MODEL");
            const int shell = pc_step_is(node, "CLOSED_SHELL") || pc_step_is(node, "OPEN_SHELL");
            if (pass == 0 && solid) {
                st = shell_faces(t, pc_step_child(node, 1), inst->id, idx, &n, cap, used, NULL);
                const pc_step_node *voids = pc_step_is(node, "BREP_WITH_VOIDS") ? pc_step_child(node, 2) : NULL;
                for (const pc_step_node *v = voids && voids->kind == PC_STEP_LIST ? voids->first : NULL;
                     v != NULL && st == PROJCURVE_OK; v = v->next)
                    st = shell_faces(t, v, inst->id, idx, &n, cap, used, NULL);
            } else if (pass == 0 && model) {
                const pc_step_node *shells = pc_step_child(node, 1);
                for (const pc_step_node *r = shells && shells->kind == PC_STEP_LIST ? shells->first : NULL;
                     r != NULL && st == PROJCURVE_OK; r = r->next) {
                    n = 0;
                    st = shell_faces(t, r, inst->id, idx, &n, cap, used, &kind);
                    if (st == PROJCURVE_OK)
                        st = add_shape(t, kind, r->kind == PC_STEP_REF ? r->ref : -1, idx, n);
                }
                n = 0;
            } else if (pass == 1 && shell && !used[i]) {
                const pc_step_node self = {.kind = PC_STEP_REF, .ref = inst->id};
                st = shell_faces(t, &self, inst->id, idx, &n, cap, used, &kind);
            }
            if (st == PROJCURVE_OK && n > 0)
                st = add_shape(t, kind, inst->id, idx, n);
            pc_arena_release(t->arena);
        }
    return st;
}

projcurve_status pc_step_read_topology(pc_step_file *f, projcurve_model *model)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    char none[1] = "";
    stopo t = {.f = f, .model = model, .arena = &arena, .reason = none};
    t.face_of = malloc((f->n_instances + 1) * sizeof *t.face_of);
    unsigned char *used = calloc(f->n_instances + 1, 1);
    projcurve_status st = PROJCURVE_OK;
    if (t.face_of == NULL || used == NULL)
        st = pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; st == PROJCURVE_OK && i <= f->n_instances; ++i)
        t.face_of[i] = -1;
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        pc_step_node *node;
        if (!named(f, &f->instances[i], precision_names))
            continue;
        st = pc_step_parse(f, &f->instances[i], &arena, &node);
        if (st == PROJCURVE_OK)
            t.precision = file_precision(&t, node);
        pc_arena_release(&arena);
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        pc_step_node *node;
        if (!named(f, &f->instances[i], face_names))
            continue;
        st = pc_step_parse(f, &f->instances[i], &arena, &node);
        if (st == PROJCURVE_OK && (pc_step_is(node, "ADVANCED_FACE") || pc_step_is(node, "FACE_SURFACE"))) {
            const inst_node face = {&f->instances[i], node};
            st = read_face(&t, &face);
        }
        pc_arena_release(&arena);
    }
    size_t *idx = st == PROJCURVE_OK ? malloc((model->n_faces + 1) * sizeof *idx) : NULL;
    if (st == PROJCURVE_OK && idx == NULL)
        st = pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    if (st == PROJCURVE_OK)
        st = read_shapes(&t, idx, used);
    free(idx);
    free(used);
    free(t.face_of);
    pc_arena_release(&arena);
    return st;
}
