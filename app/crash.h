/* crash.h: naming the plugin when plugin code takes the process down.
 *
 * The core records which plugin callback each thread is in
 * (hearth_plugin_call_current). These handlers read that record when a fatal
 * signal arrives or exit() is called, so a user learns which plugin and which
 * callback failed instead of seeing a bare "Segmentation fault". */
#ifndef HEARTH_APP_CRASH_H
#define HEARTH_APP_CRASH_H

/// Exit status of a process whose plugin crashed or called exit() inside a callback.
#define CRASH_PLUGIN_EXIT 4

/// Install handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT (on an
/// alternate stack, so a plugin's stack overflow on the main thread is still
/// reported) and an atexit hook. Inside a plugin callback: print the plugin,
/// its file and the callback on stderr and end with CRASH_PLUGIN_EXIT.
/// Elsewhere: print "hearth crashed (not in a plugin)" and take the signal's
/// default action (a core dump stays possible).
///
/// report_fd >= 0 is the `plugin check` child's mode: nothing is printed;
/// one tab-separated record goes to report_fd instead (see crash.c), a fatal
/// signal is re-raised so the parent sees it, and SIGUSR1 (the parent's
/// timeout) reports the callback in flight and ends the child.
void crash_install(int report_fd);

/// Exit status the check child uses after answering SIGUSR1.
#define CRASH_TIMEOUT_EXIT 125

/// "SIGSEGV (segmentation fault)" and the like; "signal N" for others. Static storage.
const char *crash_signal_name(int sig);
#endif
