/* SPDX-License-Identifier: BSD-3-Clause */
#include "arena.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct pc_arena_block {
    pc_arena_block *next;
    size_t used;
    size_t capacity;
    max_align_t data[];
};

#define PC_ARENA_ALIGN (sizeof(max_align_t))

void pc_arena_init(pc_arena *arena, size_t block_size)
{
    arena->head = NULL;
    arena->block_size = block_size < 4096 ? 4096 : block_size;
}

static pc_arena_block *arena_new_block(size_t capacity)
{
    if (capacity > SIZE_MAX - sizeof(pc_arena_block))
        return NULL;
    pc_arena_block *block = malloc(sizeof(pc_arena_block) + capacity);
    if (block == NULL)
        return NULL;
    block->next = NULL;
    block->used = 0;
    block->capacity = capacity;
    return block;
}

void *pc_arena_alloc(pc_arena *arena, size_t size)
{
    if (size > SIZE_MAX - PC_ARENA_ALIGN)
        return NULL;
    const size_t rounded = (size + PC_ARENA_ALIGN - 1) / PC_ARENA_ALIGN * PC_ARENA_ALIGN;
    pc_arena_block *block = arena->head;
    if (block == NULL || block->capacity - block->used < rounded) {
        const size_t capacity = rounded > arena->block_size ? rounded : arena->block_size;
        pc_arena_block *fresh = arena_new_block(capacity);
        if (fresh == NULL)
            return NULL;
        fresh->next = arena->head;
        arena->head = fresh;
        block = fresh;
    }
    void *p = (unsigned char *)block->data + block->used;
    block->used += rounded;
    return p;
}

void *pc_arena_calloc(pc_arena *arena, size_t n, size_t size)
{
    if (size != 0 && n > SIZE_MAX / size)
        return NULL;
    void *p = pc_arena_alloc(arena, n * size);
    if (p != NULL)
        memset(p, 0, n * size);
    return p;
}

void pc_arena_release(pc_arena *arena)
{
    pc_arena_block *block = arena->head;
    while (block != NULL) {
        pc_arena_block *next = block->next;
        free(block);
        block = next;
    }
    arena->head = NULL;
}
