/* SPDX-License-Identifier: BSD-3-Clause */
#include "io/io_file.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"

/* fread asks for at least this much at a time. */
#define PC_READ_CHUNK ((size_t)1 << 20)

typedef struct {
    char *items;
    size_t count, capacity;
} byte_array;

/* Reads fp to its end into *text (always with room for the NUL). */
static projcurve_status read_stream(projcurve_context *ctx, FILE *fp, const char *path,
                                    size_t max_bytes, byte_array *text)
{
    for (;;) {
        if (text->capacity - text->count < PC_READ_CHUNK + 1) {
            if (text->count > max_bytes)
                return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED, "%s is larger than %zu bytes",
                               path, max_bytes);
            projcurve_status st;
            PC_ARRAY_RESERVE(st, ctx, text, text->count + PC_READ_CHUNK + 1, 4 * PC_READ_CHUNK,
                             "the file's text");
            if (st != PROJCURVE_OK)
                return st;
        }
        errno = 0;
        const size_t room = text->capacity - text->count - 1;
        const size_t got = fread(text->items + text->count, 1, room, fp);
        text->count += got;
        if (got == 0) {
            if (ferror(fp))
                return pc_fail(ctx, PROJCURVE_ERR_IO, "error reading %s: %s", path,
                               strerror(errno));
            if (text->count > max_bytes)
                return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED, "%s is larger than %zu bytes",
                               path, max_bytes);
            return PROJCURVE_OK;
        }
    }
}

projcurve_status pc_read_file(projcurve_context *ctx, const char *path, size_t max_bytes,
                              char **text, size_t *len)
{
    *text = NULL;
    *len = 0;
    FILE *fp = fopen(path, "rb");
    if (fp == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_IO, "cannot open %s: %s", path, strerror(errno));
    byte_array bytes = {0};
    const projcurve_status st = read_stream(ctx, fp, path, max_bytes, &bytes);
    fclose(fp);
    if (st != PROJCURVE_OK) {
        PC_ARRAY_FREE(&bytes);
        return st;
    }
    bytes.items[bytes.count] = '\0';
    *text = bytes.items;
    *len = bytes.count;
    return PROJCURVE_OK;
}

projcurve_status pc_write_file(projcurve_context *ctx, const char *path, const char *text,
                               size_t len)
{
    FILE *fp = fopen(path, "wb");
    if (fp == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_IO, "cannot create %s: %s", path, strerror(errno));
    const size_t written = fwrite(text, 1, len, fp);
    const int closed = fclose(fp);
    if (written != len || closed != 0)
        return pc_fail(ctx, PROJCURVE_ERR_IO, "error writing %s", path);
    return PROJCURVE_OK;
}
