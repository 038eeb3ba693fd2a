#pragma once
// Memory budgets: what a render's big buffers will take, checked against what the machine
// has before anything is allocated, so that an impossible render fails with the numbers
// rather than with std::bad_alloc (or the kernel's OOM killer) half-way through.
#include <cstdint>
#include <string>

namespace glint {

/// Bytes a job may allocate: the GLINT_MEMORY_LIMIT environment variable when set (bytes,
/// or with a suffix K, M, G: binary units), else MemAvailable from /proc/meminfo, else
/// the physical memory from sysconf. Throws glint::Error for an unparsable variable.
uint64_t memory_budget();

/// "37.2 GiB", "512 MiB", "12 KiB", "100 bytes".
std::string format_bytes(uint64_t bytes);

/// a × b × ..., saturating at UINT64_MAX instead of wrapping.
uint64_t saturating_product(uint64_t a, uint64_t b);

/// Throws glint::Error "`what` needs N; this machine has M available" when `bytes`
/// exceeds memory_budget(). `what` reads as a subject, e.g. "the film (70000x70000)".
void check_memory(uint64_t bytes, const std::string& what);

/// Checks an image file's header before its pixels are decoded: `width` × `height` ×
/// `channels` must be positive, each side at most 1 << 20, and the decoded size
/// (`bytes_per_value` per channel value) within memory_budget() and plausible for a file
/// of `file_bytes` (no lossless coding glint reads packs more than 4096:1, so a
/// header claiming more lies). Throws glint::Error naming `path`.
void check_image_header(const std::string& path, int64_t width, int64_t height, int64_t channels,
                        uint64_t bytes_per_value, uint64_t file_bytes);

}  // namespace glint
