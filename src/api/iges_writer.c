/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public IGES writer: surfaces (128), curves (126) and projection results,
 * each composed branch as its 3D curve (126), its (u, v) pcurve (126 in the
 * plane z = 0) and a curve on surface (142, "projection of a curve onto the
 * surface") tying them to the surface. The compact forms by default (fit/:
 * S composed with the pcurve and the 3D curve are each within eps_D of the
 * projection); on request the pieces (their pcurves joined, so that S
 * composed with it is the 3D curve exactly). The traced points as a
 * polyline for a branch not composed. A surface is written once however
 * often it is added (entities are compared by their parameter text, i.e.
 * exactly). A whole-shape result as one composite curve (102) per
 * connected curve, its members the face pieces' 3D curves.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/branch_pcurve.h"
#include "api/result_surface.h"
#include "api/shape_member.h"
#include "common/error.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "io/iges.h"
#include "io/iges_write.h"
#include "io/seam_split.h"
#include "nurbs/input.h"
#include "trace/result.h"

#define PC_IGES_CURVE_ON_SURFACE 142
#define PC_IGES_COS_PROJECTION 1 /* CRTN: created as a projection */
#define PC_IGES_COS_PREFER_BOTH 3 /* PREF: S o pcurve and the 3D curve are the same curve */
#define PC_IGES_COS_PREFER_2D 1   /* only the pcurve (traced points, not composed) */

struct projcurve_iges_writer {
    pc_iges_out out;
};

projcurve_status projcurve_iges_writer_create(projcurve_context *ctx,
                                              projcurve_iges_writer **out)
{
    PC_REQUIRE(ctx, out, "out");
    projcurve_iges_writer *w = calloc(1, sizeof *w);
    if (w == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating an IGES writer");
    *out = w;
    return PROJCURVE_OK;
}

void projcurve_iges_writer_destroy(projcurve_iges_writer *writer)
{
    if (writer == NULL)
        return;
    pc_iges_out_free(&writer->out);
    free(writer);
}

/* Adds entity 128 unless an identical one is there; *de gets its pointer. */
static projcurve_status add_surface(projcurve_context *ctx, projcurve_iges_writer *w,
                                    const projcurve_surface *s, size_t *de)
{
    pc_text_buf b = {0};
    pc_iges_format_surface(&b, &s->nurbs);
    if (b.failed) {
        free(b.text);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory formatting a surface");
    }
    for (size_t i = 0; i < w->out.count; ++i)
        if (w->out.entities[i].type == 128 && strcmp(w->out.entities[i].params, b.text) == 0) {
            free(b.text);
            *de = 2 * i + 1;
            return PROJCURVE_OK;
        }
    const projcurve_status st =
        pc_iges_out_add(ctx, &w->out, 128, 0, PC_IGES_STATUS_INDEPENDENT, &b, de);
    free(b.text);
    return st;
}

projcurve_status projcurve_iges_writer_add_surface(projcurve_context *ctx,
                                                   projcurve_iges_writer *w,
                                                   const projcurve_surface *s)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    size_t de;
    return add_surface(ctx, w, s, &de);
}

static projcurve_status add_curve(projcurve_context *ctx, projcurve_iges_writer *w,
                                  const projcurve_curve *c, const char *status, size_t *de)
{
    if (c->kind != PC_CURVE_NURBS)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND,
                       "a callback curve has no NURBS form to write");
    pc_text_buf b = {0};
    pc_iges_format_curve(&b, &c->nurbs, 0);
    const projcurve_status st = pc_iges_out_add(ctx, &w->out, 126, 0, status, &b, de);
    free(b.text);
    return st;
}

projcurve_status projcurve_iges_writer_add_curve(projcurve_context *ctx,
                                                 projcurve_iges_writer *w,
                                                 const projcurve_curve *c)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, c, "curve");
    size_t de;
    return add_curve(ctx, w, c, PC_IGES_STATUS_INDEPENDENT, &de);
}

