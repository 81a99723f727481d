/* crash.c: fatal signals and exit() inside plugin callbacks (see crash.h).
 *
 * Everything the signal handler does is async-signal-safe: write(2), _exit,
 * signal, raise, and reading the thread-local call record. No stdio, no
 * allocation. Records for the check child are one line:
 *   C \t SIGNAME \t material \t file \t callback \t context \n   fatal signal
 *   X \t - \t material \t file \t callback \t context \n         exit() in a callback
 *   H \t - \t material \t file \t callback \t context \n         answer to the timeout probe
 */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* sigaltstack, SA_ONSTACK */
#endif
#include "crash.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hearth/hearth.h"

static int g_report_fd = -1;
static int g_atexit_done;
/* 64 KiB: SIGSTKSZ is no longer a constant in recent glibc, and the handler
 * needs little more than write(2)'s frames. */
static char g_altstack[1 << 16];

static const int g_fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

const char *crash_signal_name(int sig) {
    switch (sig) {
    case SIGSEGV: return "SIGSEGV (segmentation fault)";
    case SIGBUS: return "SIGBUS (bus error)";
    case SIGFPE: return "SIGFPE (arithmetic exception)";
    case SIGILL: return "SIGILL (illegal instruction)";
    case SIGABRT: return "SIGABRT (abort)";
    case SIGKILL: return "SIGKILL (killed)";
    case SIGTERM: return "SIGTERM (terminated)";
    default: return "a signal";
    }
}

static void put(int fd, const char *s) {
    size_t n = strlen(s);
    while (n > 0) {
        ssize_t w = write(fd, s, n);
        if (w <= 0) return;
        s += w;
        n -= (size_t)w;
    }
}

/* Tabs and newlines in a field would break the record; the strings come from
 * the core and the plugin's name, so they are short and usually clean. */
static void put_field(int fd, const char *s) {
    char buf[256];
    size_t k = 0;
    for (; *s && k < sizeof buf - 1; s++) buf[k++] = (*s == '\t' || *s == '\n') ? ' ' : *s;
    buf[k] = '\0';
    put(fd, "\t");
    put(fd, buf);
}

static void put_record(char kind, const char *sig, const hearth_plugin_call_info *c) {
    char k[2] = {kind, '\0'};
    put(g_report_fd, k);
    put_field(g_report_fd, sig);
    put_field(g_report_fd, c ? c->material : "");
    put_field(g_report_fd, c ? c->file : "");
    put_field(g_report_fd, c ? c->callback : "");
    put_field(g_report_fd, c ? c->context : "");
    put(g_report_fd, "\n");
}

/* "hearth: plugin 'x' (/p/hearth_x.so) <what> in its stress callback [during ...]; ..." */
static void put_message(const char *what, const hearth_plugin_call_info *c) {
    put(2, "\nhearth: plugin '");
    put(2, c->material);
    put(2, "'");
    if (*c->file) {
        put(2, " (");
        put(2, c->file);
        put(2, ")");
    }
    put(2, " ");
    put(2, what);
    put(2, " in its ");
    put(2, c->callback);
    put(2, " callback");
    if (*c->context) {
        put(2, " during ");
        put(2, c->context);
    }
    put(2, "; hearth stopped (exit status 4). Test the plugin with: hearth plugin check ");
    put(2, *c->file ? c->file : c->material);
    put(2, "\n");
}

static void on_fatal(int sig) {
    hearth_plugin_call_info c;
    const int in_plugin = hearth_plugin_call_current(&c);
    if (g_report_fd >= 0) {
        put_record('C', crash_signal_name(sig), in_plugin ? &c : NULL);
    } else if (in_plugin) {
        char what[80] = "crashed with ";
        strncat(what, crash_signal_name(sig), sizeof what - strlen(what) - 1);
        put_message(what, &c);
        _exit(CRASH_PLUGIN_EXIT);
    } else {
        put(2, "\nhearth crashed (not in a plugin): ");
        put(2, crash_signal_name(sig));
        put(2, "\n");
    }
    /* the default action: blocked until this handler returns, then it ends the process */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void on_timeout_probe(int sig) {
    (void)sig;
    hearth_plugin_call_info c;
    const int in_plugin = hearth_plugin_call_current(&c);
    put_record('H', "-", in_plugin ? &c : NULL);
    _exit(CRASH_TIMEOUT_EXIT);
}

/* exit() runs atexit hooks on the calling thread, so a plugin that calls it
 * from a callback is still "in" that callback here. */
static void on_exit_hook(void) {
    hearth_plugin_call_info c;
    if (!hearth_plugin_call_current(&c)) return;
    fflush(stdout); /* what the run printed before is whole */
    if (g_report_fd >= 0) put_record('X', "-", &c);
    else put_message("called exit()", &c);
    _exit(CRASH_PLUGIN_EXIT);
}

void crash_install(int report_fd) {
    g_report_fd = report_fd;
    stack_t ss = {.ss_sp = g_altstack, .ss_size = sizeof g_altstack, .ss_flags = 0};
    sigaltstack(&ss, NULL); /* on failure handlers still run, on the normal stack */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_fatal;
    sa.sa_flags = SA_ONSTACK;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof g_fatal / sizeof g_fatal[0]; i++) sigaction(g_fatal[i], &sa, NULL);
    if (report_fd >= 0) {
        sa.sa_handler = on_timeout_probe;
        sigaction(SIGUSR1, &sa, NULL);
    }
    if (!g_atexit_done) g_atexit_done = atexit(on_exit_hook) == 0;
}
