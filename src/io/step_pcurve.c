/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP loop pieces from PCURVEs: 2D B-splines and LINEs, cut to their
 * edge at the parameters of its vertices on the 3D curve they share, and
 * checked against that curve (reported on the model when they leave it by
 * more than PC_STEP_PCURVE_CHECK_FACTOR precisions).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "common/error.h"
#include "io/step_topology.h"

/* The precision of a face on surface s: the file's, else a fraction of
 * the surface's size. */
double pc_step_precision(const stopo *t, const projcurve_surface *s)
{
    if (t->precision > 0.0 || s == NULL)
        return t->precision;
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    return PC_STEP_DEFAULT_PRECISION_REL * pc_step_dist3(box, box + 3);
}

/* Evaluates a piece (as given, along its parameter) at fraction a of its
 * domain; 0 when it is not a valid curve. */
int pc_step_piece_at(const pc_piece_input *p, double a, double uv[2])
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

int pc_step_surface_point(const projcurve_surface *s, const double uv[2], double p[3])
{
    double d[4];
    projcurve_surface_domain(NULL, s, d);
    return projcurve_surface_eval(NULL, s, fmin(fmax(uv[0], d[0]), d[1]),
                                  fmin(fmax(uv[1], d[2]), d[3]), 0, p) == PROJCURVE_OK;
}

/* The parameter on the LINE o + t d of a vertex at (s, t) uv of the face's
 * NURBS: on an analytic surface its (u, v) is moved by the whole turns
 * (of each full-turn angle direction, PC_STEP_LINE_TURNS either way) that
 * bring it nearest the line, and of those equally near, the turn giving
 * the parameter above after (when after is finite) or nearest 0. */
#define PC_STEP_LINE_TURNS 2
static double line_parameter(const stopo *t, const double o[3], const double d[3], double dd,
                             const double st[2], double after)
{
    double uv[2] = {st[0], st[1]};
    if (t->maps == NULL)
        return ((uv[0] - o[0]) * d[0] + (uv[1] - o[1]) * d[1]) / dd;
    pc_step_uv_to_analytic(t->f, t->maps, st, uv);
    const double unit = t->f->radians_per_angle_unit > 0.0 ? t->f->radians_per_angle_unit : 1.0;
    double turn[2];
    int range[2];
    for (int k = 0; k < 2; ++k) {
        const pc_angle_map *m = &t->maps[k];
        const int full = m->is_angle && m->a1 - m->a0 >= 2.0 * M_PI * (1.0 - 1e-9);
        turn[k] = 2.0 * M_PI / unit;
        range[k] = full ? PC_STEP_LINE_TURNS : 0;
    }
    double best = 0.0, best_off = INFINITY, best_key = INFINITY;
    for (int i = -range[0]; i <= range[0]; ++i)
        for (int j = -range[1]; j <= range[1]; ++j) {
            const double q[2] = {uv[0] + i * turn[0] - o[0], uv[1] + j * turn[1] - o[1]};
            const double par = (q[0] * d[0] + q[1] * d[1]) / dd;
            const double off = hypot(q[0] - par * d[0], q[1] - par * d[1]);
            const double key = isfinite(after) ? (par > after ? par - after : INFINITY) : fabs(par);
            const double near = 1e-9 * (1.0 + fabs(turn[0]) + fabs(turn[1]));
            if (off < best_off - near || (off <= best_off + near && key < best_key))
                best = par, best_off = fmin(off, best_off), best_key = key;
        }
    return best;
}

/* A 2D LINE pcurve between the (u, v) of the edge's vertices va -> vb,
 * along the line's direction (the parameter it shares with the edge's 3D
 * curve); on an analytic surface, in its (u, v), a closed edge (va = vb)
 * once round the turn the line runs along. */
