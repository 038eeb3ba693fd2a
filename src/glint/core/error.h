#pragma once
// The one exception type of the library. Scene errors carry the script location so the
// CLI can print "file:line: message". Only the CLI catches it.
#include <stdexcept>
#include <string>

namespace glint {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// The job was stopped from outside (the CLI's SIGINT/SIGTERM handler raised the flag
/// given to Progress::set_cancel_flag); `signal` is the flag's value, the signal number.
class Interrupted : public Error {
public:
    explicit Interrupted(int signal) : Error("interrupted"), m_signal(signal) {}
    int signal() const { return m_signal; }

private:
    int m_signal;
};

}  // namespace glint
