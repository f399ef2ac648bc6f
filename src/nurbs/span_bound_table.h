/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The derivative bounds of the knot spans a projection visits
 * (span_bound.h), kept for the whole call: the corrector asks for the bound
 * of the span of every point it accepts, the refinement passes over the
 * branch several times, and a bound costs about thirty evaluations.
 *
 * An open-addressing hash table (linear probing) over storage the caller
 * owns; filled three quarters, it starts again empty. Without storage it
 * keeps the last span only.
 */
#ifndef PC_NURBS_SPAN_BOUND_TABLE_H
#define PC_NURBS_SPAN_BOUND_TABLE_H

#include <stddef.h>

#include "nurbs/nurbs.h"

/* The derivative bounds of one knot span and its parameter box. */
typedef struct pc_span_bound_entry {
    int valid;
    size_t span_u, span_v;
    double m3[4];          /* third derivatives, span_bound.h */
    double m2_max, m3_max; /* largest second / third derivative bound */
    double box[4];         /* the span: u0, u1, v0, v1 */
} pc_span_bound_entry;

/* Largest table (a power of 2) worth allocating. */
#define PC_SPAN_BOUND_MAX_SLOTS 256

typedef struct pc_span_bound_table {
    pc_span_bound_entry *slots;
    size_t mask;   /* slots - 1 */
    size_t used;   /* valid entries */
    int bits;      /* log2 of the number of slots */
    pc_span_bound_entry single; /* the storage without the caller's */
} pc_span_bound_table;

/* Entries worth giving the table of a surface: its number of spans rounded
 * up to a power of 2, at most PC_SPAN_BOUND_MAX_SLOTS; 0 for a rational
 * surface (no bounds). */
size_t pc_span_bound_table_slots(const pc_nurbs_surface *s);

/* An empty table on `storage` (n_slots zero-filled entries, a power of 2,
 * outliving the table), or on its own single entry when storage is NULL. */
void pc_span_bound_table_init(pc_span_bound_table *t, pc_span_bound_entry *storage,
                              size_t n_slots);

/* The bounds of span (span_u, span_v) of s, computed on the first request;
 * NULL for a rational surface. The entry stays valid until the next call. */
const pc_span_bound_entry *pc_span_bound_table_get(pc_span_bound_table *t,
                                                   const pc_nurbs_surface *s, size_t span_u,
                                                   size_t span_v);

#endif /* PC_NURBS_SPAN_BOUND_TABLE_H */
