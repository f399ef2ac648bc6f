/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP geometry: B-spline surfaces and curves (simple and complex/rational
 * forms, knots given by multiplicities or implied by BEZIER / UNIFORM /
 * QUASI_UNIFORM), CIRCLE (a full turn) and TRIMMED_CURVE over LINE, CIRCLE
 * or B-spline curves with PARAMETER_VALUE or point trims. Topology and
 * assembly placements are not read: curves come out as their full
 * geometry, in the coordinates of the representation that holds them.
 * Angles of trimmed circles are taken in radians.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/io_geom.h"
#include "io/step.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Instance text may be parsed this many times the file size (points are
 * parsed once per reference). */
#define PC_STEP_WORK_FACTOR 16
#define PC_STEP_WORK_MIN ((size_t)1 << 20)

/* The largest |PARAMETER_VALUE| accepted on a trimmed circle, in radians
 * (about 1,600 turns; real files stay within a few). At 1e4 one ulp of the
 * angle is 1.8e-12 rad, so reducing it modulo 2 pi keeps the trim point
 * well inside any model tolerance; larger values are refused rather than
 * rounded to an arbitrary point of the circle. */
#define PC_STEP_MAX_ANGLE 1e4

typedef struct reader {
    pc_step_file *f;
    projcurve_model *model;
    pc_arena *arena;
    long *trim_bases; /* sorted ids used as basis of a TRIMMED_CURVE */
    size_t n_trim_bases;
} reader;

typedef struct located {
    const pc_step_instance *inst;
    const pc_step_node *node;
} located;

static projcurve_status bad(const reader *r, const pc_step_instance *at, const char *what)
{
    return pc_fail(r->f->ctx, PROJCURVE_ERR_PARSE, "STEP #%ld (line %zu): %s", at->id, at->line,
                   what);
}

static projcurve_status resolve(const reader *r, const pc_step_instance *from,
                                const pc_step_node *ref, located *out)
{
    if (ref == NULL || ref->kind != PC_STEP_REF)
        return bad(r, from, "a reference (#n) is missing");
    const pc_step_instance *inst = pc_step_find(r->f, ref->ref);
    if (inst == NULL) {
        char msg[96];
        snprintf(msg, sizeof msg, "refers to #%ld, which is not defined", ref->ref);
        return bad(r, from, msg);
    }
    pc_step_node *node;
    projcurve_status st = pc_step_parse(r->f, inst, r->arena, &node);
    if (st != PROJCURVE_OK)
        return st;
    out->inst = inst;
    out->node = node;
    return PROJCURVE_OK;
}

/* The numbers of a list node into out[0..max); *n gets their count. */
static projcurve_status numbers(const reader *r, const pc_step_instance *at,
                                const pc_step_node *list, double *out, size_t max, size_t *n)
{
    if (list == NULL || list->kind != PC_STEP_LIST || list->n_children > max)
        return bad(r, at, "expected a list of numbers");
    size_t k = 0;
    for (const pc_step_node *c = list->first; c != NULL; c = c->next) {
        if (c->kind != PC_STEP_NUMBER)
            return bad(r, at, "a list holds something other than a number");
        out[k++] = c->number;
    }
    *n = k;
    return PROJCURVE_OK;
}

/* CARTESIAN_POINT('', (x, y[, z])): *dim gets 1..3. */
static projcurve_status point(const reader *r, const pc_step_instance *from,
                              const pc_step_node *ref, double p[3], size_t *dim)
{
    located loc = {NULL, NULL};
    projcurve_status st = resolve(r, from, ref, &loc);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(loc.node, "CARTESIAN_POINT"))
        return bad(r, loc.inst, "expected a CARTESIAN_POINT");
    p[0] = p[1] = p[2] = 0.0;
    st = numbers(r, loc.inst, pc_step_child(loc.node, 1), p, 3, dim);
    if (st == PROJCURVE_OK && *dim == 0)
        return bad(r, loc.inst, "a point without coordinates");
    return st;
}

