/* SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

#define PC_IGES_FIELD_WIDTH 8

/* Field k (0-based) of a directory record: a right-justified integer or
 * blank (0). */
static projcurve_status de_field(const pc_iges_file *f, size_t rec_index, int k, long *out)
{
    const char *rec = f->sec[2].records[rec_index];
    const char *s = rec + PC_IGES_FIELD_WIDTH * k;
    long v = 0;
    int sign = 1, digits = 0, i = 0;
    while (i < PC_IGES_FIELD_WIDTH && s[i] == ' ')
        ++i;
    if (i < PC_IGES_FIELD_WIDTH && (s[i] == '-' || s[i] == '+')) {
        sign = s[i] == '-' ? -1 : 1;
        ++i;
    }
    for (; i < PC_IGES_FIELD_WIDTH && isdigit((unsigned char)s[i]); ++i, ++digits)
        v = v * 10 + (s[i] - '0');
    while (i < PC_IGES_FIELD_WIDTH && s[i] == ' ')
        ++i;
    if (i != PC_IGES_FIELD_WIDTH || (digits == 0 && sign < 0))
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES line %zu: directory field %d ('%.8s') is not an integer",
                       f->sec[2].lines[rec_index], k + 1, s);
    *out = sign * v;
    return PROJCURVE_OK;
}

/* Two digits of the status field (columns 65-72 of the first record);
 * blanks count as zeros. */
static projcurve_status status_digits(const pc_iges_file *f, size_t rec_index, int at, int *out)
{
    const char *s = f->sec[2].records[rec_index] + 8 * PC_IGES_FIELD_WIDTH + at;
    int v = 0;
    for (int i = 0; i < 2; ++i) {
        if (s[i] == ' ')
            v = v * 10;
        else if (isdigit((unsigned char)s[i]))
            v = v * 10 + (s[i] - '0');
        else
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: status field '%.8s' is not numeric",
                           f->sec[2].lines[rec_index], s - at);
    }
    *out = v;
    return PROJCURVE_OK;
}

projcurve_status pc_iges_read_directory(pc_iges_file *f)
{
    f->n_entries = f->sec[2].count / 2;
    f->entries = pc_arena_calloc(f->arena, f->n_entries + 1, sizeof *f->entries);
    if (f->entries == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading the IGES directory");
    for (size_t e = 0; e < f->n_entries; ++e) {
        const size_t r = 2 * e;
        long type, pstart, transform, type2, plines, form;
        projcurve_status st;
        if ((st = de_field(f, r, 0, &type)) != PROJCURVE_OK ||
            (st = de_field(f, r, 1, &pstart)) != PROJCURVE_OK ||
            (st = de_field(f, r, 6, &transform)) != PROJCURVE_OK ||
            (st = de_field(f, r + 1, 0, &type2)) != PROJCURVE_OK ||
            (st = de_field(f, r + 1, 3, &plines)) != PROJCURVE_OK ||
            (st = de_field(f, r + 1, 4, &form)) != PROJCURVE_OK)
            return st;
        if (type != type2)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: directory entry %zu says entity type %ld, then %ld",
                           f->sec[2].lines[r], 2 * e + 1, type, type2);
        pc_iges_entry *ent = &f->entries[e];
        ent->type = (int)type;
        ent->param_start = pstart;
        ent->param_lines = plines;
        ent->transform = transform;
        ent->form = (int)form;
        if ((st = status_digits(f, r, 2, &ent->subordinate)) != PROJCURVE_OK ||
            (st = status_digits(f, r, 4, &ent->use)) != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}
