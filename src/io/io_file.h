/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A whole file into memory, NUL-terminated (the readers rely on the NUL:
 * strtod and friends), with a size ceiling so that a huge or endless input
 * (a FIFO, /dev/zero) is refused instead of exhausting memory; and a text
 * out to a file (the writers).
 */
#ifndef PC_IO_FILE_H
#define PC_IO_FILE_H

#include <stddef.h>

#include "projcurve.h"

/* Reads path into *text (malloc'd, text[*len] == '\0'; the caller frees
 * it). Statuses: OK; IO (cannot open or read, with strerror); UNSUPPORTED
 * (more than max_bytes); NO_MEMORY. On failure *text is NULL. */
projcurve_status pc_read_file(projcurve_context *ctx, const char *path, size_t max_bytes,
                              char **text, size_t *len);

/* Writes text[0..len) to path, replacing it. Statuses: OK; IO (cannot
 * create, or a short write or failed close, naming the path). */
projcurve_status pc_write_file(projcurve_context *ctx, const char *path, const char *text,
                               size_t len);

#endif /* PC_IO_FILE_H */