/* The branch's traced (u, v) points as a degree-1 pcurve in z = 0,
 * parametrised by the curve parameter t (repeated t values dropped). */
static projcurve_status add_traced_pcurve(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const projcurve_result *r, size_t branch, size_t *de)
{
    size_t n = 0;
    double probe[3];
    projcurve_status st = projcurve_result_branch_points(ctx, r, branch, 0, probe, &n);
    if (st != PROJCURVE_OK)
        return st;
    if (n < 2) {
        *de = 0;
        return PROJCURVE_OK;
    }
    double *tuv = malloc(3 * n * sizeof *tuv);
    double *xyz = malloc(3 * n * sizeof *xyz);
    double *t = malloc(n * sizeof *t);
    if (tuv == NULL || xyz == NULL || t == NULL) {
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing a pcurve");
        goto cleanup;
    }
    size_t got = 0;
    if ((st = projcurve_result_branch_points(ctx, r, branch, n, tuv, &got)) != PROJCURVE_OK)
        goto cleanup;
    /* Branches may be traced with t decreasing: keep t increasing. */
    const int reversed = tuv[0] > tuv[3 * (got - 1)];
    size_t m = 0;
    for (size_t k = 0; k < got; ++k) {
        const size_t i = reversed ? got - 1 - k : k;
        if (m > 0 && !(tuv[3 * i] > t[m - 1]))
            continue;
        t[m] = tuv[3 * i];
        xyz[3 * m] = tuv[3 * i + 1];
        xyz[3 * m + 1] = tuv[3 * i + 2];
        xyz[3 * m + 2] = 0.0;
        ++m;
    }
    *de = 0;
    if (m >= 2) {
        pc_text_buf b = {0};
        pc_iges_format_polyline(&b, xyz, t, m, 1);
        st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &b, de);
        free(b.text);
    }
cleanup:
    free(tuv);
    free(xyz);
    free(t);
    return st;
}

/* Entity 142 tying the pcurve and 3D curve (DE pointers, 0 for none) to
 * the surface. */
static projcurve_status add_curve_on_surface(projcurve_context *ctx, projcurve_iges_writer *w,
                                             size_t surface_de, size_t pcurve_de,
                                             size_t curve_de)
{
    pc_text_buf b = {0};
    pc_iges_param_int(&b, PC_IGES_COS_PROJECTION);
    pc_iges_param_int(&b, (long long)surface_de);
    pc_iges_param_int(&b, (long long)pcurve_de);
    pc_iges_param_int(&b, (long long)curve_de);
    pc_iges_param_int(&b, curve_de ? PC_IGES_COS_PREFER_BOTH : PC_IGES_COS_PREFER_2D);
    pc_iges_param_end(&b);
    size_t de;
    const projcurve_status st = pc_iges_out_add(ctx, &w->out, PC_IGES_CURVE_ON_SURFACE, 0,
                                                PC_IGES_STATUS_INDEPENDENT, &b, &de);
    free(b.text);
    return st;
}

/* The traced points of a branch joined across seams that was not composed:
 * one degree-1 pcurve and one 142 (CPTR 0) per run between jumps (a jump
 * is a vertex repeated at the same t, on the other side of the seam), so
 * that no edge of the polyline runs through the domain from one side of
 * the seam to the other. */
