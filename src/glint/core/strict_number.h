#pragma once
// Strict parsing of numbers typed by a user (command-line flags): the whole text must be
// the number, with no wrap-around, no sign where the value cannot be negative, and no
// trailing characters. std::stoi, sscanf("%d") and CLI11's integer conversion accept
// "12abc", wrap 4294967312 to 16 or -1 to 2^64 - 1; these functions reject them.
#include <cstdint>
#include <optional>
#include <string_view>

namespace glint {

/// A decimal integer in [min, max] (an optional leading '-' only), or nullopt.
std::optional<int64_t> parse_integer(std::string_view text, int64_t min, int64_t max);

/// A decimal integer in [0, max] with no sign at all, or nullopt. For seeds up to 2^64 - 1.
std::optional<uint64_t> parse_unsigned(std::string_view text, uint64_t max);

/// A finite decimal or scientific number ("1.5", "-2e-3"), or nullopt for anything else,
/// including "nan", "inf" and values out of the range of a double.
std::optional<double> parse_finite(std::string_view text);

/// "WIDTHxHEIGHT" (or 'X') with each side an integer in [1, max_side], or nullopt.
std::optional<std::pair<int, int>> parse_resolution(std::string_view text, int max_side);

}  // namespace glint
