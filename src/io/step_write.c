/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Layout of a STEP file (ISO 10303-21): the header section (FILE_SCHEMA
 * AP214), the DATA section of the geometry instances, then the product and
 * context instances; and the bookkeeping of a pc_step_out (marks, the
 * GEOMETRIC_SET, the written surfaces).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "io/io_file.h"
#include "io/step_write.h"

/* The uncertainty of a writer told no other, in model units: 1e-7 mm is
 * what CAD systems write for their own models. */
#define PC_STEP_DEFAULT_UNCERTAINTY 1e-7

#define PC_STEP_SCHEMA "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }"

void pc_step_out_init(pc_step_out *out)
{
    memset(out, 0, sizeof *out);
    out->next_id = PC_STEP_FIRST_GEOMETRY_ID;
    out->metres_per_unit = 1e-3;
    out->uncertainty = PC_STEP_DEFAULT_UNCERTAINTY;
}

static void free_surfaces_from(pc_step_out *out, size_t count)
{
    for (size_t i = count; i < out->surfaces.count; ++i)
        free(out->surfaces.items[i].key);
    if (count < out->surfaces.count)
        out->surfaces.count = count;
}

void pc_step_out_free(pc_step_out *out)
{
    free_surfaces_from(out, 0);
    PC_ARRAY_FREE(&out->surfaces);
    PC_ARRAY_FREE(&out->set);
    pc_text_buf_free(&out->data);
}

pc_step_mark pc_step_out_mark(const pc_step_out *out)
{
    return (pc_step_mark){.len = out->data.len,
                          .line_start = out->line_start,
                          .n_set = out->set.count,
                          .n_surfaces = out->surfaces.count,
                          .next_id = out->next_id,
                          .has_pcurves = out->has_pcurves};
}

void pc_step_out_rollback(pc_step_out *out, const pc_step_mark *mark)
{
    pc_text_buf_truncate(&out->data, mark->len);
    /* a failed append left the text as it was; later appends may succeed */
    out->data.failed = 0;
    out->line_start = mark->line_start;
    if (mark->n_set < out->set.count)
        out->set.count = mark->n_set;
    free_surfaces_from(out, mark->n_surfaces);
    out->next_id = mark->next_id;
    out->has_pcurves = mark->has_pcurves;
}

projcurve_status pc_step_out_add_to_set(projcurve_context *ctx, pc_step_out *out, long id)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, &out->set, out->set.count + 1, 16, "the STEP geometric set");
    if (st != PROJCURVE_OK)
        return st;
    out->set.items[out->set.count++] = id;
    return PROJCURVE_OK;
}

/* The header section; its strings hold no apostrophe or backslash, which
 * Part 21 would ask to escape. The time stamp is fixed, so that the same
 * geometry gives the same file. */
static void header(pc_text_buf *b)
{
    pc_text_buf_puts(b, "ISO-10303-21;\nHEADER;\n"
                        "FILE_DESCRIPTION(('libprojcurve: projected curves on NURBS surfaces'),"
                        "'2;1');\n"
                        "FILE_NAME('projcurve.step','2000-01-01T00:00:00',(''),(''),"
                        "'libprojcurve " PROJCURVE_VERSION_STRING "',"
                        "'libprojcurve " PROJCURVE_VERSION_STRING "','');\n"
                        "FILE_SCHEMA(('" PC_STEP_SCHEMA "'));\n"
                        "ENDSEC;\nDATA;\n");
}

projcurve_status pc_step_out_text(projcurve_context *ctx, const pc_step_out *out, char **text,
                                  size_t *len)
{
    pc_text_buf b = {0};
    header(&b);
    if (out->data.text != NULL)
        pc_text_buf_append(&b, out->data.text, out->data.len);
    pc_step_format_context(&b, out, out->next_id);
    pc_text_buf_puts(&b, "ENDSEC;\nEND-ISO-10303-21;\n");
    if (b.failed || out->data.failed) {
        pc_text_buf_free(&b);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing STEP");
    }
    *text = b.text;
    *len = b.len;
    return PROJCURVE_OK;
}

projcurve_status pc_step_out_write(projcurve_context *ctx, const pc_step_out *out,
                                   const char *path)
{
    char *text = NULL;
    size_t len = 0;
    projcurve_status st = pc_step_out_text(ctx, out, &text, &len);
    if (st != PROJCURVE_OK)
        return st;
    st = pc_write_file(ctx, path, text, len);
    free(text);
    return st;
}
