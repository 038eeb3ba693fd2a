#pragma once
// The Lua VM a scene script runs in: a bounded allocator, an instruction budget, the
// sandboxed standard library (or the full one for a trusted scene), a `require` that finds
// modules beside the scene, and a message handler that gives every error a file:line.
// Only scene/lua/ includes this header.
#include <glint/scene/lua/lua_loader.h>

#include <lua.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
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
    /// of the memory limit or the instruction budget.
    void call_main(const std::string& chunk_name);

    /// Throws glint::Error for a load status other than LUA_OK (message on the stack).
    void check_load(int status, const std::string& chunk_name);

    /// The VM's accounting, shared with the allocator and the count hook.
    struct Limits {
        size_t memory_limit = 0;
        size_t memory_used = 0;
        uint64_t instruction_limit = 0;
        uint64_t instructions = 0;  // counted in steps of kHookStep
        int last_line = -1;         // the script line the hook saw last
        char last_source[LUA_IDSIZE] = {};
        lua_State* script = nullptr;  // the main thread, once a script runs on it
    };

private:
    std::string memory_message(const std::string& chunk_name) const;

    std::unique_ptr<Limits> m_limits;
    lua_State* m_state = nullptr;
};

/// Instructions between two calls of the budget hook (the budget's granularity).
inline constexpr int kHookStep = 1000;

}  // namespace glint