static projcurve_status add_traced_runs(projcurve_context *ctx, projcurve_iges_writer *w,
                                        size_t surface_de, const projcurve_result *r,
                                        size_t branch)
{
    const pc_branch *b = &r->branches[branch];
    const size_t n = b->n_points;
    double *xyz = malloc(3 * (n + 1) * sizeof *xyz), *t = malloc((n + 1) * sizeof *t);
    projcurve_status st = PROJCURVE_OK;
    if (xyz == NULL || t == NULL)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing a pcurve");
    const int reversed = n > 1 && b->points[0] > b->points[3 * (n - 1)];
    size_t m = 0;
    for (size_t k = 0; st == PROJCURVE_OK && k <= n; ++k) {
        const size_t i = reversed ? n - 1 - k : k;
        const int jump = k < n && m > 0 && !(b->points[3 * i] > t[m - 1]);
        if (k == n || jump) { /* the run so far is done */
            if (m >= 2) {
                size_t pcurve_de = 0;
                pc_text_buf buf = {0};
                pc_iges_format_polyline(&buf, xyz, t, m, 1);
                st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &buf,
                                     &pcurve_de);
                free(buf.text);
                if (st == PROJCURVE_OK)
                    st = add_curve_on_surface(ctx, w, surface_de, pcurve_de, 0);
            }
            m = 0;
            if (k == n)
                break;
        }
        t[m] = b->points[3 * i];
        xyz[3 * m] = b->points[3 * i + 1];
        xyz[3 * m + 1] = b->points[3 * i + 2];
        xyz[3 * m + 2] = 0.0;
        ++m;
    }
    free(xyz);
    free(t);
    return st;
}

/* A branch over a t range narrower than a curve's domain may be
 * (nurbs/input.h: a sliver of the curve) has pieces but no curve handle of
 * its own: it is written as its traced pcurve, as a branch not composed. */
static int branch_forms_curve(const projcurve_result *r, size_t branch)
{
    double t[2] = {0.0, 0.0};
    if (projcurve_result_branch_info(NULL, r, branch, t, NULL, NULL, NULL, NULL) != PROJCURVE_OK)
        return 0;
    return pc_input_check_domain(NULL, "branch", fmin(t[0], t[1]), fmax(t[0], t[1])) ==
           PROJCURVE_OK;
}

/* The pcurve of a composed branch: the compact one, or the pieces' joined;
 * INVALID_ARGUMENT when it has neither. */
static projcurve_status branch_pcurve(projcurve_context *ctx, const projcurve_result *r,
                                      size_t branch, int compact, projcurve_curve **q)
{
    projcurve_status st = PROJCURVE_ERR_INVALID_ARGUMENT;
    if (compact) /* without ctx: a missing compact form is no failure here */
        st = projcurve_result_branch_compact_pcurve(NULL, r, branch, q);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(ctx, st, "out of memory for the compact pcurve of branch %zu", branch);
    if (st == PROJCURVE_ERR_INVALID_ARGUMENT) /* no compact forms: the pieces' */
        st = pc_branch_pcurve(ctx, r, branch, q);
    return st;
}

/* The pcurve of a composed branch (compact, or its pieces' (u, v) curves
 * joined), or of one that is not composed (its traced points). */
static projcurve_status add_pcurve(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const projcurve_result *r, size_t branch, int compact,
                                   size_t *de)
{
    if (!branch_forms_curve(r, branch))
        return add_traced_pcurve(ctx, w, r, branch, de);
    projcurve_curve *pcurve = NULL;
    projcurve_status st = branch_pcurve(ctx, r, branch, compact, &pcurve);
    if (st == PROJCURVE_ERR_INVALID_ARGUMENT)
        return add_traced_pcurve(ctx, w, r, branch, de);
    if (st != PROJCURVE_OK)
        return st;
    pc_text_buf b = {0};
    pc_iges_format_curve(&b, &pcurve->nurbs, 1);
    st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &b, de);
    free(b.text);
    projcurve_curve_destroy(pcurve);
    return st;
}

/* A composed branch joined across seams (docs/seams.md): one 142 per seam
 * segment, each pcurve in the domain (io/seam_split.h). */
