/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Streaming JSON writer (see json.h).
 */
#include "json.h"

#include <math.h>

int pcb_json_open(pcb_json *json, const char *path)
{
    json->file = NULL;
    json->depth = 0;
    json->count[0] = 0;
    json->failed = 0;
    if (!path)
        return 0;
    json->file = fopen(path, "w");
    if (!json->file) {
        json->failed = 1;
        return -1;
    }
    return 0;
}

int pcb_json_close(pcb_json *json)
{
    if (json->file) {
        fputc('\n', json->file);
        if (ferror(json->file))
            json->failed = 1;
        if (fclose(json->file) != 0)
            json->failed = 1;
        json->file = NULL;
    }
    if (json->depth != 0)
        json->failed = 1;
    return json->failed ? -1 : 0;
}

static void write_string_literal(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; ++s) {
        const unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

/* Separator, indentation and member name before a value. */
static int begin_value(pcb_json *json, const char *key)
{
    if (!json->file || json->failed)
        return 0;
    FILE *f = json->file;
    if (json->depth > 0) {
        fputs(json->count[json->depth] > 0 ? ",\n" : "\n", f);
        for (int i = 0; i < json->depth; ++i)
            fputs("  ", f);
    }
    ++json->count[json->depth];
    if (key) {
        write_string_literal(f, key);
        fputs(": ", f);
    }
    return 1;
}

static void open_container(pcb_json *json, const char *key, char bracket)
{
    if (json->depth + 1 >= PCB_JSON_MAX_DEPTH) {
        json->failed = 1;
        return;
    }
    if (!begin_value(json, key))
        return;
    fputc(bracket, json->file);
    json->count[++json->depth] = 0;
}

static void close_container(pcb_json *json, char bracket)
{
    if (!json->file || json->failed)
        return;
    if (json->depth == 0) {
        json->failed = 1;
        return;
    }
    const int had_values = json->count[json->depth] > 0;
    --json->depth;
    if (had_values) {
        fputc('\n', json->file);
        for (int i = 0; i < json->depth; ++i)
            fputs("  ", json->file);
    }
    fputc(bracket, json->file);
}

void pcb_json_object_begin(pcb_json *json, const char *key) { open_container(json, key, '{'); }
void pcb_json_object_end(pcb_json *json) { close_container(json, '}'); }
void pcb_json_array_begin(pcb_json *json, const char *key) { open_container(json, key, '['); }
void pcb_json_array_end(pcb_json *json) { close_container(json, ']'); }

void pcb_json_number(pcb_json *json, const char *key, double value)
{
    if (!begin_value(json, key))
        return;
    if (isfinite(value))
        fprintf(json->file, "%.9g", value);
    else
        fputs("null", json->file);
}

void pcb_json_int(pcb_json *json, const char *key, long long value)
{
    if (begin_value(json, key))
        fprintf(json->file, "%lld", value);
}

void pcb_json_string(pcb_json *json, const char *key, const char *value)
{
    if (begin_value(json, key))
        write_string_literal(json->file, value ? value : "");
}

void pcb_json_null(pcb_json *json, const char *key)
{
    if (begin_value(json, key))
        fputs("null", json->file);
}
