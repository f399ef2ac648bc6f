/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES analytic surfaces as exact NURBS, through src/analytic/:
 *   108 plane (A x + B y + C z = D): form +-1 over the box of its bounding
 *       curve's control points, form 0 over the square of half width SIZE
 *       (the display symbol's size) around the symbol's point;
 *   118 ruled surface between two curves of one degree and knot count,
 *       polynomial or with equal weights (others are listed as skipped);
 *   120 surface of revolution: the generatrix turned about the axis line
 *       from the start angle to the terminate angle (radians);
 *   122 tabulated cylinder: the directrix swept to the generatrix's
 *       terminate point, v in [0, 1];
 *   190 plane, 192 cylinder, 194 cone (semi-angle in degrees), 196 sphere,
 *   198 torus (the B-rep set of IGES 5.3): the sphere and the torus over
 *       their whole turn; 190, 192, 194 are unbounded and are built over
 *       the box the given points need (pc_analytic_box_covering: a face's
 *       loop points, which the topology reader passes); without points
 *       they are listed as skipped.
 * The NURBS's parameters are those of src/analytic/ (angles in radians,
 * lengths along the axis), and the entity's transformation is applied
 * last (exact: affine maps commute with the rational basis).
 */
#include <math.h>
#include <string.h>

#include "analytic/analytic.h"
#include "common/error.h"
#include "io/iges.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

int pc_iges_is_analytic_surface(int type)
{
    return type == 108 || type == 118 || type == 120 || type == 122 || type == 190 ||
           type == 192 || type == 194 || type == 196 || type == 198;
}

typedef struct ctx_t {
    const pc_iges_file *f;
    const pc_iges_params *p;
    long *uses;
    size_t *n_uses;
} ctx_t;

static void use(ctx_t *c, long de)
{
    if (*c->n_uses < PC_IGES_MAX_USES && de > 0)
        c->uses[(*c->n_uses)++] = de;
}

