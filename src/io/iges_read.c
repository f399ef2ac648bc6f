/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES reader: sections, directory, then every entity of interest.
 *
 * Surfaces (128) are always read, whatever their status: in a B-rep they
 * are the physically dependent bases of trimmed surfaces (144). Curves (100,
 * 102, 110, 126) are read when they stand alone: curves that are parts of
 * other entities (status "physically dependent") or that live in a
 * surface's parameter space (use flag 5) are listed as skipped. A curve on
 * surface (142) that stands alone is read as its 3D curve. The analytic
 * surfaces (108, 118, 120, 122, 190-198) are read as exact NURBS in
 * directory order with the B-splines (iges_analytic.c); the curves, points
 * and directions they are made of are read through them.
 */
#include <stdio.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

#define PC_IGES_STATUS_PHYSICALLY_DEPENDENT 1
#define PC_IGES_USE_PARAMETRIC 5
/* Parameter text may be tokenised this many times the file size (each
 * entity once, members and matrices again for each reference). */
#define PC_IGES_WORK_FACTOR 16
#define PC_IGES_WORK_MIN ((size_t)1 << 20)

static int is_curve_type(int type)
{
    return type == 100 || type == 102 || type == 110 || type == 126;
}

/* Marks the members of a composite curve as read through it. */
static void consume_members(const pc_iges_file *f, size_t de, unsigned char *consumed)
{
    pc_iges_params p;
    if (pc_iges_params_of(f, de, &p) != PROJCURVE_OK)
        return;
    for (size_t i = 2; i < p.count; ++i) {
        long member = 0;
        if (pc_iges_int(&p, i, &member) == PROJCURVE_OK && member > 0 && member % 2 == 1 &&
            (size_t)(member - 1) / 2 < f->n_entries)
            consumed[(member - 1) / 2] = 1;
    }
}

static void consume(const pc_iges_file *f, long de, unsigned char *consumed)
{
    if (de <= 0 || de % 2 == 0 || (size_t)(de - 1) / 2 >= f->n_entries)
        return;
    consumed[(de - 1) / 2] = 1;
    if (f->entries[(de - 1) / 2].type == 102)
        consume_members(f, (size_t)de, consumed);
}

