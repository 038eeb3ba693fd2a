#pragma once
// SIGINT and SIGTERM held back for a moment that must not be cut in two.
#include <csignal>

namespace glint {

/// While alive, SIGINT and SIGTERM wait (they are delivered when it ends): the outputs are
/// renamed into place under one, so that a run ends with every output renamed or none.
class SignalBlock {
public:
    SignalBlock();
    ~SignalBlock();
    SignalBlock(const SignalBlock&) = delete;
    SignalBlock& operator=(const SignalBlock&) = delete;

private:
    sigset_t m_old;
};

}  // namespace glint
