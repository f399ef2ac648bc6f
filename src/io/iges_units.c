/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES global section: the units flag (field 14), the units name (field 15)
 * and the minimum resolution (field 19, in model units), IGES 5.3 s2.2.4;
 * and the flag and name a writer gives a length unit.
 */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/iges.h"

#define PC_IGES_UNITS_FLAG 14
#define PC_IGES_UNITS_NAME 15
#define PC_IGES_RESOLUTION 19
/* The fields past the last one read are not split. */
#define PC_IGES_GLOBAL_FIELDS 20

typedef struct gfield {
    const char *text;
    size_t len;
} gfield;

/* The units flags 1 .. 11 (IGES 5.3 table 3): metres and unit name (field
 * 15); flag 3 names its unit in field 15 alone and has no entry. */
static const struct {
    double metres;
    const char *name;
} k_flags[] = {{0.0, NULL},      {0.0254, "IN"},  {0.001, "MM"}, {0.0, NULL},
               {0.3048, "FT"},   {1609.344, "MI"}, {1.0, "M"},    {1000.0, "KM"},
               {2.54e-5, "MIL"}, {1e-6, "UM"},    {0.01, "CM"},  {2.54e-8, "UIN"}};
#define PC_IGES_FLAG_COUNT ((int)(sizeof k_flags / sizeof *k_flags))
/* Two lengths in metres name the same unit when they agree to this
 * fraction: a unit computed from a STEP conversion factor (25.4 mm) carries
 * rounding of a few ulps. */
#define PC_IGES_UNIT_MATCH 1e-9

int pc_iges_unit_flag(double metres_per_unit)
{
    for (int flag = 1; flag < PC_IGES_FLAG_COUNT; ++flag)
        if (k_flags[flag].name != NULL &&
            fabs(metres_per_unit - k_flags[flag].metres) <=
                PC_IGES_UNIT_MATCH * k_flags[flag].metres)
            return flag;
    return 0;
}

const char *pc_iges_unit_name(int flag)
{
    return flag > 0 && flag < PC_IGES_FLAG_COUNT ? k_flags[flag].name : NULL;
}

/* Splits the global text into fields 1 .. n (Hollerith strings kept whole). */
static size_t split(const pc_iges_file *f, const char *g, size_t len, gfield *out, size_t max)
{
    size_t n = 0, pos = 0;
    while (n < max && pos < len) {
        while (pos < len && g[pos] == ' ')
            ++pos;
        size_t q = pos, count = 0;
        while (q < len && isdigit((unsigned char)g[q]) && q - pos < 9)
            count = count * 10 + (size_t)(g[q++] - '0');
        if (q > pos && q < len && g[q] == 'H' && count <= len - q - 1) {
            out[n++] = (gfield){g + q + 1, count};
            pos = q + 1 + count;
        } else {
            const size_t start = pos;
            while (pos < len && g[pos] != f->param_delim && g[pos] != f->record_delim)
                ++pos;
            size_t end = pos;
            while (end > start && g[end - 1] == ' ')
                --end;
            out[n++] = (gfield){g + start, end - start};
        }
        while (pos < len && g[pos] == ' ')
            ++pos;
        if (pos >= len || g[pos] == f->record_delim)
            break;
        ++pos; /* the parameter delimiter */
    }
    return n;
}

static int number(const gfield *fd, double *out)
{
    char buf[64];
    size_t n = 0;
    for (size_t k = 0; k < fd->len && n + 1 < sizeof buf; ++k)
        if (fd->text[k] != ' ')
            buf[n++] = (fd->text[k] == 'D' || fd->text[k] == 'd') ? 'E' : fd->text[k];
    buf[n] = '\0';
    char *end = NULL;
    const double v = strtod(buf, &end);
    if (n == 0 || end != buf + n || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

static int field_is(const gfield *fd, const char *name)
{
    return fd->len == strlen(name) && memcmp(fd->text, name, fd->len) == 0;
}

/* The metres of a unit name (field 15): a flag's name, or INCH. */
static double named_unit(const gfield *fd)
{
    if (field_is(fd, "INCH"))
        return k_flags[1].metres;
    for (int flag = 1; flag < PC_IGES_FLAG_COUNT; ++flag)
        if (k_flags[flag].name != NULL && field_is(fd, k_flags[flag].name))
            return k_flags[flag].metres;
    return 0.0;
}

projcurve_status pc_iges_read_units(const pc_iges_file *f, projcurve_model *model)
{
    const pc_iges_section *g = &f->sec[1];
    char *text = pc_arena_alloc(f->arena, g->count * PC_IGES_DATA_COLUMNS + 1);
    if (text == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading the IGES global section");
    size_t len = 0;
    for (size_t r = 0; r < g->count; ++r) {
        memcpy(text + len, g->records[r], PC_IGES_DATA_COLUMNS);
        len += PC_IGES_DATA_COLUMNS;
    }
    gfield fields[PC_IGES_GLOBAL_FIELDS];
    const size_t n = split(f, text, len, fields, PC_IGES_GLOBAL_FIELDS);
    double flag = 0.0, resolution = 0.0, metres = 0.0;
    if (n >= PC_IGES_UNITS_FLAG && number(&fields[PC_IGES_UNITS_FLAG - 1], &flag) &&
        flag >= 1.0 && flag <= 11.0 && flag == floor(flag))
        metres = k_flags[(int)flag].metres;
    if (metres == 0.0 && n >= PC_IGES_UNITS_NAME)
        metres = named_unit(&fields[PC_IGES_UNITS_NAME - 1]);
    if (metres > 0.0) {
        model->metres_per_unit = metres;
        model->has_length_unit = 1;
    }
    if (n >= PC_IGES_RESOLUTION && number(&fields[PC_IGES_RESOLUTION - 1], &resolution) &&
        resolution > 0.0) {
        model->precision = resolution;
        model->has_precision = 1;
    }
    return PROJCURVE_OK;
}