static projcurve_status add_seam_segments(projcurve_context *ctx, projcurve_iges_writer *w,
                                          const projcurve_surface *s, size_t surface_de,
                                          const projcurve_result *r, size_t branch,
                                          int compact)
{
    const pc_branch *b = &r->branches[branch];
    projcurve_curve *q = NULL, *c = NULL;
    projcurve_status st = branch_pcurve(ctx, r, branch, compact, &q);
    if (st == PROJCURVE_OK)
        st = pc_branch_curve3d(ctx, r, branch, compact, &c);
    pc_seam_segment *seg = NULL;
    size_t n_seg = 0;
    if (st == PROJCURVE_OK)
        st = pc_seam_split(ctx, &q->nurbs, &c->nurbs, b->seams, b->n_seams, s->nurbs.domain,
                           &seg, &n_seg);
    for (size_t k = 0; st == PROJCURVE_OK && k < n_seg; ++k) {
        size_t pcurve_de = 0, curve_de = 0;
        pc_text_buf t = {0};
        pc_iges_format_curve(&t, &seg[k].pcurve, 1);
        st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &t,
                             &pcurve_de);
        free(t.text);
        if (st != PROJCURVE_OK)
            break;
        pc_text_buf u = {0};
        pc_iges_format_curve(&u, &seg[k].curve, 0);
        st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PART, &u, &curve_de);
        free(u.text);
        if (st == PROJCURVE_OK)
            st = add_curve_on_surface(ctx, w, surface_de, pcurve_de, curve_de);
    }
    pc_seam_segments_free(seg, n_seg);
    projcurve_curve_destroy(q);
    projcurve_curve_destroy(c);
    return st;
}

static projcurve_status add_branch(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const projcurve_surface *s, size_t surface_de,
                                   const projcurve_result *r, size_t branch, int compact)
{
    if (r->branches[branch].n_seams > 0) {
        projcurve_curve *probe = NULL;
        if (branch_forms_curve(r, branch) &&
            branch_pcurve(NULL, r, branch, compact, &probe) == PROJCURVE_OK) {
            projcurve_curve_destroy(probe);
            return add_seam_segments(ctx, w, s, surface_de, r, branch, compact);
        }
        return add_traced_runs(ctx, w, surface_de, r, branch);
    }
    size_t pcurve_de = 0, curve_de = 0;
    projcurve_status st = add_pcurve(ctx, w, r, branch, compact, &pcurve_de);
    if (st != PROJCURVE_OK)
        return st;
    projcurve_curve *c = NULL;
    st = PROJCURVE_ERR_INVALID_ARGUMENT; /* a sliver: the traced pcurve alone */
    if (branch_forms_curve(r, branch))
        st = pc_branch_curve3d(ctx, r, branch, compact, &c);
    if (st == PROJCURVE_OK) {
        st = add_curve(ctx, w, c, PC_IGES_STATUS_PART, &curve_de);
        projcurve_curve_destroy(c);
    } else if (st == PROJCURVE_ERR_INVALID_ARGUMENT) {
        st = PROJCURVE_OK; /* not composed: the pcurve alone describes it */
    }
    if (st != PROJCURVE_OK || (pcurve_de == 0 && curve_de == 0))
        return st;
    return add_curve_on_surface(ctx, w, surface_de, pcurve_de, curve_de);
}

static projcurve_status add_result(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const projcurve_surface *s, const projcurve_result *r,
                                   int compact)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    PC_REQUIRE(ctx, r, "result");
    if (projcurve_result_point_dim(r) != 3)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "the result is not on a parametric surface (implicit projection)");
    projcurve_status st = pc_result_check_surface(ctx, r, s);
    if (st != PROJCURVE_OK)
        return st;
    /* All or nothing: a failure (memory) part of the way leaves the writer
     * as it was, not with half a result in it. */
    const size_t before = w->out.count;
    size_t surface_de;
    st = add_surface(ctx, w, s, &surface_de);
    const size_t n = projcurve_result_branch_count(r);
    for (size_t b = 0; st == PROJCURVE_OK && b < n; ++b)
        st = add_branch(ctx, w, s, surface_de, r, b, compact);
    if (st != PROJCURVE_OK)
        pc_iges_out_truncate(&w->out, before);
    return st;
}

