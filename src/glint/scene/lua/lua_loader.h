#pragma once
// Runs a scene script in a Lua 5.4 VM with the `glint` module and returns the scene it
// describes. This is the only place in glint that knows Lua exists.
//
// A scene runs sandboxed unless the user trusts it: the safe part of Lua's standard library
// (base without dofile/loadfile and with text-only load, string, table, math, utf8,
// coroutine, os.clock/os.time/os.difftime), `require` of Lua modules beside the scene, a
// memory limit, an instruction budget and a time limit. See docs/scene-language.md,
// "The sandbox and its limits".
#include <glint/scene/scene_desc.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>

namespace glint {

/// How a scene script runs. The defaults are the sandbox `glint render` uses.
struct LoaderOptions {
    /// The full Lua standard library (io, os, debug, package, dofile, binary load), for a
    /// scene the user trusts: `glint render --trusted-scene`.
    bool trusted = false;
    /// Bytes the script's Lua VM may hold at once; 0 = no limit.
    size_t memory_limit = size_t{1} << 30;
    /// Lua VM instructions the script may run, counted in steps of 1000; 0 = no limit. Two
    /// billion is some seconds of a busy loop, a hundred times what a large procedural
    /// scene needs.
    uint64_t instruction_limit = 2'000'000'000;
    /// Seconds the script may run, wall clock, from the start of the Lua VM to its end
    /// (finalisers included); time spent inside glint's own functions (e.g. `glint.import`
    /// reading a large model) does not count. 0 = no limit. Past it, a script running Lua
    /// code ends with an error naming its line, as for the instruction budget. A script
    /// that is inside one call of a Lua library function written in C (e.g. a string
    /// pattern that backtracks for hours) cannot be interrupted: one second later a watchdog
    /// thread prints `glint: error: FILE:LINE: script ran past its time limit ...` (the last
    /// line the script was seen at) on stderr and ends the process with exit code 1
    /// (std::_Exit). While a script runs no output file exists yet, so nothing is left
    /// behind.
    double time_limit = 60.0;
    /// A signal number that a SIGINT/SIGTERM handler sets (0 = none), or null. Once it is
    /// set, a script running Lua code stops at once and loading throws glint::Interrupted;
    /// a script stuck inside one C call is ended by the watchdog one second later, which
    /// prints `glint: interrupted by SIGINT; no output written` and ends the process with
    /// exit code 128 + the signal.
    const std::atomic<int>* interrupt = nullptr;
};

/// Tables inside parameter tables a script may nest; deeper is an error naming the line.
inline constexpr int kMaxParamTableDepth = 64;

// Throws glint::Error "file:line: message" on a syntax error, a runtime error, a parameter
// of the wrong type, a call the sandbox refuses, or a script past its limits.
SceneDesc load_scene_file(const std::string& path, const LoaderOptions& options = {});
// `chunk_name` is used in error messages in place of a file name.
SceneDesc load_scene_string(const std::string& code, const std::string& chunk_name,
                            const std::string& directory = ".", const LoaderOptions& options = {});

}  // namespace glint
