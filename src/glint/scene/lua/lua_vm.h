#pragma once
// The Lua VM a scene script runs in: a bounded allocator, an instruction budget, a time
// limit watched by a thread, the sandboxed standard library (or the full one for a trusted scene),
// a `require` that finds modules beside the scene, and a message handler that gives every error a
// file:line. Only scene/lua/ includes this header.
#include <glint/scene/lua/lua_loader.h>

#include <lua.hpp>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace glint {

/// One Lua state with the limits of LoaderOptions. Not copyable: the allocator and the hook
/// keep a pointer to the limits, which live here.
class LuaVm {
public:
    /// Starts the VM and opens the libraries a scene may use; `directory` is where `require`
    /// looks for modules. Throws glint::Error when Lua cannot start.
    LuaVm(const LoaderOptions& options, const std::string& directory);
    ~LuaVm();
    LuaVm(const LuaVm&) = delete;
    LuaVm& operator=(const LuaVm&) = delete;

    lua_State* state() const { return m_state; }

    /// Calls the function on top of the stack (no arguments, no results) under the message
    /// handler. Throws glint::Error "file:line: message" on any error, including running out
    /// of the memory limit, the instruction budget or the time limit; glint::Interrupted when
    /// the interrupt flag of LoaderOptions was raised.
    void call_main(const std::string& chunk_name);

    /// Throws glint::Error for a load status other than LUA_OK (message on the stack).
    void check_load(int status, const std::string& chunk_name);

    /// The VM's accounting, shared with the allocator, the count hook and the watchdog.
    struct Limits {
        size_t memory_limit = 0;
        size_t memory_used = 0;
        uint64_t instruction_limit = 0;
        uint64_t instructions = 0;    // counted in steps of kHookStep
        lua_State* script = nullptr;  // the main thread, once a script runs on it
        double time_limit = 0;        // seconds; 0 = none
        const std::atomic<int>* interrupt = nullptr;
        std::chrono::steady_clock::time_point start;
        std::string chunk_name;  // for a message when no line is known

        // Read by the watchdog thread while the script runs, so guarded by `mutex`.
        std::mutex mutex;
        int last_line = -1;  // the script line seen last (hook, allocator, C library calls)
        char last_source[LUA_IDSIZE] = {};
        std::chrono::steady_clock::duration paused{};  // spent in glint's functions
        bool in_glint = false;                         // a glint function runs, since...
        std::chrono::steady_clock::time_point glint_start;
    };

private:
    class Watchdog;
    std::string memory_message(const std::string& chunk_name) const;

    std::unique_ptr<Limits> m_limits;
    lua_State* m_state = nullptr;
    std::unique_ptr<Watchdog> m_watchdog;  // only with a time limit or an interrupt flag
};

/// Held by a glint function called from a script while it runs: its time does not count
/// against the script's time limit (it is bounded by its inputs, not by the script; a large
/// model may take long to import). Should a Lua error jump past the destructor, the next
/// count hook ends the pause.
class GlintCallTime {
public:
    explicit GlintCallTime(lua_State* L);
    ~GlintCallTime();
    GlintCallTime(const GlintCallTime&) = delete;
    GlintCallTime& operator=(const GlintCallTime&) = delete;

private:
    LuaVm::Limits& m_limits;
};

/// Grace after the time limit (or an interrupt) before the watchdog ends a script stuck in
/// one C call.
inline constexpr double kWatchdogGraceSeconds = 1.0;

/// Instructions between two calls of the budget hook (the budget's granularity).
inline constexpr int kHookStep = 1000;

}  // namespace glint
