/* SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

/* How far from column 73 a section letter is looked for to explain a
 * record whose columns are shifted. */
#define PC_IGES_MAX_SHIFT 8
/* Digits of the sequence number that must follow such a letter. */
#define PC_IGES_MIN_SHIFTED_DIGITS 4

static int section_index(char letter)
{
    switch (letter) {
    case 'S': return 0;
    case 'G': return 1;
    case 'D': return 2;
    case 'P': return 3;
    case 'T': return 4;
    default: return -1;
    }
}

/* Line ends: "\n" or "\r\n"; files without any line end are taken as bare
 * 80-character records (some writers emit them). */
static int has_line_ends(const char *data, size_t len)
{
    const size_t probe = len < 2 * PC_IGES_RECORD ? len : 2 * PC_IGES_RECORD;
    return memchr(data, '\n', probe) != NULL || len <= PC_IGES_RECORD;
}

/* Column 73 holds no section letter: says where the letter is when the
 * record looks shifted (a letter followed by digits to the end of the
 * record a few columns away), so the message names the real fault. */
static projcurve_status misplaced_letter(projcurve_context *ctx, const char *line, size_t len,
                                         size_t line_no, char letter)
{
    for (size_t c = PC_IGES_DATA_COLUMNS - PC_IGES_MAX_SHIFT;
         c <= PC_IGES_DATA_COLUMNS + PC_IGES_MAX_SHIFT && c + 1 < len; ++c) {
        if (c == PC_IGES_DATA_COLUMNS || section_index(line[c]) < 0)
            continue;
        size_t d = c + 1, digits = 0;
        for (; d < len && (isdigit((unsigned char)line[d]) || line[d] == ' '); ++d)
            digits += isdigit((unsigned char)line[d]) != 0;
        if (d == len && digits >= PC_IGES_MIN_SHIFTED_DIGITS)
            return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: the section letter '%c' is in column %zu, not 73: "
                           "the columns are shifted",
                           line_no, line[c], c + 1);
    }
    return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                   "IGES line %zu: column 73 holds '%c', not a section letter (S, G, D, P, T)",
                   line_no, (letter >= 32 && letter < 127) ? letter : '?');
}

static projcurve_status add_record(pc_iges_file *f, const char *line, size_t len, size_t line_no,
                                   int *last_section, size_t *counts, int counting)
{
    projcurve_context *ctx = f->ctx;
    if (len > PC_IGES_RECORD)
        return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                       "IGES line %zu: %zu columns, records have %d", line_no, len, PC_IGES_RECORD);
    if (len <= PC_IGES_DATA_COLUMNS)
        return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                       "IGES line %zu: only %zu columns, the section letter belongs in column 73",
                       line_no, len);
    const char letter = line[PC_IGES_DATA_COLUMNS];
    if (letter == 'C' || letter == 'B')
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "IGES line %zu: compressed or binary IGES is not supported", line_no);
    const int s = section_index(letter);
    if (s < 0)
        return misplaced_letter(ctx, line, len, line_no, letter);
    if (s < *last_section)
        return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                       "IGES line %zu: section %c after a later section", line_no, letter);
    *last_section = s;
    if (!counting) {
        char *rec = pc_arena_alloc(f->arena, PC_IGES_RECORD + 1);
        if (rec == NULL)
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES records");
        memset(rec, ' ', PC_IGES_RECORD);
        memcpy(rec, line, len);
        rec[PC_IGES_RECORD] = '\0';
        for (size_t i = 0; i < PC_IGES_RECORD; ++i)
            if (rec[i] == '\0' || rec[i] == '\t')
                rec[i] = ' ';
        pc_iges_section *sec = &f->sec[s];
        sec->records[sec->count] = rec;
        sec->lines[sec->count] = line_no;
        ++sec->count;
    } else {
        ++counts[s];
    }
    return PROJCURVE_OK;
}

