#include <glint/core/error.h>
#include <glint/render/render_control.h>

#include <fmt/format.h>

namespace glint {

void throw_if_cancelled(const RenderControl& control) {
    if (!control.cancel) return;
    if (const int signal = control.cancel->load(); signal != 0) throw Interrupted(signal);
}

void warn(const RenderControl& control, const std::string& message) {
    if (control.warn)
        control.warn(message);
    else
        fmt::print(stderr, "warning: {}\n", message);
}

}  // namespace glint
