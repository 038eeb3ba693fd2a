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

}  // namespace glint