/* The coordinates of the 116 point or 123 direction entity at pointer i. */
static projcurve_status vector_entity(ctx_t *c, size_t i, int type, double out[3])
{
    long de = 0;
    projcurve_status st = pc_iges_int(c->p, i, &de);
    if (st != PROJCURVE_OK)
        return st;
    const pc_iges_entry *e = pc_iges_entry_at(c->f, de, c->p->de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    if (e->type != type)
        return pc_fail(c->f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: parameter %zu points at entity %d, not %d",
                       c->p->type, c->p->de, i, e->type, type);
    pc_iges_params q;
    if ((st = pc_iges_params_of(c->f, (size_t)de, &q)) != PROJCURVE_OK)
        return st;
    use(c, de);
    return pc_iges_reals(&q, 1, 3, out);
}

/* The curve at pointer i, its transformation applied. */
static projcurve_status curve_at(ctx_t *c, size_t i, pc_io_curve *out, const char **skip)
{
    long de = 0;
    projcurve_status st = pc_iges_int(c->p, i, &de);
    if (st != PROJCURVE_OK)
        return st;
    if (pc_iges_entry_at(c->f, de, c->p->de) == NULL)
        return PROJCURVE_ERR_PARSE;
    use(c, de);
    return pc_iges_curve(c->f, (size_t)de, out, skip);
}

static projcurve_status plane_108(ctx_t *c, pc_analytic_surface *s, double box[4],
                                  const char **skip)
{
    double abcd[4], sym[4];
    long ptr = 0;
    projcurve_status st;
    if ((st = pc_iges_reals(c->p, 1, 4, abcd)) != PROJCURVE_OK || (st = pc_iges_int(c->p, 5, &ptr)) != PROJCURVE_OK ||
        (st = pc_iges_reals(c->p, 6, 4, sym)) != PROJCURVE_OK)
        return st;
    const double n2 = abcd[0] * abcd[0] + abcd[1] * abcd[1] + abcd[2] * abcd[2];
    if (!(n2 > 0.0)) {
        *skip = "a plane with the normal (0, 0, 0)";
        return PROJCURVE_OK;
    }
    const double origin[3] = {abcd[3] * abcd[0] / n2, abcd[3] * abcd[1] / n2, abcd[3] * abcd[2] / n2};
    if ((st = pc_frame_make(c->f->ctx, origin, abcd, NULL, &s->frame)) != PROJCURVE_OK)
        return st;
    s->kind = PC_ANALYTIC_PLANE;
    if (ptr != 0) {
        pc_io_curve k;
        if ((st = curve_at(c, 5, &k, skip)) != PROJCURVE_OK || *skip != NULL) {
            if (*skip != NULL)
                *skip = "its bounding curve is of an unsupported type";
            return st;
        }
        pc_analytic_box_covering(s, k.ctrl, k.n_ctrl, box);
        return PROJCURVE_OK;
    }
    if (!(sym[3] > 0.0)) {
        *skip = "unbounded, without a display size";
        return PROJCURVE_OK;
    }
    double u, v;
    pc_analytic_invert(s, sym, &u, &v);
    box[0] = u - sym[3];
    box[1] = u + sym[3];
    box[2] = v - sym[3];
    box[3] = v + sym[3];
    return PROJCURVE_OK;
}

/* The frame of 192 .. 198: location, axis and (form 1) a reference direction. */
static projcurve_status frame_of(ctx_t *c, size_t loc, size_t axis, size_t ref, int has_ref,
                                 pc_frame *out)
{
    double o[3], z[3] = {0.0, 0.0, 1.0}, x[3];
    projcurve_status st = vector_entity(c, loc, 116, o);
    if (st == PROJCURVE_OK && axis > 0)
        st = vector_entity(c, axis, 123, z);
    if (st == PROJCURVE_OK && has_ref)
        st = vector_entity(c, ref, 123, x);
    if (st != PROJCURVE_OK)
        return st;
    return pc_frame_make(c->f->ctx, o, z, has_ref ? x : NULL, out);
}

/* 190 .. 198; the unbounded 190, 192, 194 need points to cover. */
static projcurve_status elementary(ctx_t *c, int form, pc_analytic_surface *s, const double *points,
                                   size_t n_points, double box[4], const char **skip)
{
    const int ref = form == 1;
    projcurve_status st = PROJCURVE_OK;
    switch (c->p->type) {
    case 190: /* DELOC, DNORM, [DREFD] */
        s->kind = PC_ANALYTIC_PLANE;
        st = frame_of(c, 1, 2, 3, ref, &s->frame);
        break;
    case 192: /* LOCATION, AXIS, RADIUS, [REFDIR] */
        s->kind = PC_ANALYTIC_CYLINDER;
        if ((st = frame_of(c, 1, 2, 4, ref, &s->frame)) == PROJCURVE_OK)
            st = pc_iges_real(c->p, 3, &s->radius);
        break;
    case 194: /* LOCATION, AXIS, RADIUS, SANGLE (degrees), [REFDIR] */
        s->kind = PC_ANALYTIC_CONE;
        if ((st = frame_of(c, 1, 2, 5, ref, &s->frame)) == PROJCURVE_OK &&
            (st = pc_iges_real(c->p, 3, &s->radius)) == PROJCURVE_OK)
            st = pc_iges_real(c->p, 4, &s->semi_angle);
        s->semi_angle *= M_PI / 180.0;
        break;
    case 196: /* LOCATION, RADIUS, [AXIS, REFDIR] */
        s->kind = PC_ANALYTIC_SPHERE;
        if ((st = frame_of(c, 1, ref ? 3 : 0, 4, ref, &s->frame)) == PROJCURVE_OK)
            st = pc_iges_real(c->p, 2, &s->radius);
        break;
    case 198: /* LOCATION, AXIS, MAJRAD, MINRAD, [REFDIR] */
        s->kind = PC_ANALYTIC_TORUS;
        if ((st = frame_of(c, 1, 2, 5, ref, &s->frame)) == PROJCURVE_OK &&
            (st = pc_iges_real(c->p, 3, &s->radius)) == PROJCURVE_OK)
            st = pc_iges_real(c->p, 4, &s->minor_radius);
        break;
    }
    if (st == PROJCURVE_OK && !pc_analytic_box_covering(s, points, n_points, box))
        *skip = "unbounded: built for the faces that bound it";
    return st;
}

static projcurve_status revolution_120(ctx_t *c, pc_analytic_surface *s, pc_io_curve *gen,
                                       double box[4], const char **skip)
{
    pc_io_curve axis;
    projcurve_status st = curve_at(c, 1, &axis, skip);
    if (st != PROJCURVE_OK || *skip != NULL)
        return st;
    double dir[3];
    const double *a0 = axis.ctrl, *a1 = axis.ctrl + 3 * (axis.n_ctrl - 1);
    for (int k = 0; k < 3; ++k)
        dir[k] = a1[k] - a0[k];
    if ((st = pc_frame_make(c->f->ctx, a0, dir, NULL, &s->frame)) != PROJCURVE_OK ||
        (st = curve_at(c, 2, gen, skip)) != PROJCURVE_OK || *skip != NULL ||
        (st = pc_iges_reals(c->p, 3, 2, box)) != PROJCURVE_OK)
        return st;
    s->kind = PC_ANALYTIC_REVOLUTION;
    s->curve = gen;
    return PROJCURVE_OK;
}

static projcurve_status tabulated_122(ctx_t *c, pc_analytic_surface *s, pc_io_curve *dir,
                                      double box[4], const char **skip)
{
    double end[3];
    projcurve_status st = curve_at(c, 1, dir, skip);
    if (st != PROJCURVE_OK || *skip != NULL || (st = pc_iges_reals(c->p, 2, 3, end)) != PROJCURVE_OK)
        return st;
    double start[3];
    pc_rational_curve_eval(dir, dir->knots[dir->degree], start);
    for (int k = 0; k < 3; ++k)
        s->extrusion[k] = end[k] - start[k];
    s->kind = PC_ANALYTIC_EXTRUSION;
    s->curve = dir;
    box[2] = 0.0;
    box[3] = 1.0;
    return PROJCURVE_OK;
}

/* Two curves of one degree and knot count (knots scaled to the first's),
 * polynomial or with equal weights: the tensor product with a line. */
static projcurve_status ruled_118(ctx_t *c, pc_io_surface *out, const char **skip)
{
    pc_io_curve k[2];
    long dirflg = 0;
    projcurve_status st;
    if ((st = curve_at(c, 1, &k[0], skip)) != PROJCURVE_OK || *skip != NULL ||
        (st = curve_at(c, 2, &k[1], skip)) != PROJCURVE_OK || *skip != NULL ||
        (st = pc_iges_int(c->p, 3, &dirflg)) != PROJCURVE_OK)
        return st;
    const size_t n = k[0].n_ctrl, p = (size_t)k[0].degree;
    int same = k[1].n_ctrl == n && k[1].degree == k[0].degree && !k[0].weights == !k[1].weights;
    const double a0 = k[0].knots[p], a1 = k[0].knots[n], b0 = k[1].knots[p], b1 = k[1].knots[n];
    for (size_t i = 0; same && i < n + p + 1; ++i) {
        const size_t j = dirflg == 1 ? n + p - i : i;
        const double ta = (k[0].knots[i] - a0) / (a1 - a0);
        const double tb = (k[1].knots[j] - b0) / (b1 - b0);
        same = fabs(ta - (dirflg == 1 ? 1.0 - tb : tb)) <= 1e-12;
    }
    for (size_t i = 0; same && k[0].weights && i < n; ++i)
        same = k[0].weights[i] == k[1].weights[dirflg == 1 ? n - 1 - i : i];
    if (!same) {
        *skip = "curves of different degrees, knots or weights: not converted";
        return PROJCURVE_OK;
    }
    out->deg_u = k[0].degree;
    out->deg_v = 1;
    out->n_u = n;
    out->n_v = 2;
    out->ctrl = pc_arena_calloc(c->f->arena, 6 * n, sizeof(double));
    out->weights = pc_arena_calloc(c->f->arena, 2 * n, sizeof(double));
    out->knots_u = k[0].knots;
    out->knots_v = pc_arena_calloc(c->f->arena, 4, sizeof(double));
    if (out->ctrl == NULL || out->weights == NULL || out->knots_v == NULL)
        return pc_fail(c->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES entity 118");
    for (size_t i = 0; i < n; ++i) {
        const size_t j = dirflg == 1 ? n - 1 - i : i;
        memcpy(out->ctrl + 3 * i, k[0].ctrl + 3 * i, 3 * sizeof(double));
        memcpy(out->ctrl + 3 * (n + i), k[1].ctrl + 3 * j, 3 * sizeof(double));
        out->weights[i] = out->weights[n + i] = k[0].weights ? k[0].weights[i] : 1.0;
    }
    out->knots_v[2] = out->knots_v[3] = 1.0;
    return PROJCURVE_OK;
}

projcurve_status pc_iges_analytic_surface(const pc_iges_file *f, size_t de, const double *points,
                                          size_t n_points, pc_io_surface *out, const char **kind,
                                          long uses[PC_IGES_MAX_USES], size_t *n_uses,
                                          const char **skip_reason)
{
    *skip_reason = NULL;
    *n_uses = 0;
    pc_iges_params p;
    projcurve_status st = pc_iges_params_of(f, de, &p);
    if (st != PROJCURVE_OK)
        return st;
    const pc_iges_entry *e = pc_iges_entry_at(f, (long)de, de);
    ctx_t c = {f, &p, uses, n_uses};
    pc_analytic_surface s;
    memset(&s, 0, sizeof s);
    pc_io_curve swept;
    double box[4] = {0.0, 0.0, 0.0, 0.0};
    switch (p.type) {
    case 108: st = plane_108(&c, &s, box, skip_reason); break;
    case 118:
        *kind = "ruled";
        st = ruled_118(&c, out, skip_reason);
        break;
    case 120: st = revolution_120(&c, &s, &swept, box, skip_reason); break;
    case 122: st = tabulated_122(&c, &s, &swept, box, skip_reason); break;
    default: st = elementary(&c, e ? e->form : 0, &s, points, n_points, box, skip_reason); break;
    }
    if (st == PROJCURVE_OK && *skip_reason == NULL && p.type != 118) {
        if (p.type == 120 || p.type == 122) { /* the swept curve's whole domain */
            int bounded[2];
            double natural[4] = {0.0, 0.0, 0.0, 0.0};
            pc_analytic_natural_box(&s, natural, bounded);
            const int d = p.type == 120 ? 1 : 0;
            box[2 * d] = natural[2 * d];
            box[2 * d + 1] = natural[2 * d + 1];
        }
        st = pc_analytic_to_nurbs(f->ctx, f->arena, &s, box, out, NULL, NULL);
        *kind = pc_analytic_kind_name(s.kind);
    }
    /* Values that the analytic module refuses (a radius <= 0, a zero axis,
     * a spindle torus, ...) leave the entity unread with the reason. */
    if (st != PROJCURVE_OK && st != PROJCURVE_ERR_PARSE && st != PROJCURVE_ERR_NO_MEMORY) {
        *skip_reason = f->ctx ? projcurve_context_message(f->ctx) : "its values are refused";
        return PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK || *skip_reason != NULL)
        return st;
    pc_io_affine t;
    if ((st = pc_iges_transform(f, de, &t)) != PROJCURVE_OK)
        return st;
    pc_io_affine_points(&t, out->ctrl, out->n_u * out->n_v);
    return PROJCURVE_OK;
}
