/* SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

/* Hollerith lengths beyond this many digits are garbage, not strings. */
#define PC_IGES_MAX_HOLLERITH_DIGITS 9
/* Longest text taken for one number (IGES reals are at most ~30 chars). */
#define PC_IGES_MAX_NUMBER_TEXT 64

static int valid_delimiter(char c)
{
    return c > ' ' && c < 127 && !isdigit((unsigned char)c) && c != 'H' && c != '+' &&
           c != '-' && c != '.';
}

/* A delimiter field of the global section: "1Hx" or empty (the default). */
static projcurve_status global_delim(const pc_iges_file *f, const char *g, size_t len,
                                     size_t *pos, char fallback, char *out, const char *what)
{
    if (*pos + 2 < len && g[*pos] == '1' && g[*pos + 1] == 'H') {
        *out = g[*pos + 2];
        *pos += 3;
        if (!valid_delimiter(*out))
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES global section: unusable %s delimiter", what);
    } else {
        *out = fallback;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_iges_read_global(pc_iges_file *f)
{
    const pc_iges_section *g = &f->sec[1];
    char head[2 * PC_IGES_DATA_COLUMNS] = {0}; /* only len bytes are read */
    size_t len = 0;
    for (size_t r = 0; r < g->count && len + PC_IGES_DATA_COLUMNS <= sizeof head; ++r) {
        memcpy(head + len, g->records[r], PC_IGES_DATA_COLUMNS);
        len += PC_IGES_DATA_COLUMNS;
    }
    size_t pos = 0;
    projcurve_status st = global_delim(f, head, len, &pos, ',', &f->param_delim, "parameter");
    if (st != PROJCURVE_OK)
        return st;
    if (pos < len && head[pos] == f->param_delim)
        ++pos;
    st = global_delim(f, head, len, &pos, ';', &f->record_delim, "record");
    if (st != PROJCURVE_OK)
        return st;
    if (f->param_delim == f->record_delim)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES global section: parameter and record delimiters are both '%c'",
                       f->param_delim);
    return PROJCURVE_OK;
}

const pc_iges_entry *pc_iges_entry_at(const pc_iges_file *f, long de, size_t from_de)
{
    if (de < 1 || de % 2 == 0 || (size_t)(de - 1) / 2 >= f->n_entries) {
        pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                "IGES entity at DE %zu: pointer %ld is not the start of a directory entry "
                "(the directory has %zu entries)",
                from_de, de, f->n_entries);
        return NULL;
    }
    return &f->entries[(size_t)(de - 1) / 2];
}

/* The 7-column number of a P record's back pointer (columns 66-72). */
static long back_pointer(const char *rec)
{
    long v = 0;
    int any = 0;
    for (int c = 65; c < PC_IGES_DATA_COLUMNS; ++c) {
        if (isdigit((unsigned char)rec[c])) {
            v = v * 10 + (rec[c] - '0');
            any = 1;
        } else if (rec[c] != ' ') {
            return -1;
        }
    }
    return any ? v : -1;
}

/* Concatenates columns 1-64 of the entity's parameter records. */
static projcurve_status gather(const pc_iges_file *f, size_t de, const pc_iges_entry *e,
                               char **text, size_t *len)
{
    const pc_iges_section *p = &f->sec[3];
    if (e->param_start < 1 || e->param_lines < 1 || (size_t)e->param_start > p->count ||
        (size_t)e->param_lines > p->count - (size_t)e->param_start + 1)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: parameter records %ld..%ld are outside the "
                       "parameter section (%zu records)",
                       e->type, de, e->param_start, e->param_start + e->param_lines - 1, p->count);
    const size_t first = (size_t)e->param_start - 1, n = (size_t)e->param_lines;
    char *buf = pc_arena_alloc(f->arena, n * PC_IGES_PARAM_COLUMNS + 1);
    if (buf == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES parameters");
    for (size_t r = 0; r < n; ++r) {
        const char *rec = p->records[first + r];
        if (back_pointer(rec) != (long)de)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: parameter record belongs to DE %ld, expected DE %zu",
                           p->lines[first + r], back_pointer(rec), de);
        memcpy(buf + r * PC_IGES_PARAM_COLUMNS, rec, PC_IGES_PARAM_COLUMNS);
    }
    buf[n * PC_IGES_PARAM_COLUMNS] = '\0';
    *text = buf;
    *len = n * PC_IGES_PARAM_COLUMNS;
    return PROJCURVE_OK;
}

/* A Hollerith field nHxxx starting at s[*pos]: on success *pos is past it. */
static int hollerith(const char *s, size_t len, size_t *pos, pc_iges_field *field)
{
    size_t q = *pos, digits = 0, n = 0;
    while (q < len && isdigit((unsigned char)s[q]) && digits < PC_IGES_MAX_HOLLERITH_DIGITS) {
        n = n * 10 + (size_t)(s[q] - '0');
        ++q;
        ++digits;
    }
    if (digits == 0 || q >= len || s[q] != 'H' || n > len - q - 1)
        return 0;
    field->text = s + q + 1;
    field->len = n;
    *pos = q + 1 + n;
    return 1;
}

