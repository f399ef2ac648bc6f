/* SPDX-License-Identifier: BSD-3-Clause */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "io/io_text.h"
#include "io/step.h"

static int is_name_char(char c)
{
    return isalnum((unsigned char)c) || c == '_' || c == '-';
}

/* Skips blanks and comments; counts lines when line != NULL. */
static size_t skip_blank(const char *s, size_t len, size_t pos, size_t *line)
{
    while (pos < len) {
        const char c = s[pos];
        if (c == '\n') {
            if (line)
                ++*line;
            ++pos;
        } else if (isspace((unsigned char)c)) {
            ++pos;
        } else if (c == '/' && pos + 1 < len && s[pos + 1] == '*') {
            pos += 2;
            while (pos + 1 < len && !(s[pos] == '*' && s[pos + 1] == '/')) {
                if (line && s[pos] == '\n')
                    ++*line;
                ++pos;
            }
            pos = pos + 2 < len ? pos + 2 : len;
        } else {
            break;
        }
    }
    return pos;
}

/* Position of the ';' ending the record that starts at pos (outside strings
 * and comments), or len. */
static size_t record_end(const char *s, size_t len, size_t pos, size_t *line)
{
    while (pos < len) {
        const char c = s[pos];
        if (c == ';')
            return pos;
        if (c == '\'') {
            for (++pos; pos < len; ++pos) {
                if (s[pos] == '\n')
                    ++*line;
                if (s[pos] == '\'') {
                    if (pos + 1 < len && s[pos + 1] == '\'')
                        ++pos;
                    else
                        break;
                }
            }
            ++pos;
        } else if (c == '/' && pos + 1 < len && s[pos + 1] == '*') {
            pos = skip_blank(s, len, pos, line);
        } else {
            *line += (c == '\n');
            ++pos;
        }
    }
    return len;
}

static int by_id(const void *a, const void *b)
{
    const long x = ((const pc_step_instance *)a)->id, y = ((const pc_step_instance *)b)->id;
    return (x > y) - (x < y);
}

/* Finds "DATA;" at the start of a statement. */
static size_t data_section(const char *s, size_t len, size_t *line)
{
    size_t pos = 0;
    while (pos < len) {
        pos = skip_blank(s, len, pos, line);
        if (pos + 5 <= len && memcmp(s + pos, "DATA", 4) == 0) {
            const size_t q = skip_blank(s, len, pos + 4, line);
            if (q < len && (s[q] == ';' || s[q] == '('))
                return record_end(s, len, q, line) + 1;
        }
        pos = record_end(s, len, pos, line) + 1;
    }
    return len;
}

projcurve_status pc_step_index(pc_step_file *f)
{
    const char *s = f->text;
    const size_t len = f->len;
    size_t line = 1;
    size_t pos = data_section(s, len, &line);
    if (pos >= len)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP: no DATA section");
    size_t cap = 0;
    f->instances = NULL;
    f->n_instances = 0;
    int sorted = 1;
    for (;;) {
        pos = skip_blank(s, len, pos, &line);
        if (pos >= len)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP line %zu: DATA section without ENDSEC",
                           line);
        if (len - pos >= 6 && memcmp(s + pos, "ENDSEC", 6) == 0)
            break;
        const size_t start_line = line;
        if (s[pos] != '#')
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "STEP line %zu: expected an instance '#n = ...' or ENDSEC", line);
        char *end = NULL;
        const long id = strtol(s + pos + 1, &end, 10);
        if (end == s + pos + 1 || id <= 0)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP line %zu: bad instance number",
                           line);
        pos = skip_blank(s, len, (size_t)(end - s), &line);
        if (pos >= len || s[pos] != '=')
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP line %zu: '=' missing after #%ld",
                           line, id);
        const size_t begin = pos + 1;
        const size_t stop = record_end(s, len, begin, &line);
        if (stop >= len)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE,
                           "STEP line %zu: instance #%ld is not ended by ';'", start_line, id);
        void *items = f->instances;
        const projcurve_status grown =
            pc_array_reserve(f->ctx, &items, &cap, f->n_instances, f->n_instances + 1,
                             sizeof *f->instances, 1024, NULL, "the STEP instance index");
        if (grown != PROJCURVE_OK)
            return grown;
        f->instances = items;
        if (f->n_instances > 0 && f->instances[f->n_instances - 1].id >= id)
            sorted = 0;
        f->instances[f->n_instances++] =
            (pc_step_instance){.id = id, .begin = begin, .end = stop, .line = start_line};
        pos = stop + 1;
    }
    if (!sorted && f->n_instances > 1)
        qsort(f->instances, f->n_instances, sizeof *f->instances, by_id);
    for (size_t i = 1; i < f->n_instances; ++i)
        if (f->instances[i].id == f->instances[i - 1].id)
            return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP line %zu: instance #%ld defined twice",
                           f->instances[i].line, f->instances[i].id);
    return PROJCURVE_OK;
}

