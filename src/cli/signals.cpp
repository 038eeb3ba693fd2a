#include "signals.h"

#include <glint/core/error.h>

#include <pthread.h>

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
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

void throw_if_interrupted() {
    if (const int signal = g_signal.load(); signal != 0) throw Interrupted(signal);
}

SignalBlock::SignalBlock() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, &m_old);
}

SignalBlock::~SignalBlock() {
    pthread_sigmask(SIG_SETMASK, &m_old, nullptr);
}

}  // namespace glint::cli
