/* SPDX-License-Identifier: BSD-3-Clause */
#include "io/io_text.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Longest number text considered (anything longer is not a number here). */
#define PC_TEXT_MAX_NUMBER 64

void pc_text_init(pc_text_cursor *c, const char *s, size_t len)
{
    c->s = s;
    c->len = len;
    c->pos = 0;
    c->line = 1;
}

void pc_text_seek(pc_text_cursor *c, size_t pos)
{
    if (pos > c->len)
        pos = c->len;
    for (; c->pos < pos; ++c->pos)
        c->line += (c->s[c->pos] == '\n');
    for (; c->pos > pos; --c->pos)
        c->line -= (c->s[c->pos - 1] == '\n');
}

void pc_text_skip(pc_text_cursor *c, const char *skip)
{
    while (c->pos < c->len && c->s[c->pos] != '\0' && strchr(skip, c->s[c->pos]) != NULL) {
        c->line += (c->s[c->pos] == '\n');
        ++c->pos;
    }
}

size_t pc_text_parse_real(const char *s, size_t len, double *out)
{
    char buf[PC_TEXT_MAX_NUMBER + 1];
    size_t n = 0;
    while (n < len && n < PC_TEXT_MAX_NUMBER &&
           (isdigit((unsigned char)s[n]) || strchr("+-.eE", s[n]) != NULL) && s[n] != '\0')
        ++n;
    if (n == 0)
        return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    char *end = NULL;
    const double v = strtod(buf, &end);
    if (end == buf || !isfinite(v))
        return 0;
    *out = v;
    return (size_t)(end - buf);
}

int pc_text_real(pc_text_cursor *c, const char *separators, double *out)
{
    pc_text_skip(c, separators);
    const size_t used = pc_text_parse_real(c->s + c->pos, c->len - c->pos, out);
    if (used == 0)
        return 0;
    c->pos += used;
    return 1;
}
