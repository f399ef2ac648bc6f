/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A small streaming JSON writer for benchmark results. Every value call
 * takes the member name when it is written inside an object (NULL inside an
 * array or at the top). Non-finite numbers are written as null, so that the
 * output is always valid JSON. Errors are sticky: pcb_json_close reports
 * whether everything was written.
 */
#ifndef PCB_JSON_H
#define PCB_JSON_H

#include <stdio.h>

#define PCB_JSON_MAX_DEPTH 16

typedef struct pcb_json {
    FILE *file;
    int depth;
    int count[PCB_JSON_MAX_DEPTH];  /* values written at each level */
    int failed;
} pcb_json;

/* Opens path for writing (NULL path: a writer that writes nothing).
 * Returns 0 or -1. */
int pcb_json_open(pcb_json *json, const char *path);
/* Closes the file; returns 0 if every value was written, -1 otherwise. */
int pcb_json_close(pcb_json *json);

void pcb_json_object_begin(pcb_json *json, const char *key);
void pcb_json_object_end(pcb_json *json);
void pcb_json_array_begin(pcb_json *json, const char *key);
void pcb_json_array_end(pcb_json *json);
void pcb_json_number(pcb_json *json, const char *key, double value);
void pcb_json_int(pcb_json *json, const char *key, long long value);
void pcb_json_string(pcb_json *json, const char *key, const char *value);
void pcb_json_null(pcb_json *json, const char *key);

#endif /* PCB_JSON_H */
