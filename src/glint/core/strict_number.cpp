#include <glint/core/strict_number.h>

#include <charconv>
#include <cmath>
#include <utility>

namespace glint {

std::optional<int64_t> parse_integer(std::string_view text, int64_t min, int64_t max) {
    if (text.empty() || text.front() == '+') return std::nullopt;
    int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || value < min || value > max) return std::nullopt;
    return value;
}

std::optional<uint64_t> parse_unsigned(std::string_view text, uint64_t max) {
    // from_chars for unsigned types rejects '-', but be explicit: a sign is never valid.
    if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
    uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || value > max) return std::nullopt;
    return value;
}

std::optional<double> parse_finite(std::string_view text) {
    if (text.empty()) return std::nullopt;
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<std::pair<int, int>> parse_resolution(std::string_view text, int max_side) {
    const size_t x = text.find_first_of("xX");
    if (x == std::string_view::npos) return std::nullopt;
    const auto w = parse_integer(text.substr(0, x), 1, max_side);
    const auto h = parse_integer(text.substr(x + 1), 1, max_side);
    if (!w || !h) return std::nullopt;
    return std::pair<int, int>(static_cast<int>(*w), static_cast<int>(*h));
}

}  // namespace glint