projcurve_status pc_iges_params_of(const pc_iges_file *f, size_t de, pc_iges_params *out)
{
    const pc_iges_entry *e = pc_iges_entry_at(f, (long)de, de);
    if (e == NULL)
        return PROJCURVE_ERR_PARSE;
    char *s = NULL;
    size_t len = 0;
    projcurve_status st = gather(f, de, e, &s, &len);
    if (st != PROJCURVE_OK)
        return st;
    *f->work_done += len;
    if (*f->work_done > f->work_limit)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: the file refers to its entities too many times "
                       "(more than %zu parameter characters read)",
                       e->type, de, f->work_limit);
    size_t cap = 2;
    for (size_t i = 0; i < len; ++i)
        cap += (s[i] == f->param_delim);
    pc_iges_field *fields = pc_arena_alloc(f->arena, cap * sizeof *fields);
    if (fields == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES parameters");
    size_t n = 0, pos = 0;
    for (;;) {
        while (pos < len && s[pos] == ' ')
            ++pos;
        if (pos >= len || n >= cap)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES entity %d at DE %zu: parameter data ends without the record "
                           "delimiter '%c'",
                           e->type, de, f->record_delim);
        pc_iges_field field;
        if (!hollerith(s, len, &pos, &field)) {
            const size_t start = pos;
            while (pos < len && s[pos] != f->param_delim && s[pos] != f->record_delim)
                ++pos;
            size_t end = pos;
            while (end > start && s[end - 1] == ' ')
                --end;
            field.text = s + start;
            field.len = end - start;
        }
        while (pos < len && s[pos] == ' ')
            ++pos;
        fields[n++] = field;
        if (pos < len && s[pos] == f->record_delim)
            break;
        if (pos < len && s[pos] != f->param_delim)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES entity %d at DE %zu: unexpected '%c' after parameter %zu",
                           e->type, de, s[pos], n - 1);
        ++pos;
    }
    *out = (pc_iges_params){.file = f, .de = de, .type = e->type, .fields = fields, .count = n};
    long type = 0;
    st = pc_iges_int(out, 0, &type);
    if (st != PROJCURVE_OK)
        return st;
    if (type != e->type)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: parameter data is of entity type %ld", e->type,
                       de, type);
    return PROJCURVE_OK;
}

projcurve_status pc_iges_real(const pc_iges_params *p, size_t i, double *out)
{
    if (i >= p->count) {
        *out = 0.0;
        return PROJCURVE_OK;
    }
    const pc_iges_field *fd = &p->fields[i];
    char buf[PC_IGES_MAX_NUMBER_TEXT];
    size_t n = 0;
    for (size_t k = 0; k < fd->len; ++k) {
        char c = fd->text[k];
        if (c == ' ')
            continue;
        if (n + 1 >= sizeof buf)
            goto bad;
        buf[n++] = (c == 'D' || c == 'd') ? 'E' : c;
    }
    buf[n] = '\0';
    if (n == 0) {
        *out = 0.0;
        return PROJCURVE_OK;
    }
    for (size_t k = 0; k < n; ++k)
        if (!isdigit((unsigned char)buf[k]) && strchr("+-.Ee", buf[k]) == NULL)
            goto bad;
    char *end = NULL;
    const double v = strtod(buf, &end);
    if (end != buf + n || !isfinite(v))
        goto bad;
    *out = v;
    return PROJCURVE_OK;
bad:
    return pc_fail(p->file->ctx, PROJCURVE_ERR_PARSE,
                   "IGES entity %d at DE %zu: parameter %zu ('%.*s') is not a number", p->type,
                   p->de, i, (int)(fd->len > 32 ? 32 : fd->len), fd->text);
}

projcurve_status pc_iges_int(const pc_iges_params *p, size_t i, long *out)
{
    double v;
    projcurve_status st = pc_iges_real(p, i, &v);
    if (st != PROJCURVE_OK)
        return st;
    if (v != floor(v) || fabs(v) > 2147483647.0)
        return pc_fail(p->file->ctx, PROJCURVE_ERR_PARSE,
                       "IGES entity %d at DE %zu: parameter %zu (%g) is not an integer", p->type,
                       p->de, i, v);
    *out = (long)v;
    return PROJCURVE_OK;
}

projcurve_status pc_iges_reals(const pc_iges_params *p, size_t first, size_t n, double *out)
{
    for (size_t i = 0; i < n; ++i) {
        const projcurve_status st = pc_iges_real(p, first + i, &out[i]);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_iges_ints(const pc_iges_params *p, size_t first, size_t n, long *out)
{
    for (size_t i = 0; i < n; ++i) {
        const projcurve_status st = pc_iges_int(p, first + i, &out[i]);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}
