/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tracks of the face pieces and the parts rebuilt from their kept spans
 * (shapeproj/hits_part.h).
 */
#include "shapeproj/hits_part.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "faceproj/piece_cut.h"
#include "seam/seam.h"

/* Smallest part of a composed piece kept, in its s: below it, a point. */
#define PC_HITS_PART_MIN_S 1e-12

projcurve_status pc_track_set_build(projcurve_context *ctx, const projcurve_shape_result *r,
                                    const projcurve_curve *curve,
                                    const pc_projection_spec *spec, const pc_params *p,
                                    pc_track_set *out)
{
    *out = (pc_track_set){0};
    const pc_surface_projection *kind = NULL;
    projcurve_status st = pc_surface_projection_get(ctx, spec->kind, &kind);
    if (st != PROJCURVE_OK)
        return st;
    size_t n = 0;
    for (size_t i = 0; i < r->n_parts; ++i)
        n += r->parts[i].result ? r->parts[i].result->n_branches : 0;
    out->tracks = malloc((n + 1) * sizeof *out->tracks);
    out->projs = malloc((r->n_parts + 1) * sizeof *out->projs);
    out->storage = malloc((r->n_parts + 1) * sizeof *out->storage);
    if (out->tracks == NULL || out->projs == NULL || out->storage == NULL) {
        pc_track_set_free(out);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the nearest hits");
    }
    for (size_t i = 0; i < r->n_parts; ++i) {
        const pc_face_part *part = &r->parts[i];
        if (part->result == NULL)
            continue;
        const projcurve_surface *s = part->f->surface;
        kind->projector_init(&out->projs[i], &out->storage[i], s, curve, spec, p);
        const double *d = s->nurbs.domain;
        for (size_t b = 0; b < part->result->n_branches; ++b) {
            const pc_branch *br = &part->result->branches[b];
            pc_track *k = &out->tracks[out->n_tracks++];
            *k = (pc_track){.part = i, .branch = b, .b = br, .proj = &out->projs[i],
                            .jump_u = 0.5 * (d[1] - d[0]), .jump_v = 0.5 * (d[3] - d[2]),
                            .whole = br->n_points < 2};
            const double first = br->n_points > 0 ? br->points[0] : 0.0;
            const double last = br->n_points > 0 ? br->points[3 * (br->n_points - 1)] : 0.0;
            k->whole = k->whole || !(last > first);
            k->lo = fmin(first, last);
            k->hi = fmax(first, last);
        }
    }
    return PROJCURVE_OK;
}

void pc_track_set_free(pc_track_set *set)
{
    free(set->tracks);
    free(set->projs);
    free(set->storage);
    *set = (pc_track_set){0};
}

projcurve_status pc_span_push(projcurve_context *ctx, pc_span_list *l, size_t track, double s,
                              double e, double min_len)
{
    if (!(e - s > min_len))
        return PROJCURVE_OK; /* the rounding of a tie on an edge: no curve */
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, l, l->count + 1, 16, "the kept spans of the face pieces");
    if (st == PROJCURVE_OK)
        l->items[l->count++] = (pc_span){track, s, e};
    return st;
}

projcurve_status pc_track_distance(const pc_track *k, double t, double uv[2], double *out)
{
    const pc_branch *b = k->b;
    const size_t j = pc_branch_segment_at(b, t);
    const double *a = b->points + 3 * j, *c = a + 3;
    const double *near = t - a[0] <= c[0] - t ? a : c;
    uv[0] = near[1];
    uv[1] = near[2];
    if (t != a[0] && t != c[0]) {
        /* the linear guess, or the nearer vertex where the segment jumps
         * across a seam (its ends a period apart) */
        const int jump = fabs(c[1] - a[1]) > k->jump_u || fabs(c[2] - a[2]) > k->jump_v;
        const double w = c[0] > a[0] ? (t - a[0]) / (c[0] - a[0]) : 0.0;
        double g[2] = {a[1] + w * (c[1] - a[1]), a[2] + w * (c[2] - a[2])};
        if (jump) {
            g[0] = near[1];
            g[1] = near[2];
        }
        if (k->proj->correct(k->proj, t, g, NULL)) {
            uv[0] = g[0];
            uv[1] = g[1];
        }
    }
    pc_vec3 s, p;
    pc_nurbs_surface_eval(&k->proj->surface->nurbs, uv[0], uv[1], 0, NULL, NULL, &s);
    const projcurve_status st = pc_curve_eval(k->proj->curve, t, 0, NULL, &p);
    if (st != PROJCURVE_OK)
        return st;
    *out = vec3_norm(vec3_sub(s, p));
    return PROJCURVE_OK;
}

