/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growing text of the writers (IGES, STEP): appended to piece by
 * piece, always NUL-terminated, grown by common/array.h. An allocation
 * failure sets `failed` and makes every later append a no-op, so a writer
 * formats a whole entity and checks once; the text stays as it was before
 * the failing append.
 */
#ifndef PC_IO_TEXT_BUF_H
#define PC_IO_TEXT_BUF_H

#include <stddef.h>

typedef struct pc_text_buf {
    char *text; /* NULL until the first append */
    size_t len, cap;
    int failed; /* an allocation failed */
} pc_text_buf;

void pc_text_buf_append(pc_text_buf *b, const char *s, size_t n);
void pc_text_buf_puts(pc_text_buf *b, const char *s);
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void pc_text_buf_printf(pc_text_buf *b, const char *fmt, ...);
/* A finite real with 17 significant digits (which round-trips every
 * double) and always a decimal point, as IGES and STEP (ISO 10303-21
 * s6.4.2) ask: "3." for 3, "1.E-05" for 1e-5, "-0." for -0. */
void pc_text_buf_real(pc_text_buf *b, double v);
/* Cuts the text back to len characters (len <= b->len). */
void pc_text_buf_truncate(pc_text_buf *b, size_t len);
/* Releases the text and empties the buffer. */
void pc_text_buf_free(pc_text_buf *b);

#endif /* PC_IO_TEXT_BUF_H */
