/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growable array of common/array.h: every element pushed is kept in
 * order; the capacity doubles from the minimum (so n pushes make
 * ceil(log2(n / min)) + 1 allocations); a size whose byte count overflows
 * size_t is NO_MEMORY with a message and leaves the array as it was;
 * borrowed storage is copied, never freed or reallocated.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "common/array.h"

typedef struct int_array {
    int *items;
    size_t count, capacity;
} int_array;

#define N_PUSH 1000
#define MIN_CAPACITY 8

static void test_push_and_growth(void)
{
    int_array a = {0};
    size_t growths = 0, last_capacity = 0;
    for (int k = 0; k < N_PUSH; ++k) {
        projcurve_status st;
        PC_ARRAY_RESERVE(st, NULL, &a, a.count + 1, MIN_CAPACITY, "a test array");
        CHECK_OK(st);
        if (a.capacity != last_capacity) {
            /* the first growth takes the minimum, each later one doubles */
            CHECK(a.capacity == (last_capacity == 0 ? MIN_CAPACITY : 2 * last_capacity));
            last_capacity = a.capacity;
            ++growths;
        }
        a.items[a.count++] = 3 * k;
    }
    for (int k = 0; k < N_PUSH; ++k)
        CHECK(a.items[k] == 3 * k);
    /* 8, 16, ..., 1024: 8 allocations for 1000 elements */
    printf("%d pushes: capacity %zu after %zu growths\n", N_PUSH, a.capacity, growths);
    CHECK(a.capacity == 1024 && growths == 8);
    /* a reserve within the capacity changes nothing */
    int *before = a.items;
    projcurve_status st;
    PC_ARRAY_RESERVE(st, NULL, &a, a.capacity, MIN_CAPACITY, "a test array");
    CHECK_OK(st);
    CHECK(a.items == before && a.capacity == 1024);
    PC_ARRAY_FREE(&a);
    CHECK(a.items == NULL && a.count == 0 && a.capacity == 0);
}

static void test_overflow(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    int_array a = {0};
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, &a, 4, MIN_CAPACITY, "a test array");
    CHECK_OK(st);
    a.items[a.count++] = 7;
    int *const before = a.items;
    const size_t cap_before = a.capacity;
    /* need * sizeof(int) overflows size_t: refused before any allocation */
    PC_ARRAY_RESERVE(st, ctx, &a, SIZE_MAX / sizeof(int) + 1, MIN_CAPACITY, "a test array");
    CHECK(st == PROJCURVE_ERR_NO_MEMORY);
    printf("message: %s\n", projcurve_context_message(ctx));
    CHECK(strstr(projcurve_context_message(ctx), "a test array") != NULL);
    CHECK(a.items == before && a.capacity == cap_before && a.count == 1 && a.items[0] == 7);
    /* the largest need whose doubling would pass SIZE_MAX / elem_size */
    PC_ARRAY_RESERVE(st, ctx, &a, SIZE_MAX / sizeof(int) / 2 + 2, MIN_CAPACITY, "a test array");
    CHECK(st == PROJCURVE_ERR_NO_MEMORY);
    CHECK(a.items == before && a.capacity == cap_before);
    PC_ARRAY_FREE(&a);
    projcurve_context_destroy(ctx);
}

static void test_borrowed(void)
{
    int storage[4] = {1, 2, 3, 4};
    void *items = storage;
    size_t capacity = 4;
    int borrowed = 1;
    /* within the borrowed capacity: kept */
    CHECK_OK(pc_array_reserve(NULL, &items, &capacity, 4, 4, sizeof(int), 2, &borrowed, "b"));
    CHECK(items == (void *)storage && borrowed == 1);
    /* beyond it: copied to the heap, the caller's storage untouched */
    CHECK_OK(pc_array_reserve(NULL, &items, &capacity, 4, 5, sizeof(int), 2, &borrowed, "b"));
    CHECK(items != (void *)storage && borrowed == 0 && capacity == 8);
    const int *const copy = items;
    for (int k = 0; k < 4; ++k)
        CHECK(copy[k] == k + 1 && storage[k] == k + 1);
    free(items);
}

int main(void)
{
    test_push_and_growth();
    test_overflow();
    test_borrowed();
    return pc_test_finish("test_common_array");
}
