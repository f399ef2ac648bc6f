/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Layout of an IGES 5.3 file: fixed 80-column records, fields never split
 * across records, sequence numbers per section, and the terminate record
 * with the section counts.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "io/io_file.h"
#include "io/iges.h"
#include "io/iges_write.h"

/* The units flag of millimetres, the unit of a writer told no other. */
#define PC_IGES_UNIT_FLAG_MM 2

#define PC_IGES_G_WIDTH 72
#define PC_IGES_P_WIDTH 64

projcurve_status pc_iges_out_add(projcurve_context *ctx, pc_iges_out *out, int type, int form,
                                 const char *status, pc_text_buf *params, size_t *de)
{
    if (params->failed || params->text == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory formatting IGES entity %d",
                       type);
    void *items = out->entities;
    const projcurve_status grown =
        pc_array_reserve(ctx, &items, &out->cap, out->count, out->count + 1,
                         sizeof *out->entities, 16, NULL, "the written IGES entities");
    out->entities = items;
    if (grown != PROJCURVE_OK)
        return grown;
    pc_iges_out_entity *e = &out->entities[out->count];
    e->type = type;
    e->form = form;
    snprintf(e->status, sizeof e->status, "%s", status);
    e->params = params->text;
    params->text = NULL;
    params->len = params->cap = 0;
    *de = 2 * out->count + 1;
    ++out->count;
    return PROJCURVE_OK;
}

void pc_iges_out_truncate(pc_iges_out *out, size_t count)
{
    for (size_t i = count; i < out->count; ++i)
        free(out->entities[i].params);
    if (count < out->count)
        out->count = count;
}

void pc_iges_out_free(pc_iges_out *out)
{
    for (size_t i = 0; i < out->count; ++i)
        free(out->entities[i].params);
    free(out->entities);
    out->entities = NULL;
    out->count = out->cap = 0;
}

/* Emits free-format text as records of `width` data columns, breaking
 * after a delimiter so no field is split; returns the records used. */
static size_t records(pc_text_buf *s, const char *text, size_t width, char section, size_t seq,
                      size_t de)
{
    const size_t len = strlen(text);
    size_t pos = 0, used = 0;
    while (pos < len) {
        size_t take = len - pos;
        if (take > width) {
            take = width;
            while (take > 0 && text[pos + take - 1] != ',' && text[pos + take - 1] != ';')
                --take;
            if (take == 0)
                take = width; /* a single field wider than a record: split it */
        }
        char line[96];
        if (section == 'P')
            snprintf(line, sizeof line, "%-64.*s %7zuP%7zu\n", (int)take, text + pos, de,
                     seq + used);
        else
            snprintf(line, sizeof line, "%-72.*s%c%7zu\n", (int)take, text + pos, section,
                     seq + used);
        pc_text_buf_puts(s, line);
        pos += take;
        ++used;
    }
    return used;
}

/* Hollerith form of a string. */
static void hollerith(char *out, size_t cap, const char *s)
{
    snprintf(out, cap, "%zuH%s,", strlen(s), s);
}

/* unit_flag: pc_iges_unit_flag's, 0 for millimetres */
static size_t global_section(pc_text_buf *s, int unit_flag)
{
    const char *unit_name = pc_iges_unit_name(unit_flag);
    if (unit_name == NULL) {
        unit_flag = PC_IGES_UNIT_FLAG_MM;
        unit_name = pc_iges_unit_name(unit_flag);
    }
    char g[1024], h[6][96];
    hollerith(h[0], sizeof h[0], "libprojcurve model");
    hollerith(h[1], sizeof h[1], "projcurve.igs");
    hollerith(h[2], sizeof h[2], "libprojcurve " PROJCURVE_VERSION_STRING);
    hollerith(h[3], sizeof h[3], "libprojcurve " PROJCURVE_VERSION_STRING);
    hollerith(h[4], sizeof h[4], "20000101.000000");
    hollerith(h[5], sizeof h[5], unit_name);
    /* Delimiters, sender id, file, system, preprocessor, integer bits,
     * single/double precision ranges, receiver id, scale, units (flag, name),
     * line weights, max width, date, resolution, max coordinate, author,
     * organisation, IGES version 11 (= 5.3), drafting standard, date. */
    snprintf(g, sizeof g,
             "1H,,1H;,%s%s%s%s32,38,6,308,15,%s1.,%d,%s1,1.,%s1.E-10,0.,,,11,0,%s", h[0],
             h[1], h[2], h[3], h[0], unit_flag, h[5], h[4], h[4]);
    g[strlen(g) - 1] = ';';
    return records(s, g, PC_IGES_G_WIDTH, 'G', 1, 0);
}

