/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The geometry instances of a STEP file: CARTESIAN_POINTs, B-spline curves
 * and surfaces (knots as distinct values with multiplicities, the complex
 * rational entity where a weight is not 1), PCURVEs and SURFACE_CURVEs.
 * Every real is written with 17 significant digits (io/text_buf.h), so the
 * file holds the doubles given exactly; a non-finite one is refused before
 * anything is written.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "io/step_write.h"

/* Lines are broken after a separator once they are this long (Part 21
 * sets no limit; short lines keep the file readable and diffable). */
#define PC_STEP_LINE_WIDTH 72

static long next_id(pc_step_out *out)
{
    return out->next_id++;
}

/* A separator ',' and a line break when the line has grown long. */
static void comma(pc_step_out *out)
{
    pc_text_buf_append(&out->data, ",", 1);
    if (out->data.len - out->line_start > PC_STEP_LINE_WIDTH) {
        pc_text_buf_append(&out->data, "\n", 1);
        out->line_start = out->data.len;
    }
}

static void begin(pc_step_out *out, long id, const char *entity)
{
    pc_text_buf_printf(&out->data, "#%ld=%s", id, entity);
}

static void end(pc_step_out *out)
{
    pc_text_buf_append(&out->data, ";\n", 2);
    out->line_start = out->data.len;
}

/* OK, or NO_MEMORY when an append of the instances just formatted failed
 * (the caller rolls the out back to its mark). */
static projcurve_status formatted(projcurve_context *ctx, const pc_step_out *out)
{
    if (out->data.failed)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory formatting STEP");
    return PROJCURVE_OK;
}

static void real(pc_step_out *out, double v)
{
    pc_text_buf_real(&out->data, v);
}

static void ref(pc_step_out *out, long id)
{
    pc_text_buf_printf(&out->data, "#%ld", id);
}

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* ---- curves ------------------------------------------------------------- */

static double pole(const pc_step_spline *c, size_t i, int k)
{
    if (c->homogeneous)
        return c->poles[4 * i + (size_t)k] / c->poles[4 * i + 3];
    return c->poles[(size_t)c->dim * i + (size_t)k];
}

static double weight(const pc_step_spline *c, size_t i)
{
    if (c->homogeneous)
        return c->poles[4 * i + 3];
    return c->weights ? c->weights[i] : 1.0;
}

static int spline_finite(const pc_step_spline *c)
{
    if (!all_finite(c->knots, c->n_poles + (size_t)c->degree + 1))
        return 0;
    for (size_t i = 0; i < c->n_poles; ++i) {
        if (!isfinite(weight(c, i)))
            return 0;
        for (int k = 0; k < c->dim; ++k)
            if (!isfinite(pole(c, i, k)))
                return 0;
    }
    return 1;
}

static int spline_rational(const pc_step_spline *c)
{
    for (size_t i = 0; i < c->n_poles; ++i)
        if (weight(c, i) != 1.0)
            return 1;
    return 0;
}

/* A knot vector's multiplicities (mults) or distinct values, as a list:
 * exact equality groups them, so a reader's expansion of the two lists
 * gives the same vector. */
static void knot_list(pc_step_out *out, const double *u, size_t n, int mults)
{
    pc_text_buf_append(&out->data, "(", 1);
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && u[j] == u[i])
            ++j;
        if (i > 0)
            comma(out);
        if (mults)
            pc_text_buf_printf(&out->data, "%zu", j - i);
        else
            real(out, u[i]);
        i = j;
    }
    pc_text_buf_append(&out->data, ")", 1);
}

static void knots(pc_step_out *out, const double *u, size_t n)
{
    knot_list(out, u, n, 1);
    pc_text_buf_append(&out->data, ",", 1);
    knot_list(out, u, n, 0);
}