static projcurve_status direction(const reader *r, const pc_step_instance *from,
                                  const pc_step_node *ref, const char *type, double d[3])
{
    located loc = {NULL, NULL};
    projcurve_status st = resolve(r, from, ref, &loc);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(loc.node, type))
        return bad(r, loc.inst, "expected a DIRECTION");
    size_t n;
    d[0] = d[1] = d[2] = 0.0;
    st = numbers(r, loc.inst, pc_step_child(loc.node, 1), d, 3, &n);
    if (st != PROJCURVE_OK)
        return st;
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0.0) || !isfinite(len))
        return bad(r, loc.inst, "a direction of length zero");
    for (int k = 0; k < 3; ++k)
        d[k] /= len;
    return PROJCURVE_OK;
}

/* AXIS2_PLACEMENT_3D: origin and an orthonormal frame x, y (z = axis). */
static projcurve_status placement(const reader *r, const pc_step_instance *from,
                                  const pc_step_node *ref, double o[3], double x[3], double y[3],
                                  const char **skip)
{
    located loc = {NULL, NULL};
    projcurve_status st = resolve(r, from, ref, &loc);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(loc.node, "AXIS2_PLACEMENT_3D")) {
        *skip = "placed in 2D (a parameter-space curve)";
        return PROJCURVE_OK;
    }
    size_t dim = 0;
    if ((st = point(r, loc.inst, pc_step_child(loc.node, 1), o, &dim)) != PROJCURVE_OK)
        return st;
    double z[3] = {0.0, 0.0, 1.0}, xr[3] = {1.0, 0.0, 0.0};
    const pc_step_node *axis = pc_step_child(loc.node, 2), *refd = pc_step_child(loc.node, 3);
    if (axis && axis->kind == PC_STEP_REF &&
        (st = direction(r, loc.inst, axis, "DIRECTION", z)) != PROJCURVE_OK)
        return st;
    if (refd && refd->kind == PC_STEP_REF &&
        (st = direction(r, loc.inst, refd, "DIRECTION", xr)) != PROJCURVE_OK)
        return st;
    /* x = the reference direction made perpendicular to the axis. */
    double dot = xr[0] * z[0] + xr[1] * z[1] + xr[2] * z[2];
    for (int k = 0; k < 3; ++k)
        x[k] = xr[k] - dot * z[k];
    double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!(len > 1e-12)) {
        /* Any perpendicular will do when the reference is parallel. */
        const double alt[3] = {fabs(z[0]) < 0.9 ? 1.0 : 0.0, fabs(z[0]) < 0.9 ? 0.0 : 1.0, 0.0};
        dot = alt[0] * z[0] + alt[1] * z[1];
        for (int k = 0; k < 3; ++k)
            x[k] = alt[k] - dot * z[k];
        len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    }
    for (int k = 0; k < 3; ++k)
        x[k] /= len;
    y[0] = z[1] * x[2] - z[2] * x[1];
    y[1] = z[2] * x[0] - z[0] * x[2];
    y[2] = z[0] * x[1] - z[1] * x[0];
    return PROJCURVE_OK;
}

/* ---- B-splines ----------------------------------------------------------- */

typedef struct bspline_nodes {
    int dim; /* 1 curve, 2 surface */
    const pc_step_node *degree[2], *points, *mults[2], *knots[2], *weights;
    const char *implied; /* BEZIER, UNIFORM or QUASI_UNIFORM when knots are implied */
} bspline_nodes;

static const char *const implied_forms[][2] = {
    {"BEZIER_CURVE", "BEZIER_SURFACE"},
    {"UNIFORM_CURVE", "UNIFORM_SURFACE"},
    {"QUASI_UNIFORM_CURVE", "QUASI_UNIFORM_SURFACE"},
};