projcurve_status projcurve_iges_writer_add_result(projcurve_context *ctx,
                                                  projcurve_iges_writer *w,
                                                  const projcurve_surface *s,
                                                  const projcurve_result *r)
{
    return add_result(ctx, w, s, r, 1);
}

projcurve_status projcurve_iges_writer_add_result_pieces(projcurve_context *ctx,
                                                         projcurve_iges_writer *w,
                                                         const projcurve_surface *s,
                                                         const projcurve_result *r)
{
    return add_result(ctx, w, s, r, 0);
}

/* One member of a composite: the piece's 3D curve (126, physically
 * dependent), run backwards where the chain runs along it with t
 * decreasing. */
static projcurve_status add_member(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const pc_shape_member *m, size_t *de)
{
    pc_text_buf b = {0};
    if (m->forward)
        pc_iges_format_curve(&b, &m->curve->nurbs, 0);
    else
        pc_iges_format_curve_reversed(&b, &m->curve->nurbs, 0);
    const projcurve_status st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PART, &b, de);
    free(b.text);
    return st;
}

/* Connected curve `curve` of r: its pieces' 3D curves in chain order, then
 * the 102 over them. */
static projcurve_status add_connected_curve(projcurve_context *ctx, projcurve_iges_writer *w,
                                            const projcurve_shape_result *r, size_t curve)
{
    size_t n = 0;
    projcurve_status st = projcurve_shape_result_curve_info(ctx, r, curve, &n, NULL, NULL);
    if (st != PROJCURVE_OK || n == 0)
        return st;
    size_t *members = malloc(n * sizeof *members);
    if (members == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                       "out of memory for the %zu members of connected curve %zu", n, curve);
    for (size_t k = 0; st == PROJCURVE_OK && k < n; ++k) {
        pc_shape_member m;
        st = pc_shape_member_get(ctx, r, curve, k, &m);
        if (st == PROJCURVE_OK)
            st = add_member(ctx, w, &m, &members[k]);
        pc_shape_member_free(&m);
    }
    if (st == PROJCURVE_OK) {
        pc_text_buf b = {0};
        pc_iges_format_composite(&b, members, n);
        size_t de;
        st = pc_iges_out_add(ctx, &w->out, 102, 0, PC_IGES_STATUS_INDEPENDENT, &b, &de);
        free(b.text);
    }
    free(members);
    return st;
}

projcurve_status projcurve_iges_writer_add_shape_result(projcurve_context *ctx,
                                                        projcurve_iges_writer *w,
                                                        const projcurve_shape_result *r)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, r, "shape result");
    const size_t before = w->out.count; /* all or nothing, as add_result */
    projcurve_status st = PROJCURVE_OK;
    const size_t n = projcurve_shape_result_curve_count(r);
    for (size_t c = 0; st == PROJCURVE_OK && c < n; ++c)
        st = add_connected_curve(ctx, w, r, c);
    if (st != PROJCURVE_OK)
        pc_iges_out_truncate(&w->out, before);
    return st;
}

projcurve_status projcurve_iges_writer_set_length_unit(projcurve_context *ctx,
                                                       projcurve_iges_writer *w,
                                                       double metres_per_unit)
{
    PC_REQUIRE(ctx, w, "writer");
    if (!isfinite(metres_per_unit))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "length unit is not finite");
    const int flag = pc_iges_unit_flag(metres_per_unit);
    if (flag == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "length unit %.17g m is none of the IGES units (in, mm, ft, mi, m, km, "
                       "mil, um, cm, uin)",
                       metres_per_unit);
    w->out.unit_flag = flag;
    return PROJCURVE_OK;
}

projcurve_status projcurve_iges_writer_write(projcurve_context *ctx,
                                             const projcurve_iges_writer *w, const char *path)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, path, "path");
    return pc_iges_out_write(ctx, &w->out, path);
}