/* The points of a curve, numbered from first. */
static void curve_points(pc_step_out *out, const pc_step_spline *c, long first)
{
    for (size_t i = 0; i < c->n_poles; ++i) {
        begin(out, first + (long)i, "CARTESIAN_POINT('',(");
        for (int k = 0; k < c->dim; ++k) {
            if (k > 0)
                pc_text_buf_append(&out->data, ",", 1);
            real(out, pole(c, i, k));
        }
        pc_text_buf_append(&out->data, "))", 2);
        end(out);
    }
}

static void point_list(pc_step_out *out, long first, size_t n)
{
    pc_text_buf_append(&out->data, "(", 1);
    for (size_t i = 0; i < n; ++i) {
        if (i > 0)
            comma(out);
        ref(out, first + (long)i);
    }
    pc_text_buf_append(&out->data, ")", 1);
}

projcurve_status pc_step_out_curve(projcurve_context *ctx, pc_step_out *out,
                                   const pc_step_spline *c, long *id)
{
    if (!spline_finite(c))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                       "a curve to write as STEP has a knot, pole or weight that is not finite");
    const long first = out->next_id;
    out->next_id += (long)c->n_poles;
    curve_points(out, c, first);
    *id = next_id(out);
    const size_t n_knots = c->n_poles + (size_t)c->degree + 1;
    /* closed_curve: the ends coincide exactly; self_intersect unknown */
    int closed = c->n_poles > 1;
    for (int k = 0; closed && k < c->dim; ++k)
        closed = pole(c, 0, k) == pole(c, c->n_poles - 1, k);
    const char *flags = closed ? ".UNSPECIFIED.,.T.,.U." : ".UNSPECIFIED.,.F.,.U.";
    if (!spline_rational(c)) {
        begin(out, *id, "B_SPLINE_CURVE_WITH_KNOTS('',");
        pc_text_buf_printf(&out->data, "%d,", c->degree);
        point_list(out, first, c->n_poles);
        pc_text_buf_append(&out->data, ",", 1);
        pc_text_buf_puts(&out->data, flags);
        pc_text_buf_append(&out->data, ",", 1);
        knots(out, c->knots, n_knots);
        pc_text_buf_puts(&out->data, ",.UNSPECIFIED.)");
    } else {
        begin(out, *id, "(BOUNDED_CURVE()\nB_SPLINE_CURVE(");
        out->line_start = out->data.len;
        pc_text_buf_printf(&out->data, "%d,", c->degree);
        point_list(out, first, c->n_poles);
        pc_text_buf_append(&out->data, ",", 1);
        pc_text_buf_puts(&out->data, flags);
        pc_text_buf_puts(&out->data, ")\nB_SPLINE_CURVE_WITH_KNOTS(");
        out->line_start = out->data.len;
        knots(out, c->knots, n_knots);
        pc_text_buf_puts(&out->data, ",.UNSPECIFIED.)\nCURVE() GEOMETRIC_REPRESENTATION_ITEM()\n"
                                     "RATIONAL_B_SPLINE_CURVE((");
        out->line_start = out->data.len;
        for (size_t i = 0; i < c->n_poles; ++i) {
            if (i > 0)
                comma(out);
            real(out, weight(c, i));
        }
        pc_text_buf_puts(&out->data, "))\nREPRESENTATION_ITEM(''))");
    }
    end(out);
    return formatted(ctx, out);
}

/* ---- surfaces ----------------------------------------------------------- */

/* The surface's data as exact text (hexadecimal reals), its identity. */
static char *surface_key(const pc_nurbs_surface *s)
{
    pc_text_buf b = {0};
    pc_text_buf_printf(&b, "%d %d %zu %zu", s->deg_u, s->deg_v, s->n_u, s->n_v);
    const size_t nu = s->n_u + (size_t)s->deg_u + 1, nv = s->n_v + (size_t)s->deg_v + 1;
    for (size_t i = 0; i < nu; ++i)
        pc_text_buf_printf(&b, " %a", s->knots_u[i]);
    for (size_t i = 0; i < nv; ++i)
        pc_text_buf_printf(&b, " %a", s->knots_v[i]);
    for (size_t i = 0; i < 4 * s->n_u * s->n_v; ++i)
        pc_text_buf_printf(&b, " %a", s->cw[i]);
    if (b.failed) {
        pc_text_buf_free(&b);
        return NULL;
    }
    return b.text;
}