typedef struct trim_list {
    pc_branch_trim *items;
    size_t count, capacity;
} trim_list;

/* s on piece q at its end t: 0 / 1 at the piece's own ends, else the
 * pcurve's point nearest the cut point uv. */
static double piece_s(const pc_piece *q, double t, const double uv[2])
{
    if (t == q->t0)
        return 0.0;
    if (t == q->t1)
        return 1.0;
    return pc_piece_point_parameter(q, t, uv);
}

static projcurve_status copy_pieces(projcurve_context *ctx, const pc_branch *b,
                                    const pc_span *sp, const double uv_s[2],
                                    const double uv_e[2], pc_branch *nb)
{
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < b->n_pieces; ++k) {
        const pc_piece *q = &b->pieces[k];
        const double lo = fmax(sp->s, fmin(q->t0, q->t1));
        const double hi = fmin(sp->e, fmax(q->t0, q->t1));
        if (!(lo < hi))
            continue;
        const double a = piece_s(q, lo, uv_s), c = piece_s(q, hi, uv_e);
        const double s0 = fmin(a, c), s1 = fmax(a, c);
        if (!(s1 - s0 > PC_HITS_PART_MIN_S))
            continue;
        const int forward = q->t1 >= q->t0;
        st = pc_piece_append_part(ctx, nb, q, s0, s1, forward ? lo : hi, forward ? hi : lo);
    }
    return st;
}

static projcurve_status copy_compact(projcurve_context *ctx, const pc_branch *b,
                                     const pc_span *sp, pc_branch *nb)
{
    if (b->compact == PC_COMPACT_NONE || !(sp->e > sp->s))
        return PROJCURVE_OK;
    projcurve_status st =
        pc_bspline_restrict(ctx, &b->compact_pcurve, sp->s, sp->e, &nb->compact_pcurve);
    if (st == PROJCURVE_OK)
        st = pc_bspline_restrict(ctx, &b->compact_curve, sp->s, sp->e, &nb->compact_curve);
    if (st != PROJCURVE_OK)
        return st;
    nb->compact = nb->compact_pcurve.n_poles > 0 ? b->compact : PC_COMPACT_NONE;
    nb->compact_pcurve_error = b->compact_pcurve_error;
    nb->compact_curve_error = b->compact_curve_error;
    return PROJCURVE_OK;
}

/* The points of b in the span, with the exact points at its cuts. */
static projcurve_status copy_points(projcurve_context *ctx, const pc_track *k,
                                    const pc_span *sp, int cut_s, int cut_e,
                                    const double uv_s[2], const double uv_e[2], pc_branch *nb)
{
    const pc_branch *b = k->b;
    const double eps = 1e-13 * (k->hi - k->lo);
    projcurve_status st = PROJCURVE_OK;
    if (cut_s) {
        const double pt[3] = {sp->s, uv_s[0], uv_s[1]};
        st = pc_branch_add_point(ctx, nb, 3, pt);
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < b->n_points; ++i) {
        const double t = b->points[3 * i];
        const int in = cut_s ? t > sp->s + eps : t >= sp->s;
        const int before = cut_e ? t < sp->e - eps : t <= sp->e;
        if (in && before)
            st = pc_branch_add_point(ctx, nb, 3, b->points + 3 * i);
    }
    if (st == PROJCURVE_OK && cut_e) {
        const double pt[3] = {sp->e, uv_e[0], uv_e[1]};
        st = pc_branch_add_point(ctx, nb, 3, pt);
    }
    return st;
}

