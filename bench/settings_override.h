#pragma once
// `--set KEY=VALUE` for the benchmark programs: a render setting that overrides the scene's
// glint.render{...} (true/false as booleans, numbers as numbers, anything else a string).
#include <glint/core/error.h>
#include <glint/core/params.h>

#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <utility>

namespace glint::bench {

inline std::pair<std::string, ParamValue> parse_setting_override(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos) throw Error(fmt::format("--set: '{}' is not KEY=VALUE", text));
    const std::string value = text.substr(eq + 1);
    ParamValue parsed = value;
    if (value == "true" || value == "false") {
        parsed = value == "true";
    } else {
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (!value.empty() && end == value.c_str() + value.size()) parsed = number;
    }
    return {text.substr(0, eq), parsed};
}

}  // namespace glint::bench
