/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Small text scanning helpers shared by the text readers: numbers from a
 * NUL-terminated buffer with line tracking.
 */
#ifndef PC_IO_TEXT_H
#define PC_IO_TEXT_H

#include <stddef.h>

typedef struct pc_text_cursor {
    const char *s;
    size_t len;
    size_t pos;
    size_t line; /* 1-based line of s[pos] */
} pc_text_cursor;

void pc_text_init(pc_text_cursor *c, const char *s, size_t len);
/* Moves to pos (either way), counting line ends on the way. */
void pc_text_seek(pc_text_cursor *c, size_t pos);
/* Skips characters from `skip` (and NUL-free whitespace if include_space). */
void pc_text_skip(pc_text_cursor *c, const char *skip);
/* Reads a finite real number at the cursor (after skipping separators);
 * returns 0 and leaves the cursor where the number should start when there
 * is none. */
int pc_text_real(pc_text_cursor *c, const char *separators, double *out);
/* Parses the longest real at s[0..len) into *out (strtod rules, finite);
 * returns the number of characters used (0 if none). */
size_t pc_text_parse_real(const char *s, size_t len, double *out);

#endif /* PC_IO_TEXT_H */