/* Appends span sp of its track to out, its trim ends to tl. */
static projcurve_status add_span(projcurve_context *ctx, const pc_track *k, const pc_span *sp,
                                 const pc_branch_trim *old, projcurve_result *out,
                                 trim_list *tl)
{
    const pc_branch *b = k->b;
    const int cut_s = !k->whole && sp->s > k->lo, cut_e = !k->whole && sp->e < k->hi;
    double uv_s[2] = {0.0, 0.0}, uv_e[2] = {0.0, 0.0}, d;
    projcurve_status st = PROJCURVE_OK;
    if (cut_s)
        st = pc_track_distance(k, sp->s, uv_s, &d);
    if (st == PROJCURVE_OK && cut_e)
        st = pc_track_distance(k, sp->e, uv_e, &d);
    pc_branch *nb = NULL;
    if (st == PROJCURVE_OK)
        st = pc_result_add_branch(ctx, out, &nb);
    if (st == PROJCURVE_OK)
        PC_ARRAY_RESERVE(st, ctx, tl, tl->count + 1, 8, "branch trims");
    if (st != PROJCURVE_OK)
        return st;
    pc_branch_trim *bt = &tl->items[tl->count++];
    *bt = *old;
    nb->start = b->start;
    nb->end = b->end;
    if (cut_s) {
        bt->start = (pc_trim_end){.on_loop = 0, .edge = -1, .t = sp->s, .uv = {uv_s[0], uv_s[1]}};
        nb->start = PROJCURVE_START_VISIBLE;
    }
    if (cut_e) {
        bt->end = (pc_trim_end){.on_loop = 0, .edge = -1, .t = sp->e, .uv = {uv_e[0], uv_e[1]}};
        nb->end = PROJCURVE_END_OCCLUDED;
    }
    st = copy_points(ctx, k, sp, cut_s, cut_e, uv_s, uv_e, nb);
    if (st == PROJCURVE_OK)
        st = copy_pieces(ctx, b, sp, uv_s, uv_e, nb);
    if (st == PROJCURVE_OK)
        st = copy_compact(ctx, b, sp, nb);
    if (st == PROJCURVE_OK && sp->e > sp->s)
        st = pc_seam_restrict_records(ctx, b, sp->s, sp->e, nb);
    return st;
}

/* The new result of part i from its spans (those of its tracks). */
static projcurve_status rebuild_part(projcurve_context *ctx, const pc_face_part *part, size_t i,
                                     const pc_track_set *set, const pc_span_list *spans,
                                     projcurve_result **out, pc_branch_trim **trims)
{
    projcurve_result *nr = NULL;
    trim_list tl = {0};
    projcurve_status st = pc_result_create(ctx, 3, &nr);
    for (size_t j = 0; st == PROJCURVE_OK && j < spans->count; ++j) {
        const pc_track *k = &set->tracks[spans->items[j].track];
        if (k->part == i)
            st = add_span(ctx, k, &spans->items[j], &part->trims[k->branch], nr, &tl);
    }
    if (st != PROJCURVE_OK) {
        projcurve_result_destroy(nr);
        PC_ARRAY_FREE(&tl);
        return st;
    }
    nr->stats = part->result->stats;
    nr->failures_dropped = part->result->failures_dropped;
    double pieces = 0.0;
    for (size_t b = 0; b < nr->n_branches; ++b)
        pieces += (double)nr->branches[b].n_pieces;
    nr->stats.pieces = pieces;
    *out = nr;
    *trims = tl.items;
    return PROJCURVE_OK;
}

projcurve_status pc_parts_rebuild(projcurve_context *ctx, projcurve_shape_result *r,
                                  const pc_track_set *set, const pc_span_list *spans)
{
    projcurve_result **results = calloc(r->n_parts + 1, sizeof *results);
    pc_branch_trim **trims = calloc(r->n_parts + 1, sizeof *trims);
    projcurve_status st = PROJCURVE_OK;
    if (results == NULL || trims == NULL)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the nearest hits");
    for (size_t i = 0; st == PROJCURVE_OK && i < r->n_parts; ++i)
        if (r->parts[i].result != NULL)
            st = rebuild_part(ctx, &r->parts[i], i, set, spans, &results[i], &trims[i]);
    /* all or nothing: the new parts replace the old only when all are made */
    for (size_t i = 0; results != NULL && trims != NULL && i < r->n_parts; ++i) {
        if (r->parts[i].result == NULL)
            continue;
        if (st == PROJCURVE_OK) {
            projcurve_result_destroy(r->parts[i].result);
            free(r->parts[i].trims);
            r->parts[i].result = results[i];
            r->parts[i].trims = trims[i];
        } else {
            projcurve_result_destroy(results[i]);
            free(trims[i]);
        }
    }
    free(results);
    free(trims);
    return st;
}
