#include <glint/core/cancel.h>
#include <glint/core/error.h>

namespace glint {
namespace {

// The one process-wide pointer: a signal is a process-wide event, and the phases that poll
// it lie too deep in the library to be handed a flag each.
std::atomic<const std::atomic<int>*> g_cancel_flag{nullptr};

}  // namespace

void set_cancel_flag(const std::atomic<int>* flag) {
    g_cancel_flag.store(flag, std::memory_order_release);
}

const std::atomic<int>* cancel_flag() {
    return g_cancel_flag.load(std::memory_order_acquire);
}

void throw_if_cancelled() {
    const std::atomic<int>* flag = cancel_flag();
    if (!flag) return;
    if (const int signal = flag->load(std::memory_order_relaxed); signal != 0)
        throw Interrupted(signal);
}

}  // namespace glint
