/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A bump allocator owned by one call: temporary data of a projection is
 * taken from it and released at once at the end, so error paths cannot leak
 * and the tracing loop does not call malloc per step.
 */
#ifndef PC_COMMON_ARENA_H
#define PC_COMMON_ARENA_H

#include <stddef.h>

typedef struct pc_arena_block pc_arena_block;

typedef struct pc_arena {
    pc_arena_block *head; /* most recent block */
    size_t block_size;    /* default size of new blocks */
} pc_arena;

/* An empty arena; nothing is allocated until the first pc_arena_alloc. */
void pc_arena_init(pc_arena *arena, size_t block_size);

/* size bytes aligned for any type, or NULL when memory runs out (or the size
 * overflows). The memory is not zeroed. */
void *pc_arena_alloc(pc_arena *arena, size_t size);

/* n * size bytes, zeroed; NULL on overflow or when memory runs out. */
void *pc_arena_calloc(pc_arena *arena, size_t n, size_t size);

/* Releases every block. The arena can be used again afterwards. */
void pc_arena_release(pc_arena *arena);

#endif /* PC_COMMON_ARENA_H */
