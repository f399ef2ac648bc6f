/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Allocation-failure injection, for test builds only (the CMake option
 * PROJCURVE_ALLOC_HOOK). The build force-includes this header into every
 * library source, so that each malloc, calloc and realloc of the library
 * goes through one hook that names its call site; the hook asks
 * pc_alloc_hook_fail, which a test program defines (the library has only a
 * weak, absent one), whether this call fails. A release build has neither
 * the header nor the hook: the allocations are the C library's own.
 *
 * The redirection is by macro, not by interposing the C library's symbols,
 * so that it works under AddressSanitizer (which interposes them itself)
 * and touches only the library's own calls.
 */
#ifndef PC_COMMON_ALLOC_HOOK_H
#define PC_COMMON_ALLOC_HOOK_H

/* <stdlib.h> is read here, before the macros below rename the calls, and
 * so before a source's own feature macros: the one the sources use (for
 * clock_gettime and mkdir) is set first, to the same value. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <stddef.h>
#include <stdlib.h>

/* Defined by a test program: nonzero makes this allocation fail (return
 * NULL). file and line name the call site. Absent (weak) in the library. */
int pc_alloc_hook_fail(const char *file, int line);

void *pc_alloc_hook_malloc(size_t size, const char *file, int line);
void *pc_alloc_hook_calloc(size_t n, size_t size, const char *file, int line);
void *pc_alloc_hook_realloc(void *p, size_t size, const char *file, int line);

#define malloc(size) pc_alloc_hook_malloc((size), __FILE__, __LINE__)
#define calloc(n, size) pc_alloc_hook_calloc((n), (size), __FILE__, __LINE__)
#define realloc(p, size) pc_alloc_hook_realloc((p), (size), __FILE__, __LINE__)

#endif /* PC_COMMON_ALLOC_HOOK_H */
