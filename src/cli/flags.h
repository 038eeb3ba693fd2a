#pragma once
// What the subcommands share: exit codes, strict parsing of numeric flags (CLI11's own
// conversions wrap 4294967312 to 16 and -1 to 2^64 - 1), the scene loader's options and
// the help texts of the flags that several subcommands take.
#include <glint/core/error.h>
#include <glint/math/vector.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/scene/scene_desc.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace glint::cli {

constexpr int kExitInputError = 1;
constexpr int kExitUsageError = 2;
constexpr int kMaxResolution = 65536;  // as glint.render{width, height}
constexpr int kMaxThreads = 4096;
constexpr double kMaxScriptTimeLimit = 1e6;  // seconds, about 11 days

/// Rejects FLAG's value TEXT, saying what was EXPECTED; main() turns it into exit code 2.
[[noreturn]] void bad_flag(const std::string& flag, const std::string& text,
                           const std::string& expected);

/// Runs `check`; a glint::Error it throws about a flag's value (the render settings give a
/// flag's name as the place of the values it set, "--integrator: ...") becomes a usage error,
/// exit code 2, as for any other bad flag. Errors about output paths and memory stay input
/// errors (exit code 1).
template <typename Check>
auto with_flag_errors_as_usage_errors(Check&& check) {
    try {
        return check();
    } catch (const CLI::ValidationError&) {
        throw;
    } catch (const Interrupted&) {
        throw;
    } catch (const Error& e) {
        const std::string message = e.what();
        // Not the flag's fault: an output path, or a value this machine lacks the memory for
        // (core/memory.h's message), which stays exit code 1 as documented.
        const bool about_the_machine = message.find("this machine has") != std::string::npos;
        if (message.rfind("--", 0) == 0 && message.rfind("--output", 0) != 0 && !about_the_machine)
            throw CLI::ValidationError(message);
        throw;
    }
}

/// An integer flag in [min, max]; nothing when the flag was not given.
std::optional<int> int_flag(const std::string& flag, const std::string& text, int min, int max);

/// --crop's x0,y0,x1,y1 as numbers; render settings check them against the resolution.
std::vector<double> parse_crop(const std::string& text);

/// --res's WIDTHxHEIGHT.
Vec2i parse_resolution_flag(const std::string& text);

/// A scene runs sandboxed with bounded memory, instructions and time unless the user vouches
/// for it; --script-time-limit sets the time limit either way. SIGINT and SIGTERM stop a
/// script too.
LoaderOptions loader_options(bool trusted_scene, const std::string& time_limit);

/// A Lua scene script, or a model file (.obj, .ply, .gltf, .glb) rendered as it is with a
/// default camera and light where it has none. The importers' warnings are printed here.
SceneDesc load_scene(const std::string& path, const LoaderOptions& options);

/// Help of --trusted-scene and --script-time-limit.
const char* trusted_scene_help();
std::string script_time_limit_help();

}  // namespace glint::cli