/* Walks the records; with counting != 0 only counts them per section. */
static projcurve_status walk(pc_iges_file *f, const char *data, size_t len, size_t *counts,
                             int counting)
{
    int last_section = 0;
    size_t line_no = 0;
    if (!has_line_ends(data, len)) {
        if (len % PC_IGES_RECORD != 0)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES: no line ends and a length (%zu) that is not a multiple of 80",
                           len);
        for (size_t pos = 0; pos < len; pos += PC_IGES_RECORD) {
            projcurve_status st = add_record(f, data + pos, PC_IGES_RECORD, ++line_no,
                                             &last_section, counts, counting);
            if (st != PROJCURVE_OK)
                return st;
        }
        return PROJCURVE_OK;
    }
    size_t pos = 0;
    while (pos < len) {
        const char *nl = memchr(data + pos, '\n', len - pos);
        const size_t end = nl ? (size_t)(nl - data) : len;
        size_t n = end - pos;
        if (n > 0 && data[pos + n - 1] == '\r')
            --n;
        ++line_no;
        /* Blank lines (often one at the end) carry nothing. */
        size_t blank = 0;
        while (blank < n && (data[pos + blank] == ' ' || data[pos + blank] == '\x1a'))
            ++blank;
        if (blank < n) {
            projcurve_status st = add_record(f, data + pos, n, line_no, &last_section, counts,
                                             counting);
            if (st != PROJCURVE_OK)
                return st;
        }
        pos = end + 1;
    }
    return PROJCURVE_OK;
}

/* The terminate record "S0000001G0000004D0000026P0000521" counts the
 * records of the other sections: a file cut short or missing lines (a
 * partial copy or transfer) is caught here, with the section that differs,
 * instead of surfacing later as an entity whose parameters are missing. */
static projcurve_status check_terminate(const pc_iges_file *f)
{
    const pc_iges_section *t = &f->sec[4];
    if (t->count == 0)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES: no terminate (T) record at the end: the file is truncated");
    const char *rec = t->records[0];
    for (int s = 0; s < 4; ++s) {
        const char *field = rec + 8 * s;
        char digits[8];
        memcpy(digits, field + 1, 7);
        digits[7] = '\0';
        char *end = NULL;
        const long n = strtol(digits, &end, 10);
        while (end != NULL && *end == ' ')
            ++end;
        if (field[0] != "SGDP"[s] || end == digits || end == NULL || *end != '\0' || n < 0)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: the terminate record does not count the sections "
                           "('%.32s')",
                           t->lines[0], rec);
        if ((size_t)n != f->sec[s].count)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "IGES line %zu: the terminate record counts %ld %c records, the file "
                           "has %zu: records are missing or the file is truncated",
                           t->lines[0], n, "SGDP"[s], f->sec[s].count);
    }
    return PROJCURVE_OK;
}

projcurve_status pc_iges_split(pc_iges_file *f, const char *data, size_t len)
{
    size_t counts[5] = {0};
    projcurve_status st = walk(f, data, len, counts, 1);
    if (st != PROJCURVE_OK)
        return st;
    for (int s = 0; s < 5; ++s) {
        f->sec[s].count = 0;
        f->sec[s].records = pc_arena_calloc(f->arena, counts[s] + 1, sizeof(char *));
        f->sec[s].lines = pc_arena_calloc(f->arena, counts[s] + 1, sizeof(size_t));
        if (f->sec[s].records == NULL || f->sec[s].lines == NULL)
            return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES records");
    }
    st = walk(f, data, len, counts, 0);
    if (st != PROJCURVE_OK)
        return st;
    st = check_terminate(f);
    if (st != PROJCURVE_OK)
        return st;
    if (f->sec[1].count == 0)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "IGES: no global (G) section");
    if (f->sec[2].count % 2 != 0)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                       "IGES: the directory has %zu records, an odd number (two per entity)",
                       f->sec[2].count);
    return PROJCURVE_OK;
}