static projcurve_status layout(projcurve_context *ctx, const pc_iges_out *out, pc_text_buf *s)
{
    char line[96];
    snprintf(line, sizeof line, "%-72sS%7d\n", "libprojcurve: projected curves on NURBS surfaces", 1);
    pc_text_buf_puts(s, line);
    const size_t n_g = global_section(s, out->unit_flag);
    /* Parameter record counts first: the directory points into P. */
    size_t *p_start = calloc(out->count + 1, sizeof *p_start);
    size_t *p_count = calloc(out->count + 1, sizeof *p_count);
    if (p_start == NULL || p_count == NULL) {
        free(p_start);
        free(p_count);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing IGES");
    }
    pc_text_buf params = {0};
    size_t seq = 1;
    for (size_t i = 0; i < out->count; ++i) {
        const pc_iges_out_entity *e = &out->entities[i];
        char head[16];
        snprintf(head, sizeof head, "%d,", e->type);
        /* The type field and the parameters go through one text. */
        pc_text_buf whole = {0};
        pc_text_buf_puts(&whole, head);
        pc_text_buf_puts(&whole, e->params);
        if (whole.failed) {
            params.failed = 1;
            free(whole.text);
            break;
        }
        p_start[i] = seq;
        p_count[i] = records(&params, whole.text, PC_IGES_P_WIDTH, 'P', seq, 2 * i + 1);
        seq += p_count[i];
        free(whole.text);
    }
    for (size_t i = 0; i < out->count; ++i) {
        const pc_iges_out_entity *e = &out->entities[i];
        snprintf(line, sizeof line, "%8d%8zu%8d%8d%8d%8d%8d%8d%8sD%7zu\n", e->type, p_start[i], 0,
                 0, 0, 0, 0, 0, e->status, 2 * i + 1);
        pc_text_buf_puts(s, line);
        snprintf(line, sizeof line, "%8d%8d%8d%8zu%8d%8s%8s%8s%8dD%7zu\n", e->type, 0, 0,
                 p_count[i], e->form, "", "", "", 0, 2 * i + 2);
        pc_text_buf_puts(s, line);
    }
    if (params.text)
        pc_text_buf_puts(s, params.text);
    snprintf(line, sizeof line, "S%7dG%7zuD%7zuP%7zu%40sT%7d\n", 1, n_g, 2 * out->count, seq - 1,
             "", 1);
    pc_text_buf_puts(s, line);
    const int failed = params.failed || s->failed;
    free(params.text);
    free(p_start);
    free(p_count);
    if (failed)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing IGES");
    return PROJCURVE_OK;
}

projcurve_status pc_iges_out_text(projcurve_context *ctx, const pc_iges_out *out, char **text,
                                  size_t *len)
{
    pc_text_buf s = {0};
    const projcurve_status st = layout(ctx, out, &s);
    if (st != PROJCURVE_OK) {
        free(s.text);
        return st;
    }
    *text = s.text;
    *len = s.len;
    return PROJCURVE_OK;
}

projcurve_status pc_iges_out_write(projcurve_context *ctx, const pc_iges_out *out,
                                   const char *path)
{
    char *text = NULL;
    size_t len = 0;
    projcurve_status st = pc_iges_out_text(ctx, out, &text, &len);
    if (st != PROJCURVE_OK)
        return st;
    st = pc_write_file(ctx, path, text, len);
    free(text);
    return st;
}
