#pragma once
// The installed weights, for the tests that need them. Their absence is a failure, not a
// skip: CI runs scripts/install-deps.sh first, and a denoiser test that silently skips would
// pass on a machine where `--denoise` cannot work.
#include <glint/denoise/network_denoiser.h>

#include <filesystem>
#include <string>

namespace glint::test {

/// The path of `name`.tza in denoise_weights_dir(); throws std::runtime_error (a failed test)
/// when it is not there.
inline std::string installed_weights(const std::string& name) {
    const std::string path =
        (std::filesystem::path(denoise_weights_dir()) / (name + ".tza")).string();
    if (!std::filesystem::is_regular_file(path))
        throw std::runtime_error(path + " is missing: run scripts/install-deps.sh");
    return path;
}

}  // namespace glint::test
