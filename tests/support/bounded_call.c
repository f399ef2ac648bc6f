/* SPDX-License-Identifier: BSD-3-Clause */
#define _GNU_SOURCE
#include "bounded_call.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define PC_BOUNDED_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PC_BOUNDED_ASAN 1
#endif
#endif
#ifndef PC_BOUNDED_ASAN
#define PC_BOUNDED_ASAN 0
#endif

int pc_bounded_limits_memory(void)
{
    return !PC_BOUNDED_ASAN;
}

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double pc_bounded_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Field `index` (0: size, 1: resident) of /proc/self/statm, in KiB. */
static long statm_kib(int index)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long v[2] = {0, 0};
    if (f == NULL)
        return 0;
    if (fscanf(f, "%ld %ld", &v[0], &v[1]) != 2)
        v[0] = v[1] = 0;
    fclose(f);
    return v[index] * (sysconf(_SC_PAGESIZE) / 1024);
}

long pc_bounded_rss_kib(void)
{
    return statm_kib(1);
}

long pc_bounded_peak_rss_kib(void)
{
    struct rusage ru;
    return getrusage(RUSAGE_SELF, &ru) == 0 ? ru.ru_maxrss : 0;
}

void pc_bounded_cpu_guard(double seconds)
{
    struct itimerval it;
    memset(&it, 0, sizeof it);
    it.it_value.tv_sec = (time_t)seconds;
    it.it_value.tv_usec = (suseconds_t)((seconds - (double)(time_t)seconds) * 1e6);
    setitimer(ITIMER_PROF, &it, NULL);
}

void pc_bounded_send(int fd, const void *record, size_t size)
{
    const char *p = record;
    while (size > 0) {
        const ssize_t w = write(fd, p, size);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return;
        p += w;
        size -= (size_t)w;
    }
}

static void child(const pc_bounded_limits *limits, pc_bounded_fn fn, void *user, int fd)
{
    /* The default actions end the child: a hang is one failed case. */
    signal(SIGPROF, SIG_DFL);
    signal(SIGALRM, SIG_DFL);
    if (limits->wall_seconds > 0.0)
        alarm((unsigned)(limits->wall_seconds + 0.999));
    if (limits->extra_address_mib > 0 && pc_bounded_limits_memory()) {
        const rlim_t now = (rlim_t)statm_kib(0) * 1024;
        const struct rlimit rl = {now + (rlim_t)limits->extra_address_mib * 1024 * 1024,
                                  now + (rlim_t)limits->extra_address_mib * 1024 * 1024};
        setrlimit(RLIMIT_AS, &rl);
    }
    fn(user, fd);
    close(fd);
    _exit(0);
}

pid_t pc_bounded_start(pc_bounded_slot *slot, const pc_bounded_limits *limits, pc_bounded_fn fn,
                       void *user, void *buffer, size_t capacity, int tag)
{
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    fflush(stdout);
    fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return -1;
    }
    if (pid == 0) {
        close(fds[0]);
        child(limits, fn, user, fds[1]);
    }
    close(fds[1]);
    slot->pid = pid;
    slot->fd = fds[0];
    slot->start = wall_now();
    slot->buffer = buffer;
    slot->capacity = capacity;
    slot->received = 0;
    slot->tag = tag;
    return pid;
}

/* Reads what the child sent; the records are small (far below the pipe's
 * 64 KiB), so the child never blocks on a full pipe before it exits. */
static void drain(pc_bounded_slot *slot)
{
    char *buf = slot->buffer;
    for (;;) {
        char scratch[512];
        const size_t room = slot->capacity - slot->received;
        char *to = room > 0 ? buf + slot->received : scratch;
        const ssize_t r = read(slot->fd, to, room > 0 ? room : sizeof scratch);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            break;
        if (room > 0)
            slot->received += (size_t)r;
    }
    close(slot->fd);
}

int pc_bounded_wait(pc_bounded_slot *slots, int n, pc_bounded_outcome *out)
{
    int any = 0;
    for (int i = 0; i < n; ++i)
        any |= slots[i].pid > 0;
    if (!any)
        return -1;
    for (;;) {
        int status = 0;
        struct rusage ru;
        const pid_t pid = wait4(-1, &status, 0, &ru);
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        for (int i = 0; i < n; ++i) {
            if (slots[i].pid != pid)
                continue;
            drain(&slots[i]);
            memset(out, 0, sizeof *out);
            out->exited = WIFEXITED(status);
            out->exit_code = out->exited ? WEXITSTATUS(status) : 0;
            out->signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
            out->max_rss_kib = ru.ru_maxrss;
            out->wall_seconds = wall_now() - slots[i].start;
            out->received = slots[i].received;
            slots[i].pid = 0;
            return i;
        }
    }
}
