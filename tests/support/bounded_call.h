/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Runs a piece of test code in a forked child process with a CPU-time
 * guard, a wall-clock backstop and an address-space limit, so that a call
 * that hangs or runs away with memory fails one case instead of the whole
 * test. The child reports through a pipe (fixed-size records it writes
 * with pc_bounded_send); the parent collects them, with the child's exit
 * status and peak resident set size (wait4), after it ends.
 *
 * Under AddressSanitizer the address-space limit is not set: the
 * sanitizer reserves terabytes of shadow memory at start-up.
 */
#ifndef PC_TEST_BOUNDED_CALL_H
#define PC_TEST_BOUNDED_CALL_H

#include <stddef.h>
#include <sys/types.h>

typedef struct pc_bounded_limits {
    double wall_seconds;     /* the child is killed (SIGALRM) after this */
    size_t extra_address_mib; /* the child's address space may grow by this
                               * much past its size at the fork; 0: no limit */
} pc_bounded_limits;

/* What a child did: it exited (code) or was killed (signal); its peak
 * resident set (KiB, from wait4) and wall time; the bytes it sent. */
typedef struct pc_bounded_outcome {
    int exited, exit_code, signal;
    long max_rss_kib;
    double wall_seconds;
    size_t received;
} pc_bounded_outcome;

typedef void (*pc_bounded_fn)(void *user, int fd);

/* 1 where the address-space limit is applied (not under ASan). */
int pc_bounded_limits_memory(void);

/* Starts fn(user, fd) in a child that exits 0 after it returns; fd is the
 * write end of the child's pipe. Returns the child's pid, or -1 (fork or
 * pipe failed). At most `slots` children may run at once. */
typedef struct pc_bounded_slot {
    pid_t pid;
    int fd;
    double start;
    void *buffer;
    size_t capacity, received;
    int tag;
} pc_bounded_slot;

pid_t pc_bounded_start(pc_bounded_slot *slot, const pc_bounded_limits *limits, pc_bounded_fn fn,
                       void *user, void *buffer, size_t capacity, int tag);

/* Waits for one of the n slots' children to end, reads what it sent into
 * its buffer, fills *out and returns the slot's index (-1 if none runs). */
int pc_bounded_wait(pc_bounded_slot *slots, int n, pc_bounded_outcome *out);

/* In the child: a CPU-time guard of `seconds` from now (SIGPROF ends the
 * child when it is exceeded; 0 removes it), and one record to the parent. */
void pc_bounded_cpu_guard(double seconds);
void pc_bounded_send(int fd, const void *record, size_t size);

/* CPU seconds this process has used (CLOCK_PROCESS_CPUTIME_ID), and its
 * resident set and peak resident set now, in KiB. */
double pc_bounded_cpu_now(void);
long pc_bounded_rss_kib(void);
long pc_bounded_peak_rss_kib(void);

#endif /* PC_TEST_BOUNDED_CALL_H */
