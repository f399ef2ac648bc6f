/* SPDX-License-Identifier: BSD-3-Clause */
#include "open_cases.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *copy_of(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (c != NULL) {
        memcpy(c, s, n);
        c[n] = '\0';
    }
    return c;
}

static int add_line(pc_open_cases *list, const char *line, size_t *cap)
{
    const char *tab = strchr(line, '\t');
    if (tab == NULL)
        return -1;
    if (list->count == *cap) {
        const size_t grown = *cap ? 2 * *cap : 64;
        pc_open_case *items = realloc(list->items, grown * sizeof *items);
        if (items == NULL)
            return -1;
        list->items = items;
        *cap = grown;
    }
    char padded[512];
    snprintf(padded, sizeof padded, " %s ", tab + 1);
    pc_open_case *c = &list->items[list->count];
    c->key = copy_of(line, (size_t)(tab - line));
    c->classes = copy_of(padded, strlen(padded));
    c->seen = c->passed = 0;
    if (c->key == NULL || c->classes == NULL) {
        free(c->key);
        free(c->classes);
        return -1;
    }
    ++list->count;
    return 0;
}

int pc_open_cases_read(const char *path, pc_open_cases *out)
{
    *out = (pc_open_cases){0};
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return 0;
    char line[1024];
    size_t cap = 0, number = 0;
    int status = 0;
    while (status == 0 && fgets(line, sizeof line, f) != NULL) {
        ++number;
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '\0' || line[0] == '#')
            continue;
        if (add_line(out, line, &cap) != 0) {
            fprintf(stderr, "%s:%zu: malformed open case (key TAB classes) or no memory\n",
                    path, number);
            status = -1;
        }
    }
    fclose(f);
    return status;
}

pc_open_case *pc_open_cases_find(const pc_open_cases *list, const char *key)
{
    for (size_t k = 0; k < list->count; ++k)
        if (strcmp(list->items[k].key, key) == 0)
            return &list->items[k];
    return NULL;
}

int pc_open_case_allows(const pc_open_case *c, const char *class_name)
{
    char needle[64];
    snprintf(needle, sizeof needle, " %s ", class_name);
    return strstr(c->classes, needle) != NULL;
}

void pc_open_cases_free(pc_open_cases *list)
{
    for (size_t k = 0; k < list->count; ++k) {
        free(list->items[k].key);
        free(list->items[k].classes);
    }
    free(list->items);
    *list = (pc_open_cases){0};
}