/* Finds the parts of a B-spline instance; returns 0 if it is not one. */
static int bspline_parts(const pc_step_node *n, bspline_nodes *b)
{
    memset(b, 0, sizeof *b);
    static const char *const with_knots[2] = {"B_SPLINE_CURVE_WITH_KNOTS",
                                              "B_SPLINE_SURFACE_WITH_KNOTS"};
    static const char *const base[2] = {"B_SPLINE_CURVE", "B_SPLINE_SURFACE"};
    static const char *const rational[2] = {"RATIONAL_B_SPLINE_CURVE", "RATIONAL_B_SPLINE_SURFACE"};
    for (int d = 0; d < 2; ++d) {
        const size_t nd = (size_t)d + 1; /* number of parametric directions */
        if (n->kind == PC_STEP_TYPED) {
            /* Simple instance: name first, then the B_SPLINE_* attributes. */
            const pc_step_node *head = NULL;
            if (pc_step_is(n, with_knots[d]))
                head = n;
            for (size_t k = 0; k < 3 && head == NULL; ++k)
                if (pc_step_is(n, implied_forms[k][d])) {
                    head = n;
                    b->implied = implied_forms[k][d];
                }
            if (head == NULL)
                continue;
            b->dim = d + 1;
            for (size_t k = 0; k < nd; ++k)
                b->degree[k] = pc_step_child(n, 1 + k);
            b->points = pc_step_child(n, 1 + nd);
            /* attributes after the points: form, closed flag(s), self-intersect */
            const size_t after = 1 + nd + 1 + 1 + nd + 1;
            if (b->implied == NULL)
                for (size_t k = 0; k < nd; ++k) {
                    b->mults[k] = pc_step_child(n, after + k);
                    b->knots[k] = pc_step_child(n, after + nd + k);
                }
            return 1;
        }
        const pc_step_node *bs = pc_step_part(n, base[d]);
        if (bs == NULL)
            continue;
        b->dim = d + 1;
        for (size_t k = 0; k < nd; ++k)
            b->degree[k] = pc_step_child(bs, k);
        b->points = pc_step_child(bs, nd);
        const pc_step_node *wk = pc_step_part(n, with_knots[d]);
        if (wk != NULL) {
            for (size_t k = 0; k < nd; ++k) {
                b->mults[k] = pc_step_child(wk, k);
                b->knots[k] = pc_step_child(wk, nd + k);
            }
        } else {
            b->implied = "";
            for (size_t k = 0; k < 3; ++k)
                if (pc_step_part(n, implied_forms[k][d]) != NULL)
                    b->implied = implied_forms[k][d];
        }
        const pc_step_node *rat = pc_step_part(n, rational[d]);
        if (rat != NULL)
            b->weights = pc_step_child(rat, 0);
        return 1;
    }
    return 0;
}

static projcurve_status degree_of(const reader *r, const pc_step_instance *at,
                                  const pc_step_node *n, int *out)
{
    if (n == NULL || n->kind != PC_STEP_NUMBER || n->number != floor(n->number) ||
        n->number < 1 || n->number > PROJCURVE_MAX_DEGREE)
        return bad(r, at, "degree is not an integer in 1..30");
    *out = (int)n->number;
    return PROJCURVE_OK;
}

/* Knot vector of n_ctrl + degree + 1 values from multiplicities and
 * distinct knots, or implied by the form. */
