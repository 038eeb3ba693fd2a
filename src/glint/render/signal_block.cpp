#include <glint/render/signal_block.h>

#include <pthread.h>

namespace glint {

SignalBlock::SignalBlock() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);  // the stopping signals (cli/signals.h kStoppingSignals)
    pthread_sigmask(SIG_BLOCK, &set, &m_old);
}

SignalBlock::~SignalBlock() {
    pthread_sigmask(SIG_SETMASK, &m_old, nullptr);
}

}  // namespace glint
