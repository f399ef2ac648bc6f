/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The allocation hook of alloc_hook.h (compiled only with
 * PROJCURVE_ALLOC_HOOK; see there).
 */
#ifdef PC_ALLOC_HOOK
#include "common/alloc_hook.h"

/* The build force-included the header: here the names are the C library's. */
#undef malloc
#undef calloc
#undef realloc

/* Weak, so that a program that does not inject failures links without a
 * definition: the address is then NULL and nothing fails. */
extern int pc_alloc_hook_fail(const char *file, int line) __attribute__((weak));

static int should_fail(const char *file, int line)
{
    return pc_alloc_hook_fail != NULL && pc_alloc_hook_fail(file, line);
}

void *pc_alloc_hook_malloc(size_t size, const char *file, int line)
{
    return should_fail(file, line) ? NULL : malloc(size);
}

void *pc_alloc_hook_calloc(size_t n, size_t size, const char *file, int line)
{
    return should_fail(file, line) ? NULL : calloc(n, size);
}

void *pc_alloc_hook_realloc(void *p, size_t size, const char *file, int line)
{
    return should_fail(file, line) ? NULL : realloc(p, size);
}
#else
/* ISO C wants a translation unit to declare something. */
typedef int pc_alloc_hook_unused;
#endif