static int surface_rational(const pc_nurbs_surface *s)
{
    for (size_t i = 0; i < s->n_u * s->n_v; ++i)
        if (s->cw[4 * i + 3] != 1.0)
            return 1;
    return 0;
}

/* Points P(i, j) (u index i fastest in storage) numbered row by row of
 * the STEP list of lists, whose outer index is u: #first + i n_v + j. */
static void surface_points(pc_step_out *out, const pc_nurbs_surface *s, long first)
{
    for (size_t i = 0; i < s->n_u; ++i)
        for (size_t j = 0; j < s->n_v; ++j) {
            const double *h = s->cw + 4 * (j * s->n_u + i);
            begin(out, first + (long)(i * s->n_v + j), "CARTESIAN_POINT('',(");
            for (int k = 0; k < 3; ++k) {
                if (k > 0)
                    pc_text_buf_append(&out->data, ",", 1);
                real(out, h[k] / h[3]);
            }
            pc_text_buf_append(&out->data, "))", 2);
            end(out);
        }
}

static void surface_net(pc_step_out *out, const pc_nurbs_surface *s, long first)
{
    pc_text_buf_append(&out->data, "(", 1);
    for (size_t i = 0; i < s->n_u; ++i) {
        if (i > 0)
            comma(out);
        point_list(out, first + (long)(i * s->n_v), s->n_v);
    }
    pc_text_buf_append(&out->data, ")", 1);
}

static void surface_weights(pc_step_out *out, const pc_nurbs_surface *s)
{
    pc_text_buf_append(&out->data, "(", 1);
    for (size_t i = 0; i < s->n_u; ++i) {
        pc_text_buf_append(&out->data, i > 0 ? ",(" : "(", i > 0 ? 2 : 1);
        for (size_t j = 0; j < s->n_v; ++j) {
            if (j > 0)
                comma(out);
            real(out, s->cw[4 * (j * s->n_u + i) + 3]);
        }
        pc_text_buf_append(&out->data, ")", 1);
    }
    pc_text_buf_append(&out->data, ")", 1);
}

static void surface_entity(pc_step_out *out, const pc_nurbs_surface *s, long first, long id)
{
    const size_t nu = s->n_u + (size_t)s->deg_u + 1, nv = s->n_v + (size_t)s->deg_v + 1;
    const int rational = surface_rational(s);
    begin(out, id, rational ? "(BOUNDED_SURFACE()\nB_SPLINE_SURFACE("
                            : "B_SPLINE_SURFACE_WITH_KNOTS('',");
    if (rational)
        out->line_start = out->data.len;
    pc_text_buf_printf(&out->data, "%d,%d,", s->deg_u, s->deg_v);
    surface_net(out, s, first);
    pc_text_buf_puts(&out->data, ",.UNSPECIFIED.,.F.,.F.,.U.");
    pc_text_buf_puts(&out->data, rational ? ")\nB_SPLINE_SURFACE_WITH_KNOTS(" : ",");
    if (rational)
        out->line_start = out->data.len;
    /* (u multiplicities),(v multiplicities),(u knots),(v knots) */
    knot_list(out, s->knots_u, nu, 1);
    comma(out);
    knot_list(out, s->knots_v, nv, 1);
    comma(out);
    knot_list(out, s->knots_u, nu, 0);
    comma(out);
    knot_list(out, s->knots_v, nv, 0);
    pc_text_buf_puts(&out->data, ",.UNSPECIFIED.)");
    if (rational) {
        pc_text_buf_puts(&out->data, "\nGEOMETRIC_REPRESENTATION_ITEM()\nRATIONAL_B_SPLINE_SURFACE(");
        out->line_start = out->data.len;
        surface_weights(out, s);
        pc_text_buf_puts(&out->data, ")\nREPRESENTATION_ITEM('') SURFACE())");
    }
    end(out);
}

