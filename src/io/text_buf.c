/* SPDX-License-Identifier: BSD-3-Clause */
#include "io/text_buf.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"

/* Room for a real of 17 digits, sign, point, exponent and the point added. */
#define PC_TEXT_REAL_CHARS 40
/* Formatted pieces up to this length are formatted on the stack. */
#define PC_TEXT_PRINTF_STACK 256

void pc_text_buf_append(pc_text_buf *b, const char *s, size_t n)
{
    if (b->failed)
        return;
    void *items = b->text;
    /* no context here: a failure is the buffer's flag, which its writer
     * reports with the context it has */
    if (pc_array_reserve(NULL, &items, &b->cap, b->len, b->len + n + 1, 1, 256, NULL,
                         "written text") != PROJCURVE_OK) {
        b->failed = 1;
        return;
    }
    b->text = items;
    memcpy(b->text + b->len, s, n);
    b->len += n;
    b->text[b->len] = '\0';
}

void pc_text_buf_puts(pc_text_buf *b, const char *s)
{
    pc_text_buf_append(b, s, strlen(s));
}

void pc_text_buf_printf(pc_text_buf *b, const char *fmt, ...)
{
    char local[PC_TEXT_PRINTF_STACK];
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(local, sizeof local, fmt, ap);
    va_end(ap);
    if (n < 0) {
        b->failed = 1;
        return;
    }
    if ((size_t)n < sizeof local) {
        pc_text_buf_append(b, local, (size_t)n);
        return;
    }
    char *big = malloc((size_t)n + 1);
    if (big == NULL) {
        b->failed = 1;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(big, (size_t)n + 1, fmt, ap);
    va_end(ap);
    pc_text_buf_append(b, big, (size_t)n);
    free(big);
}

void pc_text_buf_real(pc_text_buf *b, double v)
{
    char s[PC_TEXT_REAL_CHARS];
    int n = snprintf(s, sizeof s, "%.17G", v);
    /* "1E-05" -> "1.E-05", "3" -> "3.". */
    if (strchr(s, '.') == NULL) {
        char *e = strchr(s, 'E');
        const size_t at = e ? (size_t)(e - s) : (size_t)n;
        memmove(s + at + 1, s + at, (size_t)n - at + 1);
        s[at] = '.';
        ++n;
    }
    pc_text_buf_append(b, s, (size_t)n);
}

void pc_text_buf_truncate(pc_text_buf *b, size_t len)
{
    if (b->text != NULL && len < b->len) {
        b->len = len;
        b->text[len] = '\0';
    }
}

void pc_text_buf_free(pc_text_buf *b)
{
    free(b->text);
    b->text = NULL;
    b->len = b->cap = 0;
}