void pc_step_index_free(pc_step_file *f)
{
    free(f->instances);
    f->instances = NULL;
    f->n_instances = 0;
}

const pc_step_instance *pc_step_find(const pc_step_file *f, long id)
{
    size_t lo = 0, hi = f->n_instances;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (f->instances[mid].id < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return (lo < f->n_instances && f->instances[lo].id == id) ? &f->instances[lo] : NULL;
}

/* ---- values ------------------------------------------------------------ */

typedef struct parser {
    const pc_step_file *f;
    const pc_step_instance *inst;
    pc_arena *arena;
    size_t pos, end;
} parser;

static projcurve_status syntax(const parser *p, const char *what)
{
    return pc_fail(p->f->ctx, PROJCURVE_ERR_PARSE, "STEP instance #%ld (line %zu): %s",
                   p->inst->id, p->inst->line, what);
}

static pc_step_node *new_node(parser *p, pc_step_kind kind)
{
    pc_step_node *n = pc_arena_calloc(p->arena, 1, sizeof *n);
    if (n != NULL)
        n->kind = kind;
    return n;
}

static void skip(parser *p)
{
    p->pos = skip_blank(p->f->text, p->end, p->pos, NULL);
}

static projcurve_status value(parser *p, int depth, pc_step_node **out);

/* '(' value, value, ... ')' into the children of parent. */
static projcurve_status list_items(parser *p, int depth, pc_step_node *parent)
{
    const char *s = p->f->text;
    ++p->pos; /* '(' */
    skip(p);
    pc_step_node **tail = &parent->first;
    if (p->pos < p->end && s[p->pos] == ')') {
        ++p->pos;
        return PROJCURVE_OK;
    }
    for (;;) {
        pc_step_node *child;
        projcurve_status st = value(p, depth + 1, &child);
        if (st != PROJCURVE_OK)
            return st;
        *tail = child;
        tail = &child->next;
        ++parent->n_children;
        skip(p);
        if (p->pos >= p->end)
            return syntax(p, "a list is not closed");
        if (s[p->pos] == ')') {
            ++p->pos;
            return PROJCURVE_OK;
        }
        if (s[p->pos] != ',')
            return syntax(p, "expected ',' or ')' in a list");
        ++p->pos;
    }
}

static projcurve_status typed(parser *p, int depth, pc_step_node **out)
{
    const char *s = p->f->text;
    const size_t start = p->pos;
    while (p->pos < p->end && is_name_char(s[p->pos]))
        ++p->pos;
    pc_step_node *n = new_node(p, PC_STEP_TYPED);
    if (n == NULL)
        return pc_fail(p->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory parsing STEP");
    n->text = s + start;
    n->len = p->pos - start;
    skip(p);
    if (p->pos >= p->end || s[p->pos] != '(')
        return syntax(p, "expected '(' after a type name");
    *out = n;
    return list_items(p, depth, n);
}

static projcurve_status out_of_memory(const parser *p)
{
    return pc_fail(p->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory parsing STEP");
}

/* '...' (with '' for a quote) or "..." (binary): the text between. */
static projcurve_status string_value(parser *p, pc_step_node *n)
{
    const char *s = p->f->text;
    const char quote = s[p->pos];
    const size_t start = ++p->pos;
    while (p->pos < p->end) {
        if (s[p->pos] == quote) {
            if (quote == '\'' && p->pos + 1 < p->end && s[p->pos + 1] == '\'') {
                p->pos += 2;
                continue;
            }
            break;
        }
        ++p->pos;
    }
    if (p->pos >= p->end)
        return syntax(p, "a string is not closed");
    n->text = s + start;
    n->len = p->pos - start;
    ++p->pos;
    return PROJCURVE_OK;
}

/* .NAME. */
static projcurve_status enum_value(parser *p, pc_step_node *n)
{
    const char *s = p->f->text;
    const size_t start = ++p->pos;
    while (p->pos < p->end && is_name_char(s[p->pos]))
        ++p->pos;
    if (p->pos >= p->end || s[p->pos] != '.')
        return syntax(p, "an enumeration is not closed by '.'");
    n->text = s + start;
    n->len = p->pos - start;
    ++p->pos;
    return PROJCURVE_OK;
}

static projcurve_status ref_value(parser *p, pc_step_node *n)
{
    const char *s = p->f->text;
    char *e = NULL;
    const long id = strtol(s + p->pos + 1, &e, 10);
    if (e == s + p->pos + 1 || (size_t)(e - s) > p->end)
        return syntax(p, "bad reference");
    n->ref = id;
    p->pos = (size_t)(e - s);
    return PROJCURVE_OK;
}

static projcurve_status number_value(parser *p, pc_step_node *n)
{
    const size_t used = pc_text_parse_real(p->f->text + p->pos, p->end - p->pos, &n->number);
    if (used == 0)
        return syntax(p, "a number is malformed");
    p->pos += used;
    return PROJCURVE_OK;
}

static projcurve_status value(parser *p, int depth, pc_step_node **out)
{
    if (depth > PC_STEP_MAX_DEPTH)
        return syntax(p, "values nested too deeply");
    skip(p);
    if (p->pos >= p->end)
        return syntax(p, "a value is missing");
    const char c = p->f->text[p->pos];
    if (isalpha((unsigned char)c) || c == '_')
        return typed(p, depth, out);
    pc_step_kind kind;
    if (c == '(')
        kind = PC_STEP_LIST;
    else if (c == '$' || c == '*')
        kind = c == '$' ? PC_STEP_OMITTED : PC_STEP_DERIVED;
    else if (c == '#')
        kind = PC_STEP_REF;
    else if (c == '\'' || c == '"')
        kind = PC_STEP_STRING;
    else if (c == '.')
        kind = PC_STEP_ENUM;
    else if (isdigit((unsigned char)c) || c == '-' || c == '+')
        kind = PC_STEP_NUMBER;
    else
        return syntax(p, "unexpected character");
    pc_step_node *n = new_node(p, kind);
    if (n == NULL)
        return out_of_memory(p);
    *out = n;
    switch (kind) {
    case PC_STEP_LIST: return list_items(p, depth, n);
    case PC_STEP_REF: return ref_value(p, n);
    case PC_STEP_STRING: return string_value(p, n);
    case PC_STEP_ENUM: return enum_value(p, n);
    case PC_STEP_NUMBER: return number_value(p, n);
    default: ++p->pos; return PROJCURVE_OK; /* $ or * */
    }
}

projcurve_status pc_step_parse(const pc_step_file *f, const pc_step_instance *inst,
                               pc_arena *arena, pc_step_node **out)
{
    parser p = {.f = f, .inst = inst, .arena = arena, .pos = inst->begin, .end = inst->end};
    if (f->work_done != NULL) {
        *f->work_done += inst->end - inst->begin;
        if (*f->work_done > f->work_limit)
            return syntax(&p, "the file refers to its instances too many times");
    }
    skip(&p);
    if (p.pos >= p.end)
        return syntax(&p, "empty instance");
    pc_step_node *n = NULL;
    projcurve_status st;
    if (f->text[p.pos] == '(') {
        /* Complex instance: a list of NAME(...) without commas. */
        n = new_node(&p, PC_STEP_COMPLEX);
        if (n == NULL)
            return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory parsing STEP");
        ++p.pos;
        pc_step_node **tail = &n->first;
        for (;;) {
            skip(&p);
            if (p.pos >= p.end)
                return syntax(&p, "complex instance is not closed");
            if (f->text[p.pos] == ')') {
                ++p.pos;
                break;
            }
            if (!isalpha((unsigned char)f->text[p.pos]))
                return syntax(&p, "expected a sub-entity NAME(...)");
            pc_step_node *part;
            if ((st = typed(&p, 1, &part)) != PROJCURVE_OK)
                return st;
            *tail = part;
            tail = &part->next;
            ++n->n_children;
        }
    } else {
        if (!isalpha((unsigned char)f->text[p.pos]))
            return syntax(&p, "expected an entity NAME(...)");
        if ((st = typed(&p, 0, &n)) != PROJCURVE_OK)
            return st;
    }
    skip(&p);
    if (p.pos != p.end)
        return syntax(&p, "text after the entity");
    *out = n;
    return PROJCURVE_OK;
}

const pc_step_node *pc_step_child(const pc_step_node *n, size_t i)
{
    if (n == NULL)
        return NULL;
    const pc_step_node *c = n->first;
    for (size_t k = 0; c != NULL && k < i; ++k)
        c = c->next;
    return c;
}

int pc_step_is(const pc_step_node *n, const char *name)
{
    const size_t len = strlen(name);
    return n != NULL && n->kind == PC_STEP_TYPED && n->len == len && memcmp(n->text, name, len) == 0;
}

const pc_step_node *pc_step_part(const pc_step_node *inst, const char *name)
{
    if (inst == NULL)
        return NULL;
    if (inst->kind == PC_STEP_TYPED)
        return pc_step_is(inst, name) ? inst : NULL;
    for (const pc_step_node *c = inst->first; c != NULL; c = c->next)
        if (pc_step_is(c, name))
            return c;
    return NULL;
}