projcurve_status pc_step_out_surface(projcurve_context *ctx, pc_step_out *out,
                                     const pc_nurbs_surface *s, long *id)
{
    const size_t nu = s->n_u + (size_t)s->deg_u + 1, nv = s->n_v + (size_t)s->deg_v + 1;
    if (!all_finite(s->knots_u, nu) || !all_finite(s->knots_v, nv) ||
        !all_finite(s->cw, 4 * s->n_u * s->n_v))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                       "a surface to write as STEP has a knot, pole or weight that is not "
                       "finite");
    char *key = surface_key(s);
    if (key == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing a STEP surface");
    for (size_t i = 0; i < out->surfaces.count; ++i)
        if (strcmp(out->surfaces.items[i].key, key) == 0) {
            free(key);
            *id = out->surfaces.items[i].id;
            return PROJCURVE_OK;
        }
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, &out->surfaces, out->surfaces.count + 1, 8,
                     "the written STEP surfaces");
    if (st != PROJCURVE_OK) {
        free(key);
        return st;
    }
    const long first = out->next_id;
    out->next_id += (long)(s->n_u * s->n_v);
    surface_points(out, s, first);
    *id = next_id(out);
    surface_entity(out, s, first, *id);
    out->surfaces.items[out->surfaces.count++] = (pc_step_surface_key){.id = *id, .key = key};
    if ((st = formatted(ctx, out)) != PROJCURVE_OK)
        return st;
    return pc_step_out_add_to_set(ctx, out, *id);
}

/* ---- curves on surfaces -------------------------------------------------- */

projcurve_status pc_step_out_pcurve(projcurve_context *ctx, pc_step_out *out, long surface,
                                    long curve2d, long *id)
{
    const long rep = next_id(out);
    begin(out, rep, "DEFINITIONAL_REPRESENTATION('',(");
    ref(out, curve2d);
    pc_text_buf_printf(&out->data, "),#%ld)", PC_STEP_PARAMETRIC_CONTEXT_ID);
    end(out);
    *id = next_id(out);
    begin(out, *id, "PCURVE('',");
    pc_text_buf_printf(&out->data, "#%ld,#%ld)", surface, rep);
    end(out);
    out->has_pcurves = 1;
    return formatted(ctx, out);
}

projcurve_status pc_step_out_surface_curve(projcurve_context *ctx, pc_step_out *out,
                                           long curve3d, long pcurve, long *id)
{
    *id = next_id(out);
    begin(out, *id, "SURFACE_CURVE('',");
    pc_text_buf_printf(&out->data, "#%ld,(#%ld),.PCURVE_S1.)", curve3d, pcurve);
    end(out);
    return formatted(ctx, out);
}

/* ---- composite curves ------------------------------------------------------ */

projcurve_status pc_step_out_composite_curve(projcurve_context *ctx, pc_step_out *out,
                                             const pc_step_segment *segments, size_t n,
                                             long *id)
{
    const long first = out->next_id;
    out->next_id += (long)n;
    for (size_t k = 0; k < n; ++k) {
        begin(out, first + (long)k, "COMPOSITE_CURVE_SEGMENT(");
        pc_text_buf_printf(&out->data, "%s,%s,#%ld)",
                           segments[k].continuous ? ".CONTINUOUS." : ".DISCONTINUOUS.",
                           segments[k].same_sense ? ".T." : ".F.", segments[k].curve);
        end(out);
    }
    *id = next_id(out);
    begin(out, *id, "COMPOSITE_CURVE('',(");
    for (size_t k = 0; k < n; ++k) {
        if (k > 0)
            comma(out);
        ref(out, first + (long)k);
    }
    pc_text_buf_puts(&out->data, "),.U.)");
    end(out);
    return formatted(ctx, out);
}
