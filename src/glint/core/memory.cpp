#include <glint/core/error.h>
#include <glint/core/memory.h>

#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string_view>

namespace glint {
namespace {

constexpr uint64_t kMaxU64 = std::numeric_limits<uint64_t>::max();
constexpr int64_t kMaxImageSide = int64_t{1} << 20;
// Deflate (PNG, EXR zip) tops out near 1032:1; RLE and PIZ well below. 4096 leaves room.
constexpr uint64_t kMaxCompression = 4096;

uint64_t parse_limit(std::string_view text) {
    uint64_t value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string_view suffix(ptr, static_cast<size_t>(text.data() + text.size() - ptr));
    uint64_t scale = 1;
    if (suffix == "K" || suffix == "k")
        scale = uint64_t{1} << 10;
    else if (suffix == "M" || suffix == "m")
        scale = uint64_t{1} << 20;
    else if (suffix == "G" || suffix == "g")
        scale = uint64_t{1} << 30;
    else if (!suffix.empty())
        scale = 0;
    if (ec != std::errc() || scale == 0 || value > kMaxU64 / scale) {
        throw Error(fmt::format(
            "GLINT_MEMORY_LIMIT='{}' is not a byte count (e.g. 1073741824, 512M or 8G)", text));
    }
    return value * scale;
}

uint64_t meminfo_available() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    uint64_t kib = 0;
    std::string unit;
    while (in >> key >> kib >> unit) {
        if (key == "MemAvailable:") return kib * 1024;
    }
    return 0;
}

}  // namespace

uint64_t memory_budget() {
    if (const char* limit = std::getenv("GLINT_MEMORY_LIMIT"); limit && *limit)
        return parse_limit(limit);
    if (const uint64_t available = meminfo_available(); available > 0) return available;
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0)
        return saturating_product(static_cast<uint64_t>(pages), static_cast<uint64_t>(page));
    return kMaxU64;  // unknown: let the allocator decide
}

std::string format_bytes(uint64_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    if (bytes < 1024) return fmt::format("{} bytes", bytes);
    double value = static_cast<double>(bytes) / 1024.0;
    int unit = 0;
    while (value >= 1024.0 && unit < 5) value /= 1024.0, ++unit;
    return fmt::format("{:.1f} {}", value, units[unit]);
}

uint64_t saturating_product(uint64_t a, uint64_t b) {
    if (a != 0 && b > kMaxU64 / a) return kMaxU64;
    return a * b;
}

void check_memory(uint64_t bytes, const std::string& what) {
    const uint64_t budget = memory_budget();
    if (bytes > budget) {
        throw Error(fmt::format("{} needs {}; this machine has {} available{}", what,
                                format_bytes(bytes), format_bytes(budget),
                                std::getenv("GLINT_MEMORY_LIMIT") ? " (GLINT_MEMORY_LIMIT)" : ""));
    }
}

void check_image_header(const std::string& path, int64_t width, int64_t height, int64_t channels,
                        uint64_t bytes_per_value, uint64_t file_bytes) {
    if (width <= 0 || height <= 0 || channels <= 0) {
        throw Error(fmt::format("image '{}': its header gives {}x{} pixels with {} channels", path,
                                width, height, channels));
    }
    if (width > kMaxImageSide || height > kMaxImageSide || channels > 1024) {
        throw Error(fmt::format(
            "image '{}': its header claims {}x{} pixels with {} channels; glint reads images "
            "up to {}x{} with at most 1024 channels",
            path, width, height, channels, kMaxImageSide, kMaxImageSide));
    }
    const uint64_t values = saturating_product(
        saturating_product(static_cast<uint64_t>(width), static_cast<uint64_t>(height)),
        static_cast<uint64_t>(channels));
    const uint64_t decoded = saturating_product(values, bytes_per_value);
    if (decoded / kMaxCompression > file_bytes + 65536) {
        throw Error(fmt::format(
            "image '{}': its header claims {}x{} pixels with {} channels ({}), more than a "
            "file of {} can hold; the file is damaged",
            path, width, height, channels, format_bytes(decoded), format_bytes(file_bytes)));
    }
    check_memory(saturating_product(values, sizeof(float)),
                 fmt::format("image '{}' ({}x{}, {} channels)", path, width, height, channels));
}

}  // namespace glint