static projcurve_status knot_vector(const reader *r, const pc_step_instance *at,
                                    const bspline_nodes *b, size_t dir, int degree, size_t n_ctrl,
                                    double **out)
{
    const size_t p = (size_t)degree, total = n_ctrl + p + 1;
    double *u = pc_arena_calloc(r->arena, total, sizeof *u);
    if (u == NULL)
        return pc_fail(r->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    *out = u;
    if (b->implied != NULL) {
        if (strstr(b->implied, "QUASI_UNIFORM") == b->implied) {
            for (size_t i = 0; i < total; ++i)
                u[i] = (i <= p) ? 0.0 : (i >= n_ctrl ? (double)(n_ctrl - p) : (double)(i - p));
        } else if (strstr(b->implied, "UNIFORM") == b->implied) {
            for (size_t i = 0; i < total; ++i)
                u[i] = (double)i - (double)p;
        } else if (strstr(b->implied, "BEZIER") == b->implied && (n_ctrl - 1) % p == 0) {
            const size_t segs = (n_ctrl - 1) / p;
            for (size_t i = 0; i < total; ++i)
                u[i] = (i <= p) ? 0.0 : (i >= n_ctrl ? (double)segs : (double)((i - 1) / p));
        } else {
            return bad(r, at, "knots are neither given nor implied by a known form");
        }
        return PROJCURVE_OK;
    }
    const pc_step_node *m = b->mults[dir], *k = b->knots[dir];
    if (m == NULL || k == NULL || m->kind != PC_STEP_LIST || k->kind != PC_STEP_LIST ||
        m->n_children != k->n_children)
        return bad(r, at, "knot multiplicities and knots do not pair up");
    size_t q = 0;
    for (const pc_step_node *mi = m->first, *ki = k->first; mi != NULL; mi = mi->next, ki = ki->next) {
        if (mi->kind != PC_STEP_NUMBER || ki->kind != PC_STEP_NUMBER || mi->number < 1 ||
            mi->number != floor(mi->number) || mi->number > (double)(total - q))
            return bad(r, at, "knot multiplicities do not add up to points + degree + 1");
        for (size_t c = 0; c < (size_t)mi->number; ++c)
            u[q++] = ki->number;
    }
    if (q != total)
        return bad(r, at, "knot multiplicities do not add up to points + degree + 1");
    return PROJCURVE_OK;
}

/* Points (and weights) of a curve (one list) or surface (list of lists,
 * outer index u): stored u fastest. *planar is set when points are 2D. */
static projcurve_status control_net(const reader *r, const pc_step_instance *at,
                                    const bspline_nodes *b, size_t n[2], double **ctrl,
                                    double **weights, int *planar)
{
    const pc_step_node *pts = b->points;
    if (pts == NULL || pts->kind != PC_STEP_LIST || pts->n_children == 0)
        return bad(r, at, "control points are not a list");
    n[0] = pts->n_children;
    n[1] = 1;
    if (b->dim == 2) {
        const pc_step_node *row = pts->first;
        if (row->kind != PC_STEP_LIST || row->n_children == 0)
            return bad(r, at, "control points are not a list of lists");
        n[1] = row->n_children;
    }
    const size_t count = n[0] * n[1];
    *ctrl = pc_arena_calloc(r->arena, 3 * count, sizeof(double));
    *weights = b->weights ? pc_arena_calloc(r->arena, count, sizeof(double)) : NULL;
    if (*ctrl == NULL || (b->weights && *weights == NULL))
        return pc_fail(r->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    const pc_step_node *wrow = b->weights ? b->weights->first : NULL;
    if (b->weights && (b->weights->kind != PC_STEP_LIST || b->weights->n_children != n[0]))
        return bad(r, at, "weights do not match the control points");
    size_t i = 0;
    for (const pc_step_node *row = pts->first; row != NULL; row = row->next, ++i) {
        const pc_step_node *first = (b->dim == 2) ? row->first : row;
        if (b->dim == 2 && (row->kind != PC_STEP_LIST || row->n_children != n[1]))
            return bad(r, at, "rows of control points differ in length");
        const pc_step_node *w = NULL;
        if (wrow != NULL) {
            w = (b->dim == 2) ? wrow->first : wrow;
            if (b->dim == 2 && (wrow->kind != PC_STEP_LIST || wrow->n_children != n[1]))
                return bad(r, at, "weights do not match the control points");
        }
        size_t j = 0;
        for (const pc_step_node *c = first; c != NULL && j < n[1]; c = (b->dim == 2) ? c->next : NULL, ++j) {
            const size_t idx = j * n[0] + i;
            size_t dim = 0;
            projcurve_status st = point(r, at, c, *ctrl + 3 * idx, &dim);
            if (st != PROJCURVE_OK)
                return st;
            *planar |= (dim < 3);
            if (w != NULL) {
                if (w->kind != PC_STEP_NUMBER)
                    return bad(r, at, "a weight is not a number");
                (*weights)[idx] = w->number;
                w = w->next;
            }
        }
        if (wrow != NULL)
            wrow = wrow->next;
    }
    return PROJCURVE_OK;
}

static projcurve_status bspline_curve(const reader *r, const pc_step_instance *at,
                                      const bspline_nodes *b, pc_io_curve *out, const char **skip)
{
    size_t n[2] = {0, 0};
    int planar = 0;
    projcurve_status st = degree_of(r, at, b->degree[0], &out->degree);
    if (st == PROJCURVE_OK)
        st = control_net(r, at, b, n, &out->ctrl, &out->weights, &planar);
    if (st == PROJCURVE_OK)
        st = knot_vector(r, at, b, 0, out->degree, n[0], &out->knots);
    out->n_ctrl = n[0];
    if (st == PROJCURVE_OK && planar)
        *skip = "2D, a curve in a parameter space";
    return st;
}

static projcurve_status bspline_surface(const reader *r, const pc_step_instance *at,
                                        const bspline_nodes *b, pc_io_surface *out,
                                        const char **skip)
{
    size_t n[2] = {0, 0};
    int planar = 0;
    projcurve_status st;
    if ((st = degree_of(r, at, b->degree[0], &out->deg_u)) != PROJCURVE_OK ||
        (st = degree_of(r, at, b->degree[1], &out->deg_v)) != PROJCURVE_OK ||
        (st = control_net(r, at, b, n, &out->ctrl, &out->weights, &planar)) != PROJCURVE_OK ||
        (st = knot_vector(r, at, b, 0, out->deg_u, n[0], &out->knots_u)) != PROJCURVE_OK ||
        (st = knot_vector(r, at, b, 1, out->deg_v, n[1], &out->knots_v)) != PROJCURVE_OK)
        return st;
    out->n_u = n[0];
    out->n_v = n[1];
    if (planar)
        *skip = "2D control points";
    return PROJCURVE_OK;
}

/* ---- circles, lines, trimmed curves --------------------------------------- */

static projcurve_status circle_frame(const reader *r, const located *c, double o[3], double x[3],
                                     double y[3], double *radius, const char **skip)
{
    const pc_step_node *rad = pc_step_child(c->node, 2);
    projcurve_status st = placement(r, c->inst, pc_step_child(c->node, 1), o, x, y, skip);
    if (st != PROJCURVE_OK || *skip != NULL)
        return st;
    if (rad == NULL || rad->kind != PC_STEP_NUMBER || !(rad->number > 0.0))
        return bad(r, c->inst, "circle radius is not a positive number");
    *radius = rad->number;
    return PROJCURVE_OK;
}

static projcurve_status full_circle(const reader *r, const located *c, pc_io_curve *out,
                                    const char **skip)
{
    double o[3], x[3], y[3], radius;
    projcurve_status st = circle_frame(r, c, o, x, y, &radius, skip);
    if (st != PROJCURVE_OK || *skip != NULL)
        return st;
    return pc_io_arc_curve(r->f->ctx, r->arena, o, x, y, radius, 0.0, 2.0 * M_PI, out);
}

/* LINE('', pnt, VECTOR('', DIRECTION, magnitude)): P(t) = pnt + t m d. */
static projcurve_status line_frame(const reader *r, const located *l, double o[3], double v[3])
{
    size_t dim = 0;
    projcurve_status st = point(r, l->inst, pc_step_child(l->node, 1), o, &dim);
    if (st != PROJCURVE_OK)
        return st;
    located vec = {NULL, NULL};
    if ((st = resolve(r, l->inst, pc_step_child(l->node, 2), &vec)) != PROJCURVE_OK)
        return st;
    const pc_step_node *mag = pc_step_child(vec.node, 2);
    if (!pc_step_is(vec.node, "VECTOR") || mag == NULL || mag->kind != PC_STEP_NUMBER)
        return bad(r, vec.inst, "expected VECTOR('', direction, magnitude)");
    if ((st = direction(r, vec.inst, pc_step_child(vec.node, 1), "DIRECTION", v)) != PROJCURVE_OK)
        return st;
    for (int k = 0; k < 3; ++k)
        v[k] *= mag->number;
    return PROJCURVE_OK;
}

/* A trim: PARAMETER_VALUE(t) if present (preferred), else a point. */
static projcurve_status trim_of(const reader *r, const pc_step_instance *at,
                                const pc_step_node *list, int *has_param, double *t,
                                int *has_point, double p[3])
{
    *has_param = *has_point = 0;
    if (list == NULL || list->kind != PC_STEP_LIST)
        return bad(r, at, "a trim is not a list");
    for (const pc_step_node *c = list->first; c != NULL; c = c->next) {
        if (pc_step_is(c, "PARAMETER_VALUE") && c->first && c->first->kind == PC_STEP_NUMBER) {
            if (!isfinite(c->first->number))
                return bad(r, at, "a PARAMETER_VALUE is not finite");
            *has_param = 1;
            *t = c->first->number;
        } else if (c->kind == PC_STEP_REF) {
            size_t dim = 0;
            projcurve_status st = point(r, at, c, p, &dim);
            if (st != PROJCURVE_OK)
                return st;
            *has_point = 1;
        }
    }
    if (!*has_param && !*has_point)
        return bad(r, at, "a trim has neither a parameter nor a point");
    return PROJCURVE_OK;
}

static void reverse_curve(pc_io_curve *c)
{
    const size_t n = c->n_ctrl, nk = c->n_ctrl + (size_t)c->degree + 1;
    for (size_t i = 0; i < n / 2; ++i) {
        for (size_t k = 0; k < 3; ++k) {
            const double tmp = c->ctrl[3 * i + k];
            c->ctrl[3 * i + k] = c->ctrl[3 * (n - 1 - i) + k];
            c->ctrl[3 * (n - 1 - i) + k] = tmp;
        }
        if (c->weights) {
            const double tmp = c->weights[i];
            c->weights[i] = c->weights[n - 1 - i];
            c->weights[n - 1 - i] = tmp;
        }
    }
    /* u -> a + b - u keeps the domain [a, b]. */
    const double sum = c->knots[0] + c->knots[nk - 1];
    for (size_t i = 0; i < nk / 2; ++i) {
        const double tmp = c->knots[i];
        c->knots[i] = sum - c->knots[nk - 1 - i];
        c->knots[nk - 1 - i] = sum - tmp;
    }
    if (nk % 2 == 1)
        c->knots[nk / 2] = sum - c->knots[nk / 2];
}

static projcurve_status trimmed_curve(const reader *r, const located *tc, pc_io_curve *out,
                                      const char **skip)
{
    located basis = {NULL, NULL};
    projcurve_status st = resolve(r, tc->inst, pc_step_child(tc->node, 1), &basis);
    if (st != PROJCURVE_OK)
        return st;
    int hp[2], hq[2];
    double t[2], p[2][3];
    for (size_t k = 0; k < 2; ++k)
        if ((st = trim_of(r, tc->inst, pc_step_child(tc->node, 2 + k), &hp[k], &t[k], &hq[k],
                          p[k])) != PROJCURVE_OK)
            return st;
    const pc_step_node *sense = pc_step_child(tc->node, 4);
    const int forward = !(sense && sense->kind == PC_STEP_ENUM && sense->len == 1 && sense->text[0] == 'F');
    if (pc_step_is(basis.node, "LINE")) {
        double o[3], v[3];
        if ((st = line_frame(r, &basis, o, v)) != PROJCURVE_OK)
            return st;
        for (size_t k = 0; k < 2; ++k)
            if (hp[k])
                for (int c = 0; c < 3; ++c)
                    p[k][c] = o[c] + t[k] * v[c];
        return pc_io_line_curve(r->f->ctx, r->arena, p[0], p[1], out);
    }
    if (pc_step_is(basis.node, "CIRCLE")) {
        double o[3], x[3], y[3], radius;
        if ((st = circle_frame(r, &basis, o, x, y, &radius, skip)) != PROJCURVE_OK || *skip)
            return st;
        for (size_t k = 0; k < 2; ++k)
            if (!hp[k]) {
                double d[3];
                for (int c = 0; c < 3; ++c)
                    d[c] = p[k][c] - o[c];
                t[k] = atan2(d[0] * y[0] + d[1] * y[1] + d[2] * y[2],
                             d[0] * x[0] + d[1] * x[1] + d[2] * x[2]);
            }
        for (size_t k = 0; k < 2; ++k)
            if (!(fabs(t[k]) <= PC_STEP_MAX_ANGLE))
                return bad(r, tc->inst, "a trim angle of a CIRCLE exceeds 1e4 rad in magnitude");
        /* The arc runs from a0 through a sweep in (0, 2 pi], reduced in one
         * step (fmod is exact) instead of by adding turns. */
        const double a0 = forward ? t[0] : t[1];
        double sweep = fmod((forward ? t[1] : t[0]) - (forward ? t[0] : t[1]), 2.0 * M_PI);
        if (sweep <= 0.0)
            sweep += 2.0 * M_PI;
        const double a1 = a0 + sweep;
        st = pc_io_arc_curve(r->f->ctx, r->arena, o, x, y, radius, a0, a1, out);
        if (st == PROJCURVE_OK && !forward)
            reverse_curve(out);
        return st;
    }
    bspline_nodes b;
    if (bspline_parts(basis.node, &b) && b.dim == 1) {
        if (!hp[0] || !hp[1]) {
            *skip = "trimmed by points only";
            return PROJCURVE_OK;
        }
        pc_io_curve full;
        if ((st = bspline_curve(r, basis.inst, &b, &full, skip)) != PROJCURVE_OK || *skip)
            return st;
        const double a = forward ? t[0] : t[1], e = forward ? t[1] : t[0];
        if ((st = pc_io_curve_restrict(r->f->ctx, r->arena, &full, a, e, out)) != PROJCURVE_OK)
            return bad(r, tc->inst, "trim parameters outside the basis curve");
        if (!forward)
            reverse_curve(out);
        return PROJCURVE_OK;
    }
    *skip = "basis curve of an unsupported type";
    return PROJCURVE_OK;
}

/* ---- dispatch -------------------------------------------------------------- */

/* Geometry types that are recognised but not converted. */
static const char *const listed_types[] = {
    "PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE", "SPHERICAL_SURFACE", "TOROIDAL_SURFACE",
    "DEGENERATE_TOROIDAL_SURFACE", "SURFACE_OF_REVOLUTION", "SURFACE_OF_LINEAR_EXTRUSION",
    "OFFSET_SURFACE", "RECTANGULAR_TRIMMED_SURFACE", "CURVE_BOUNDED_SURFACE",
    "RECTANGULAR_COMPOSITE_SURFACE", "ELLIPSE", "HYPERBOLA", "PARABOLA", "POLYLINE",
    "OFFSET_CURVE_3D", "COMPOSITE_CURVE", "LINE"};

/* The entity name of a simple instance (without parsing it). */
static size_t simple_name(const pc_step_file *f, const pc_step_instance *inst, char *name)
{
    size_t pos = inst->begin;
    while (pos < inst->end && (f->text[pos] == ' ' || f->text[pos] == '\n' || f->text[pos] == '\r' || f->text[pos] == '\t'))
        ++pos;
    size_t n = 0;
    while (pos < inst->end && n + 1 < PC_STEP_MAX_NAME &&
           ((f->text[pos] >= 'A' && f->text[pos] <= 'Z') || f->text[pos] == '_' ||
            (f->text[pos] >= '0' && f->text[pos] <= '9')))
        name[n++] = f->text[pos++];
    name[n] = '\0';
    return n;
}

static int is_trim_basis(const reader *r, long id)
{
    size_t lo = 0, hi = r->n_trim_bases;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (r->trim_bases[mid] < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < r->n_trim_bases && r->trim_bases[lo] == id;
}

static int interesting(const char *name)
{
    return strstr(name, "B_SPLINE_") != NULL || strstr(name, "BEZIER_") == name ||
           strstr(name, "UNIFORM_") != NULL || strcmp(name, "CIRCLE") == 0 ||
           strcmp(name, "TRIMMED_CURVE") == 0;
}

static projcurve_status read_instance(reader *r, const pc_step_instance *inst, const char *name)
{
    located loc = {.inst = inst};
    pc_step_node *node;
    projcurve_status st = pc_step_parse(r->f, inst, r->arena, &node);
    if (st != PROJCURVE_OK)
        return st;
    loc.node = node;
    const char *label = name[0] ? name : "complex entity";
    char origin[PC_STEP_MAX_NAME + 48];
    snprintf(origin, sizeof origin, "STEP #%ld %s", inst->id, label);
    const char *skip = NULL;
    bspline_nodes b;
    if (bspline_parts(node, &b)) {
        if (b.dim == 2) {
            pc_io_surface s;
            st = bspline_surface(r, inst, &b, &s, &skip);
            if (st == PROJCURVE_OK && skip == NULL)
                return pc_model_add_surface(r->f->ctx, r->model, &s, origin);
        } else {
            if (is_trim_basis(r, inst->id))
                return PROJCURVE_OK;
            pc_io_curve c;
            st = bspline_curve(r, inst, &b, &c, &skip);
            if (st == PROJCURVE_OK && skip == NULL)
                return pc_model_add_curve(r->f->ctx, r->model, &c, origin);
        }
    } else if (pc_step_is(node, "CIRCLE") || pc_step_is(node, "TRIMMED_CURVE")) {
        if (is_trim_basis(r, inst->id))
            return PROJCURVE_OK;
        pc_io_curve c;
        st = pc_step_is(node, "CIRCLE") ? full_circle(r, &loc, &c, &skip)
                                        : trimmed_curve(r, &loc, &c, &skip);
        if (st == PROJCURVE_OK && skip == NULL)
            return pc_model_add_curve(r->f->ctx, r->model, &c, origin);
    } else {
        return PROJCURVE_OK; /* a complex entity that is no B-spline (units, contexts) */
    }
    if (st != PROJCURVE_OK)
        return st;
    return pc_model_add_skipped(r->f->ctx, r->model, "%s (%s)", origin, skip);
}

/* Ids of the basis curves of TRIMMED_CURVEs, sorted: these are read through
 * the trimmed curve only. */
static projcurve_status collect_trim_bases(reader *r)
{
    char name[PC_STEP_MAX_NAME];
    size_t count = 0;
    for (size_t i = 0; i < r->f->n_instances; ++i)
        if (simple_name(r->f, &r->f->instances[i], name) && strcmp(name, "TRIMMED_CURVE") == 0)
            ++count;
    r->trim_bases = malloc((count + 1) * sizeof *r->trim_bases);
    if (r->trim_bases == NULL)
        return pc_fail(r->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < r->f->n_instances; ++i) {
        const pc_step_instance *inst = &r->f->instances[i];
        if (!simple_name(r->f, inst, name) || strcmp(name, "TRIMMED_CURVE") != 0)
            continue;
        pc_step_node *node;
        projcurve_status st = pc_step_parse(r->f, inst, r->arena, &node);
        if (st != PROJCURVE_OK)
            return st;
        const pc_step_node *basis = pc_step_child(node, 1);
        if (basis && basis->kind == PC_STEP_REF)
            r->trim_bases[r->n_trim_bases++] = basis->ref;
        pc_arena_release(r->arena);
    }
    for (size_t i = 1; i < r->n_trim_bases; ++i) /* insertion sort: few entries */
        for (size_t j = i; j > 0 && r->trim_bases[j - 1] > r->trim_bases[j]; --j) {
            const long tmp = r->trim_bases[j];
            r->trim_bases[j] = r->trim_bases[j - 1];
            r->trim_bases[j - 1] = tmp;
        }
    return PROJCURVE_OK;
}

projcurve_status pc_step_read_geometry(pc_step_file *f, projcurve_model *model)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    reader r = {.f = f, .model = model, .arena = &arena};
    projcurve_status st = collect_trim_bases(&r);
    char name[PC_STEP_MAX_NAME];
    for (size_t i = 0; st == PROJCURVE_OK && i < f->n_instances; ++i) {
        const pc_step_instance *inst = &f->instances[i];
        const size_t n = simple_name(f, inst, name);
        if (n == 0 || interesting(name)) {
            st = read_instance(&r, inst, name);
        } else if (!is_trim_basis(&r, inst->id)) {
            for (size_t k = 0; k < sizeof listed_types / sizeof *listed_types; ++k)
                if (strcmp(name, listed_types[k]) == 0) {
                    st = pc_model_add_skipped(f->ctx, model, "STEP #%ld %s%s", inst->id, name,
                                              strcmp(name, "LINE") == 0 ? " (unbounded)" : "");
                    break;
                }
        }
        pc_arena_release(&arena);
    }
    free(r.trim_bases);
    pc_arena_release(&arena);
    return st;
}

projcurve_status pc_step_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model)
{
    size_t work_done = 0;
    pc_step_file f = {.ctx = ctx, .text = data, .len = len, .work_done = &work_done,
                      .work_limit = PC_STEP_WORK_FACTOR * len + PC_STEP_WORK_MIN};
    projcurve_status st = pc_step_index(&f);
    if (st == PROJCURVE_OK)
        st = pc_step_read_geometry(&f, model);
    if (st == PROJCURVE_OK)
        model->unit = pc_step_length_unit(data, len);
    pc_step_index_free(&f);
    return st;
}
