/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The per-call table of span derivative bounds (span_bound_table.h).
 */
#include "nurbs/span_bound_table.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "nurbs/span_bound.h"

/* 2^64 / golden ratio: multiplying by it and keeping the top bits spreads
 * consecutive and strided keys evenly (Knuth, TAOCP 3, 6.4); a plain
 * modulus maps spans a row apart to neighbouring slots. */
#define PC_FIBONACCI_HASH UINT64_C(11400714819323198485)

size_t pc_span_bound_table_slots(const pc_nurbs_surface *s)
{
    if (s->rational)
        return 0;
    const size_t spans = (s->n_u - (size_t)s->deg_u) * (s->n_v - (size_t)s->deg_v);
    size_t slots = 1;
    while (slots < spans && slots < PC_SPAN_BOUND_MAX_SLOTS)
        slots *= 2;
    return slots;
}

void pc_span_bound_table_init(pc_span_bound_table *t, pc_span_bound_entry *storage,
                              size_t n_slots)
{
    t->single = (pc_span_bound_entry){0};
    t->used = 0;
    if (storage == NULL || n_slots == 0 || (n_slots & (n_slots - 1)) != 0) {
        t->slots = &t->single;
        t->mask = 0;
        t->bits = 0;
        return;
    }
    t->slots = storage;
    t->mask = n_slots - 1;
    t->bits = 0;
    while (((size_t)1 << t->bits) < n_slots)
        ++t->bits;
}

static size_t home_slot(const pc_span_bound_table *t, const pc_nurbs_surface *s, size_t span_u,
                        size_t span_v)
{
    if (t->bits == 0)
        return 0;
    /* the span's index in the grid of spans */
    const uint64_t index = (uint64_t)(span_u - (size_t)s->deg_u) *
                               (uint64_t)(s->n_v - (size_t)s->deg_v) +
                           (uint64_t)(span_v - (size_t)s->deg_v);
    return (size_t)((index * PC_FIBONACCI_HASH) >> (64 - t->bits));
}

/* Computes the bounds of the span into e; 0 for a rational surface. */
static int fill(pc_span_bound_entry *e, const pc_nurbs_surface *s, size_t span_u, size_t span_v)
{
    double m2[3];
    if (!pc_span_bounds(s, span_u, span_v, m2, e->m3))
        return 0;
    e->m2_max = fmax(m2[0], fmax(m2[1], m2[2]));
    e->m3_max = fmax(fmax(e->m3[0], e->m3[1]), fmax(e->m3[2], e->m3[3]));
    e->span_u = span_u;
    e->span_v = span_v;
    e->box[0] = s->knots_u[span_u];
    e->box[1] = s->knots_u[span_u + 1];
    e->box[2] = s->knots_v[span_v];
    e->box[3] = s->knots_v[span_v + 1];
    e->valid = 1;
    return 1;
}

const pc_span_bound_entry *pc_span_bound_table_get(pc_span_bound_table *t,
                                                   const pc_nurbs_surface *s, size_t span_u,
                                                   size_t span_v)
{
    const size_t home = home_slot(t, s, span_u, span_v);
    size_t i = home, probes = 0;
    for (; probes <= t->mask; ++probes, i = (i + 1) & t->mask) {
        const pc_span_bound_entry *e = &t->slots[i];
        if (!e->valid)
            break;
        if (e->span_u == span_u && e->span_v == span_v)
            return e;
    }
    /* not there: three quarters full (or no free slot), start again empty,
     * so that probe sequences stay short */
    if (probes > t->mask || 4 * (t->used + 1) > 3 * (t->mask + 1)) {
        memset(t->slots, 0, (t->mask + 1) * sizeof *t->slots);
        t->used = 0;
        i = home;
    }
    pc_span_bound_entry *e = &t->slots[i];
    if (!fill(e, s, span_u, span_v)) {
        e->valid = 0;
        return NULL;
    }
    ++t->used;
    return e;
}
