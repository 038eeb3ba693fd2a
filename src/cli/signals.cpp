#include "signals.h"

#include <glint/core/cancel.h>
#include <glint/core/error.h>

#include <csignal>

namespace glint::cli {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

namespace {

extern "C" void on_signal(int signal) {
    int expected = 0;
    g_signal.compare_exchange_strong(expected, signal);
}

}  // namespace

void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    // SIGHUP (the terminal closed) ends a run as SIGINT does: the default action would kill
    // the process in the middle of writing, leaving its temporaries.
    for (const int signal : kStoppingSignals) sigaction(signal, &action, nullptr);
    // Past a file-size limit (ulimit -f) the write fails with EFBIG, which the output code
    // checks and cleans up after; SIGXFSZ's default action would kill the process first.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGXFSZ, &ignore, nullptr);
    // Every long phase of the library polls the same flag (core/cancel.h).
    set_cancel_flag(&g_signal);
}

const char* signal_name(int signal) {
    switch (signal) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        default:
            return "a signal";
    }
}

void throw_if_interrupted() {
    if (const int signal = g_signal.load(); signal != 0) throw Interrupted(signal);
}

}  // namespace glint::cli