/* Entity 142 (CRTN, SPTR, BPTR, CPTR, PREF): its 3D curve CPTR, if any. */
static projcurve_status curve_on_surface(const pc_iges_file *f, size_t de, pc_io_curve *c,
                                         const char **reason, unsigned char *consumed)
{
    pc_iges_params p;
    long ptrs[2] = {0, 0}; /* BPTR, CPTR */
    projcurve_status st = pc_iges_params_of(f, de, &p);
    if (st == PROJCURVE_OK)
        st = pc_iges_ints(&p, 3, 2, ptrs);
    if (st != PROJCURVE_OK)
        return st;
    const long bptr = ptrs[0], cptr = ptrs[1];
    if (bptr != 0 && pc_iges_entry_at(f, bptr, de) == NULL)
        return PROJCURVE_ERR_PARSE;
    consume(f, bptr, consumed);
    if (cptr == 0) {
        *reason = "only a parameter-space curve";
        return PROJCURVE_OK;
    }
    const pc_iges_entry *e = pc_iges_entry_at(f, cptr, de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    consume(f, cptr, consumed);
    if (!(e->type == 100 || e->type == 102 || e->type == 110 || e->type == 126)) {
        *reason = "its 3D curve is of an unsupported type";
        return PROJCURVE_OK;
    }
    return pc_iges_curve(f, (size_t)cptr, c, reason);
}

static projcurve_status analytic_surface(pc_iges_file *f, projcurve_model *model, size_t index,
                                         unsigned char *consumed, const char *origin)
{
    pc_io_surface s;
    const char *kind = NULL, *reason = NULL;
    long uses[PC_IGES_MAX_USES];
    size_t n_uses = 0;
    projcurve_status st =
        pc_iges_analytic_surface(f, 2 * index + 1, NULL, 0, &s, &kind, uses, &n_uses, &reason);
    if (st != PROJCURVE_OK)
        return st;
    consumed[index] = 1;
    for (size_t i = 0; i < n_uses; ++i)
        consume(f, uses[i], consumed);
    if (reason != NULL)
        return pc_model_add_skipped(f->ctx, model, "%s (%s)", origin, reason);
    st = pc_model_add_surface_kind(f->ctx, model, &s, origin, kind);
    if (st == PROJCURVE_OK) /* a 144 on it may make a face (iges_topology.c) */
        f->surface_of[index] = (long)model->n_surfaces - 1;
    return st;
}

static projcurve_status read_entity(pc_iges_file *f, projcurve_model *model, size_t index,
                                    unsigned char *consumed)
{
    const pc_iges_entry *e = &f->entries[index];
    const size_t de = 2 * index + 1;
    char origin[64];
    snprintf(origin, sizeof origin, "IGES entity %d at DE %zu", e->type, de);
    if (e->type == 128) {
        pc_io_surface s;
        projcurve_status st = pc_iges_surface(f, de, &s);
        if (st == PROJCURVE_OK)
            st = pc_model_add_surface(f->ctx, model, &s, origin);
        if (st == PROJCURVE_OK)
            f->surface_of[index] = (long)model->n_surfaces - 1;
        return st;
    }
    if (pc_iges_is_analytic_surface(e->type))
        return analytic_surface(f, model, index, consumed, origin);
    if (!(is_curve_type(e->type) || e->type == 142) || consumed[index])
        return PROJCURVE_OK;
    if (e->subordinate == PC_IGES_STATUS_PHYSICALLY_DEPENDENT)
        return PROJCURVE_OK; /* listed as skipped unless its parent read it */
    if (e->use == PC_IGES_USE_PARAMETRIC)
        return PROJCURVE_OK;
    pc_io_curve c;
    const char *reason = NULL;
    projcurve_status st = e->type == 142 ? curve_on_surface(f, de, &c, &reason, consumed)
                                         : pc_iges_curve(f, de, &c, &reason);
    if (st != PROJCURVE_OK)
        return st;
    consumed[index] = 1; /* read or listed here with its reason, not again below */
    if (reason != NULL)
        return pc_model_add_skipped(f->ctx, model, "%s (%s)", origin, reason);
    if (e->type == 102)
        consume_members(f, de, consumed); /* read through it */
    return pc_model_add_curve(f->ctx, model, &c, origin);
}

static const char *skip_note(const pc_iges_entry *e)
{
    if (e->type == 142 && e->subordinate == PC_IGES_STATUS_PHYSICALLY_DEPENDENT)
        return " (a part of another entity)";
    if (e->use == PC_IGES_USE_PARAMETRIC && is_curve_type(e->type))
        return " (a curve in parameter space)";
    if (e->subordinate == PC_IGES_STATUS_PHYSICALLY_DEPENDENT && is_curve_type(e->type))
        return " (a part of another entity)";
    return "";
}

projcurve_status pc_iges_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model)
{
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    pc_iges_file f;
    memset(&f, 0, sizeof f);
    f.ctx = ctx;
    f.arena = &arena;
    size_t work_done = 0;
    f.work_done = &work_done;
    f.work_limit = PC_IGES_WORK_FACTOR * len + PC_IGES_WORK_MIN;
    projcurve_status st = pc_iges_split(&f, data, len);
    if (st == PROJCURVE_OK)
        st = pc_iges_read_global(&f);
    if (st == PROJCURVE_OK)
        st = pc_iges_read_directory(&f);
    if (st == PROJCURVE_OK)
        st = pc_iges_read_units(&f, model);
    unsigned char *consumed = NULL;
    if (st == PROJCURVE_OK) {
        consumed = pc_arena_calloc(&arena, f.n_entries + 1, 1);
        f.surface_of = pc_arena_calloc(&arena, f.n_entries + 1, sizeof *f.surface_of);
        for (size_t i = 0; f.surface_of != NULL && i <= f.n_entries; ++i)
            f.surface_of[i] = -1;
        if (consumed == NULL || f.surface_of == NULL)
            st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < f.n_entries; ++i)
        st = read_entity(&f, model, i, consumed);
    if (st == PROJCURVE_OK)
        st = pc_iges_read_topology(&f, model, consumed);
    /* Everything neither read nor used by what was read is listed; 124
     * matrices are used through field 7 and 0 is the null entity. */
    for (size_t i = 0; st == PROJCURVE_OK && i < f.n_entries; ++i) {
        const pc_iges_entry *e = &f.entries[i];
        if (consumed[i] || e->type == 128 || e->type == 124 || e->type == 0)
            continue;
        st = pc_model_add_skipped(ctx, model, "IGES entity %d at DE %zu%s", e->type, 2 * i + 1,
                                  skip_note(e));
    }
    pc_arena_release(&arena);
    return st;
}