projcurve_status pc_step_line_piece(const stopo *t, const pc_step_located *curve,
                                   const projcurve_surface *s, const double va[3],
                                   const double vb[3], pc_piece_input *out)
{
    double o[3], d[3], uv[2][2];
    projcurve_status st = pc_step_line(t->f, t->arena, curve, o, d);
    if (st != PROJCURVE_OK)
        return st;
    const double dd = d[0] * d[0] + d[1] * d[1];
    if (!(dd > 0.0))
        return pc_step_give_up(t, "#%ld: a LINE of no length%s", curve->inst->id, "");
    for (int k = 0; k < 2; ++k)
        if (projcurve_surface_closest_point(NULL, s, k ? vb : va, uv[k], NULL, NULL) != PROJCURVE_OK)
            return pc_step_give_up(t, "#%ld: a vertex cannot be placed on the surface%s", curve->inst->id, "");
    double lo, hi;
    if (t->maps == NULL) {
        const double p0 = line_parameter(t, o, d, dd, uv[0], NAN), p1 = line_parameter(t, o, d, dd, uv[1], NAN);
        lo = fmin(p0, p1), hi = fmax(p0, p1);
    } else {
        lo = line_parameter(t, o, d, dd, uv[0], NAN);
        const int closed = pc_step_dist3(va, vb) <= PC_STEP_PCURVE_CHECK_FACTOR * pc_step_precision(t, s);
        hi = closed ? lo : line_parameter(t, o, d, dd, uv[1], lo);
        if (closed) { /* once round: the turn of the angle the line moves along */
            const double unit = t->f->radians_per_angle_unit > 0.0 ? t->f->radians_per_angle_unit : 1.0;
            const int k = fabs(d[0]) >= fabs(d[1]) ? 0 : 1;
            hi = lo + 2.0 * M_PI / unit / fabs(d[k]);
        }
    }
    if (!(hi > lo))
        return pc_step_give_up(t, "#%ld: its edge has no length on the LINE%s", curve->inst->id, "");
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
projcurve_status pc_step_bspline_piece(const stopo *t, const pc_step_located *curve, pc_piece_input *out)
{
    pc_io_curve c;
    const char *skip = NULL;
    projcurve_status st = pc_step_curve(t->f, t->arena, curve, &c, NULL, &skip);
    if (st != PROJCURVE_OK)
        return st;
    if (skip != pc_step_planar_curve)
        return pc_step_give_up(t, "pcurve #%ld: %s", curve->inst->id, skip ? skip : "not a 2D curve");
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
projcurve_status pc_step_pcurves_on(const stopo *t, const pc_step_located *geom, long surface_id,
                                   pc_step_located found[2], size_t *n)
{
    *n = 0;
    const pc_step_node *list = pc_step_child(geom->node, 2);
    if (list == NULL || list->kind != PC_STEP_LIST)
        return PROJCURVE_OK;
    for (const pc_step_node *r = list->first; r != NULL && *n < 2; r = r->next) {
        pc_step_located pc, rep, curve;
        projcurve_status st = pc_step_fetch(t, r, geom->inst->id, &pc);
        if (st != PROJCURVE_OK || pc.inst == NULL)
            return st;
        const pc_step_node *surf = pc_step_child(pc.node, 1);
        if (!pc_step_is(pc.node, "PCURVE") || surf == NULL || surf->kind != PC_STEP_REF ||
            surf->ref != surface_id)
            continue;
        if ((st = pc_step_fetch(t, pc_step_child(pc.node, 2), pc.inst->id, &rep)) != PROJCURVE_OK ||
            rep.inst == NULL)
            return st;
        const pc_step_node *items = pc_step_child(rep.node, 1);
        if (items == NULL || items->kind != PC_STEP_LIST || items->first == NULL)
            return pc_step_give_up(t, "#%ld: a representation without items%s", rep.inst->id, "");
        if ((st = pc_step_fetch(t, items->first, rep.inst->id, &curve)) != PROJCURVE_OK || curve.inst == NULL)
            return st;
        found[(*n)++] = curve;
    }
    return PROJCURVE_OK;
}

/* A pcurve whose ends land away from its edge's vertices is reported
 * (listed on the model); a piece whose 3D image is one point is a pole. */
projcurve_status pc_step_check_piece(const stopo *t, const projcurve_surface *s, long surface_id,
                                    long edge_id, pc_piece_input *piece, const double v0[3],
                                    const double v1[3], unsigned *flags)
{
    double uv[3][2], p[3][3];
    if (!pc_step_piece_at(piece, 0.0, uv[0]) || !pc_step_piece_at(piece, 1.0, uv[1]) || !pc_step_piece_at(piece, 0.5, uv[2]))
        return pc_step_give_up(t, "#%ld: its pcurve is not a valid curve%s", edge_id, "");
    for (int k = 0; k < 3; ++k)
        if (!pc_step_surface_point(s, uv[k], p[k]))
            return pc_step_give_up(t, "#%ld: its pcurve leaves the surface%s", edge_id, "");
    const double prec = pc_step_precision(t, s);
    const double off = fmax(pc_step_dist3(p[0], v0), pc_step_dist3(p[1], v1));
    if (off > PC_STEP_PCURVE_CHECK_FACTOR * prec) {
        projcurve_status st = pc_model_add_skipped(
            t->f->ctx, t->model,
            "STEP #%ld EDGE_CURVE: its pcurve on surface #%ld ends %.3g from its vertices "
            "(precision %.3g)", edge_id, surface_id, off, prec);
        if (st != PROJCURVE_OK)
            return st;
    }
    if (pc_step_dist3(p[0], p[1]) <= prec && pc_step_dist3(p[0], p[2]) <= prec && hypot(uv[0][0] - uv[1][0], uv[0][1] - uv[1][1]) > 0.0)
        *flags |= PC_PIECE_DEGENERATE;
    return PROJCURVE_OK;
}

/* The distance of p from the 3D curve of an edge (LINE: the unbounded
 * line; B-spline, CIRCLE, TRIMMED_CURVE: their closest point), or -1
 * when the curve is of another kind. */
static double curve_distance(const stopo *t, const pc_step_located *curve, const double p[3])
{
    if (pc_step_is(curve->node, "LINE")) {
        double o[3], d[3];
        if (pc_step_line(t->f, t->arena, curve, o, d) != PROJCURVE_OK)
            return -1.0;
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double a = dd > 0.0 ? ((p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1] + (p[2] - o[2]) * d[2]) / dd : 0.0;
        const double q[3] = {o[0] + a * d[0], o[1] + a * d[1], o[2] + a * d[2]};
        return pc_step_dist3(p, q);
    }
    pc_io_curve c;
    const char *skip = NULL;
    projcurve_curve *h = NULL;
    if (pc_step_curve(t->f, t->arena, curve, &c, NULL, &skip) != PROJCURVE_OK || skip != NULL ||
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
projcurve_status pc_step_check_against_curve(const stopo *t, const projcurve_surface *s,
                                            long surface_id, long edge_id,
                                            const pc_piece_input *piece, const pc_step_located *curve)
{
    double worst = 0.0;
    for (int k = 1; k <= 3; ++k) {
        double uv[2], p[3];
        if (!pc_step_piece_at(piece, 0.25 * k, uv) || !pc_step_surface_point(s, uv, p))
            return PROJCURVE_OK;
        const double d = curve_distance(t, curve, p);
        if (d < 0.0)
            return PROJCURVE_OK; /* a curve kind not read: nothing to compare with */
        worst = fmax(worst, d);
    }
    const double prec = pc_step_precision(t, s);
    if (worst <= PC_STEP_PCURVE_CHECK_FACTOR * prec)
        return PROJCURVE_OK;
    return pc_model_add_skipped(t->f->ctx, t->model,
                                "STEP #%ld EDGE_CURVE: its pcurve on surface #%ld is %.3g from "
                                "its 3D curve (precision %.3g)", edge_id, surface_id, worst, prec);
}

/* Golden-section steps (PC_STEP_RANGE_REFINE) in [a, b] towards the
 * parameter whose surface point is nearest v. */
#define PC_STEP_RANGE_REFINE 60
static double golden_nearest(const projcurve_surface *s, const pc_curve2 *c, const double v[3],
                             double a, double b)
{
    double uv[2];
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int k = 0; k < PC_STEP_RANGE_REFINE; ++k) {
        const double x = b - g * (b - a), y = a + g * (b - a);
        double px[3], py[3];
        pc_curve2_eval(c, x, uv);
        const int okx = pc_step_surface_point(s, uv, px);
        pc_curve2_eval(c, y, uv);
        const int oky = pc_step_surface_point(s, uv, py);
        if (okx && oky && pc_step_dist3(px, v) < pc_step_dist3(py, v))
            b = y;
        else
            a = x;
    }
    return 0.5 * (a + b);
}

/* The parameter of a pcurve whose surface point is nearest v: the best
 * of PC_STEP_RANGE_SAMPLES samples per control point, then golden-section
 * steps (a fixed number) between its neighbours. */
#define PC_STEP_RANGE_SAMPLES 16
static double nearest_parameter(const projcurve_surface *s, const pc_curve2 *c, const double v[3])
{
    double t0, t1, uv[2], p[3];
    pc_curve2_domain(c, &t0, &t1);
    const size_t n = PC_STEP_RANGE_SAMPLES * c->n_ctrl;
    size_t best = 0;
    double best_d = INFINITY;
    for (size_t i = 0; i <= n; ++i) {
        pc_curve2_eval(c, t0 + (t1 - t0) * (double)i / (double)n, uv);
        if (pc_step_surface_point(s, uv, p) && pc_step_dist3(p, v) < best_d)
            best_d = pc_step_dist3(p, v), best = i;
    }
    double a = t0 + (t1 - t0) * (double)(best > 0 ? best - 1 : 0) / (double)n;
    double b = t0 + (t1 - t0) * (double)(best < n ? best + 1 : n) / (double)n;
    return golden_nearest(s, c, v, a, b);
}

/* The parameter of a pcurve whose surface point is nearest v within
 * PC_STEP_NEAR_WIDTH of its domain around guess, by golden-section
 * steps (a fixed number). */
#define PC_STEP_NEAR_WIDTH (1.0 / 16.0)
static double nearest_parameter_near(const projcurve_surface *s, const pc_curve2 *c,
                                     const double v[3], double guess)
{
    double t0, t1;
    pc_curve2_domain(c, &t0, &t1);
    const double w = PC_STEP_NEAR_WIDTH * (t1 - t0);
    double a = fmax(t0, guess - w), b = fmin(t1, guess + w);
    return golden_nearest(s, c, v, a, b);
}

/* 1 when the pcurve's surface point at parameter a is farther than prec
 * from v (only then is a refined: near a pole the surface point hardly
 * moves with the parameter, and the 3D curve's is the better). */
static int off_vertex(const projcurve_surface *s, const pc_curve2 *c, const double v[3], double a,
                      double prec)
{
    double uv[2], p[3];
    pc_curve2_eval(c, a, uv);
    return pc_step_surface_point(s, uv, p) && pc_step_dist3(p, v) > prec;
}

/* The parameter of v on the edge's 3D curve, which the pcurve shares
 * (ISO 10303-42 SURFACE_CURVE): a LINE's and a CIRCLE's (its angle, moved
 * by turns into [t0, t1] of the pcurve) in closed form, a B-spline's by
 * closest point. 0 when the curve is of another kind. */
static int curve3_parameter(const stopo *t, const pc_step_located *curve, const double v[3], double t0,
                            double t1, double *out)
{
    if (pc_step_is(curve->node, "LINE")) {
        double o[3], d[3];
        if (pc_step_line(t->f, t->arena, curve, o, d) != PROJCURVE_OK)
            return 0;
        const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        *out = ((v[0] - o[0]) * d[0] + (v[1] - o[1]) * d[1] + (v[2] - o[2]) * d[2]) / dd;
        return dd > 0.0;
    }
    if (pc_step_is(curve->node, "CIRCLE")) {
        double o[3], x[3], y[3], ra = 0.0, rb = 0.0;
        const char *skip = NULL;
        if (pc_step_conic(t->f, t->arena, curve, o, x, y, &ra, &rb, &skip) != PROJCURVE_OK || skip)
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
    projcurve_curve *h = NULL;
    if (pc_step_curve(t->f, t->arena, curve, &c, NULL, &skip) != PROJCURVE_OK || skip != NULL ||
        projcurve_curve_create_nurbs(NULL, c.degree, c.n_ctrl, c.ctrl, c.weights, c.knots, &h) != PROJCURVE_OK)
        return 0;
    const int ok = projcurve_curve_closest_point(NULL, h, v, out, NULL, NULL) == PROJCURVE_OK;
    projcurve_curve_destroy(h);
    return ok;
}

/* A pcurve may run past its edge (it shares the 3D curve's parameter, and
 * the vertices bound the edge): when its ends are not at the vertices it
 * is cut, exactly (knot insertion), to the parameters nearest them. */
projcurve_status pc_step_restrict_to_edge(const stopo *t, const projcurve_surface *s,
                                         pc_piece_input *piece, const double v0[3],
                                         const double v1[3], const pc_step_located *curve3)
{
    pc_curve2 c;
    if (pc_curve2_init(NULL, &c, piece->degree, piece->n_ctrl, piece->ctrl, piece->weights,
                       piece->knots, "") != PROJCURVE_OK)
        return PROJCURVE_OK; /* pc_step_check_piece names it */
    double t0, t1, uv[2], p0[3], p1[3];
    pc_curve2_domain(&c, &t0, &t1);
    pc_curve2_eval(&c, t0, uv);
    int ok = pc_step_surface_point(s, uv, p0);
    pc_curve2_eval(&c, t1, uv);
    ok = ok && pc_step_surface_point(s, uv, p1);
    const double prec = PC_STEP_PCURVE_CHECK_FACTOR * pc_step_precision(t, s);
    if (!ok || (pc_step_dist3(p0, v0) <= prec && pc_step_dist3(p1, v1) <= prec) || pc_step_dist3(v0, v1) <= prec) {
        pc_curve2_free(&c);
        return PROJCURVE_OK;
    }
    /* the 3D curve's parameter first (well conditioned where the surface
     * is not: near a pole every u is nearly the same point) */
    double a = 0.0, b = 0.0;
    const double slack = 1e-9 * (t1 - t0);
    const int circle = curve3->inst != NULL && pc_step_is(curve3->node, "CIRCLE");
    if (curve3->inst == NULL || !curve3_parameter(t, curve3, v0, t0, t1, &a) ||
        !curve3_parameter(t, curve3, v1, t0, t1, &b) || a < t0 - slack || b > t1 + slack) {
        a = nearest_parameter(s, &c, v0);
        b = nearest_parameter(s, &c, v1);
    } else if (circle && t->analytic) {
        /* an arc past the angle 0 ends a turn on; a pcurve that is a
         * rational B-spline of the circle has the angle as its parameter
         * at its knots only: a vertex off it is found near its angle */
        if (b <= a && b + 2.0 * M_PI <= t1 + slack)
            b += 2.0 * M_PI;
        a = off_vertex(s, &c, v0, a, prec) ? nearest_parameter_near(s, &c, v0, a) : a;
        b = off_vertex(s, &c, v1, b, prec) ? nearest_parameter_near(s, &c, v1, b) : b;
    }
    a = fmax(a, t0);
    b = fmin(b, t1);
    pc_curve2_free(&c);
    if (!(b > a))
        return PROJCURVE_OK; /* left whole: pc_step_check_piece reports the mismatch */
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
