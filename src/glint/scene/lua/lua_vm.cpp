#include <glint/core/error.h>
#include <glint/scene/lua/lua_vm.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <thread>
#include <utility>

namespace glint {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kTrustedHint =
    "is not available to a scene: scenes run sandboxed (glint render --trusted-scene gives a "
    "scene you trust the full Lua library)";

LuaVm::Limits& limits_of(lua_State* L) {
    void* ud = nullptr;
    lua_getallocf(L, &ud);
    return *static_cast<LuaVm::Limits*>(ud);
}

void set_place(LuaVm::Limits& limits, const lua_Debug& ar) {
    const std::lock_guard lock(limits.mutex);
    limits.last_line = ar.currentline;
    std::memcpy(limits.last_source, ar.short_src, sizeof(limits.last_source));
}

// Records the line the script is at, for a memory error (which Lua reports without a
// place). Reading the stack allocates nothing, so the allocator may do it; the main thread
// is what it can see (a coroutine's line is approximated by where it was resumed).
void remember_line(LuaVm::Limits& limits) {
    if (!limits.script) return;
    lua_Debug ar;
    for (int level = 0; lua_getstack(limits.script, level, &ar); ++level) {
        if (lua_getinfo(limits.script, "Sl", &ar) && ar.currentline > 0) {
            set_place(limits, ar);
            return;
        }
    }
}

// Ends the time a glint function runs (the caller holds the mutex).
void end_glint_time(LuaVm::Limits& limits, Clock::time_point now) {
    if (!limits.in_glint) return;
    limits.paused += now - limits.glint_start;
    limits.in_glint = false;
}

// The signal the interrupt flag holds, 0 for none.
int interrupt_signal(const LuaVm::Limits& limits) {
    return limits.interrupt ? limits.interrupt->load(std::memory_order_relaxed) : 0;
}

// Seconds the script itself has run: since the VM started, less the time in glint's own
// functions.
double script_seconds(LuaVm::Limits& limits) {
    const Clock::time_point now = Clock::now();
    const std::lock_guard lock(limits.mutex);
    Clock::duration paused = limits.paused;
    if (limits.in_glint) paused += now - limits.glint_start;
    return std::chrono::duration<double>(now - limits.start - paused).count();
}

// Counts every allocation against the limit; growing past it fails, which Lua reports as a
// memory error (and a script's pcall may catch, after which the memory is free again).
// Shrinking and freeing never fail.
void* limited_alloc(void* ud, void* ptr, size_t old_size, size_t new_size) {
    auto& limits = *static_cast<LuaVm::Limits*>(ud);
    // When ptr is null, old_size is a type tag, not a size.
    const size_t old_bytes = ptr ? old_size : 0;
    if (new_size == 0) {
        std::free(ptr);
        limits.memory_used -= old_bytes;
        return nullptr;
    }
    if (limits.memory_limit > 0 && new_size > old_bytes &&
        limits.memory_used - old_bytes + new_size > limits.memory_limit) {
        remember_line(limits);
        return nullptr;
    }
    void* memory = std::realloc(ptr, new_size);
    if (!memory) return nullptr;
    limits.memory_used = limits.memory_used - old_bytes + new_size;
    return memory;
}

// Called every kHookStep instructions of every coroutine: counts them against the budget,
// checks the time limit, and remembers the line, so that a memory error (which Lua reports
// without a place) or the watchdog can name where the script was.
void count_hook(lua_State* L, lua_Debug* ar) {
    LuaVm::Limits& limits = limits_of(L);
    limits.instructions += kHookStep;
    {
        const std::lock_guard lock(limits.mutex);
        // Lua code runs, so no glint function does (a Lua error may have jumped past the end
        // of one).
        end_glint_time(limits, Clock::now());
    }
    if (lua_getinfo(L, "Sl", ar) && ar->currentline > 0) set_place(limits, *ar);
    const bool interrupted = interrupt_signal(limits) != 0;
    const bool over_budget = !interrupted && limits.instruction_limit > 0 &&
                             limits.instructions > limits.instruction_limit;
    const bool over_time = !interrupted && !over_budget && limits.time_limit > 0 &&
                           script_seconds(limits) > limits.time_limit;
    if (!interrupted && !over_budget && !over_time) return;
    // A script that catches this error with pcall must not go on: from now on every
    // instruction, in this coroutine and the main one, raises it again.
    lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);
    lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_MAINTHREAD);
    if (lua_State* main = lua_tothread(L, -1)) lua_sethook(main, count_hook, LUA_MASKCOUNT, 1);
    lua_pop(L, 1);
    if (interrupted) {
        lua_pushfstring(L, "%s:%d: interrupted", ar->short_src, ar->currentline);
    } else if (over_budget) {
        lua_pushfstring(L,
                        "%s:%d: script ran past its instruction budget of %I Lua instructions "
                        "(an endless loop?)",
                        ar->short_src, ar->currentline,
                        static_cast<lua_Integer>(limits.instruction_limit));
    } else {  // the string is gone before lua_error jumps past its destructor
        const std::string seconds = fmt::format("{:g}", limits.time_limit);
        lua_pushfstring(L, "%s:%d: script ran past its time limit of %s s (an endless loop?)",
                        ar->short_src, ar->currentline, seconds.c_str());
    }
    lua_error(L);
}

// A Lua library function written in C, called through this closure, which first notes the
// line that calls it: the count hook does not run while C code does, and the watchdog
// names this line when the call never ends (a backtracking string pattern can run for
// hours). The original (upvalue 1, a light C function) runs in this closure's frame, not
// through lua_call, so that its errors still name the function and the script's line.
int noted_library_call(lua_State* L) {
    lua_Debug ar;
    if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
        set_place(limits_of(L), ar);
    return lua_tocfunction(L, lua_upvalueindex(1))(L);
}

// Wraps the library functions whose one call can take long in noted_library_call: the
// pattern functions (polynomial of high degree in the subject's length), and those that
// build long strings.
void note_long_library_calls(lua_State* L) {
    const std::pair<const char*, const char*> functions[] = {
        {LUA_STRLIBNAME, "find"},
        {LUA_STRLIBNAME, "match"},
        {LUA_STRLIBNAME, "gmatch"},
        {LUA_STRLIBNAME, "gsub"},
        {LUA_STRLIBNAME, "rep"},
        {LUA_STRLIBNAME, "format"},
        {LUA_TABLIBNAME, "concat"},
        // Finalisers run inside it (and Lua runs them with hooks off: no count hook stops
        // a __gc that loops, only the watchdog).
        {"_G", "collectgarbage"},
    };
    for (const auto& [library, name] : functions) {
        lua_getglobal(L, library);
        lua_getfield(L, -1, name);
        bool plain = lua_iscfunction(L, -1) != 0;
        if (plain && lua_getupvalue(L, -1, 1) != nullptr) {
            lua_pop(L, 1);
            plain = false;
        }
        if (plain) {
            lua_pushcclosure(L, noted_library_call, 1);
            lua_setfield(L, -2, name);
        } else {
            lua_pop(L, 1);  // not a plain C function: leave it as it is
        }
        lua_pop(L, 1);
    }
}

// "file:line:" of the innermost Lua function on the stack (C functions have no line).
void push_script_location(lua_State* L) {
    lua_Debug ar;
    for (int level = 1; lua_getstack(L, level, &ar); ++level) {
        if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0) {
            lua_pushfstring(L, "%s:%d:", ar.short_src, ar.currentline);
            return;
        }
    }
    lua_pushliteral(L, "?:");
}

// Whether `message` starts with a place, "source:line:".
bool has_location(const char* message) {
    const char* colon = std::strchr(message, ':');
    if (!colon || colon == message) return false;
    const char* digit = colon + 1;
    if (!std::isdigit(static_cast<unsigned char>(*digit))) return false;
    while (std::isdigit(static_cast<unsigned char>(*digit))) ++digit;
    return *digit == ':';
}

// Runtime errors and error("text") already carry file:line; error(42) or error({}) do not,
// so those get the place of the Lua code that raised them, as do the messages Lua raises
// from inside a C function ("C stack overflow", "error in __gc") and error("text", 0).
int message_handler(lua_State* L) {
    if (lua_type(L, 1) == LUA_TSTRING) {
        if (has_location(lua_tostring(L, 1))) return 1;
        push_script_location(L);
        if (std::strcmp(lua_tostring(L, -1), "?:") == 0) {
            lua_pop(L, 1);
            return 1;
        }
        lua_pushfstring(L, "%s %s", lua_tostring(L, -1), lua_tostring(L, 1));
        return 1;
    }
    push_script_location(L);
    if (luaL_getmetafield(L, 1, "__tostring") != LUA_TNIL) {
        lua_pop(L, 1);
        luaL_tolstring(L, 1, nullptr);
        lua_pushfstring(L, "%s %s", lua_tostring(L, -2), lua_tostring(L, -1));
    } else if (lua_type(L, 1) == LUA_TNUMBER) {
        luaL_tolstring(L, 1, nullptr);
        lua_pushfstring(L, "%s error(%s): the script raised a number, not a message",
                        lua_tostring(L, -2), lua_tostring(L, -1));
    } else {
        lua_pushfstring(L, "%s the script raised an error whose value is a %s, not a message",
                        lua_tostring(L, -1), luaL_typename(L, 1));
    }
    return 1;
}

// __index of the placeholder tables `io`, `os`, `debug` and `package`: every missing field
// is an error naming the script line that asked for it.
int forbidden_field(lua_State* L) {
    const char* library = lua_tostring(L, lua_upvalueindex(1));
    const char* field = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "?";
    return luaL_error(L, "%s.%s %s", library, field, kTrustedHint);
}

int forbidden_function(lua_State* L) {
    return luaL_error(L, "%s %s", lua_tostring(L, lua_upvalueindex(1)), kTrustedHint);
}

// load() of text only: precompiled chunks can be forged to crash the VM.
int text_only_load(lua_State* L) {
    size_t size = 0;
    const char* text = lua_type(L, 1) == LUA_TSTRING ? lua_tolstring(L, 1, &size) : nullptr;
    if (text && size > 0 && text[0] == LUA_SIGNATURE[0])
        return luaL_error(L, "load: a scene may load text chunks only, not precompiled ones");
    if (lua_gettop(L) < 3) lua_settop(L, 3);  // keep `env` absent when it was not given
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

// The file of module `name` beside the scene: dots separate folders, each part a plain
// name, and the file (after following links) must lie inside the scene's folder.
std::string module_path(const std::string& directory, const std::string& name) {
    bool plain = !name.empty() && name.front() != '.' && name.back() != '.' &&
                 name.find("..") == std::string::npos;
    for (char c : name) {
        plain &= std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    }
    if (!plain) {
        throw Error(
            fmt::format("require('{}'): a module name is made of letters, digits, '_' and "
                        "'-', with dots between folders (e.g. 'lib.shapes')",
                        name));
    }
    std::string relative = name;
    for (char& c : relative) c = c == '.' ? '/' : c;
    namespace fs = std::filesystem;
    const fs::path path = fs::path(directory) / (relative + ".lua");
    if (!fs::is_regular_file(path)) {
        throw Error(fmt::format("require('{}'): no module file '{}' beside the scene", name,
                                path.string()));
    }
    const fs::path inside =
        fs::weakly_canonical(path).lexically_relative(fs::weakly_canonical(directory));
    if (inside.empty() || *inside.begin() == "..")
        throw Error(fmt::format("require('{}'): '{}' leads outside the scene's folder", name,
                                path.string()));
    return path.string();
}

// A light userdata marking a module that is being loaded, to report a require cycle.
char g_loading_marker;

// require(name) for a sandboxed scene: a module beside the scene, loaded as text once.
int sandbox_require(lua_State* L) {
    const char* name = luaL_checkstring(L, 1);
    lua_settop(L, 1);
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);  // 2
    if (lua_getfield(L, 2, name) != LUA_TNIL) {
        if (lua_touserdata(L, -1) == &g_loading_marker)
            return luaL_error(L, "require('%s'): the module requires itself (a cycle)", name);
        return 1;
    }
    lua_pop(L, 1);
    bool found = false;
    {  // C++ objects end here, before any Lua error can jump over them.
        std::string text;
        try {
            text = module_path(lua_tostring(L, lua_upvalueindex(1)), name);
            found = true;
        } catch (const std::exception& e) {
            text = e.what();
        }
        lua_pushstring(L, text.c_str());  // 3: path or message
    }
    if (!found) {
        luaL_where(L, 1);
        lua_insert(L, -2);
        lua_concat(L, 2);
        return lua_error(L);
    }
    if (luaL_loadfilex(L, lua_tostring(L, 3), "t") != LUA_OK) {
        luaL_where(L, 1);
        lua_pushfstring(L, "require('%s'): ", name);
        lua_rotate(L, -3, 2);  // where, prefix, message
        lua_concat(L, 3);
        return lua_error(L);
    }
    lua_pushlightuserdata(L, &g_loading_marker);
    lua_setfield(L, 2, name);
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 3);
    lua_call(L, 2, 1);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        lua_pushboolean(L, 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, 2, name);
    return 1;
}

void open_library(lua_State* L, const char* name, lua_CFunction open) {
    lua_pushcfunction(L, open);
    lua_call(L, 0, 1);
    lua_setglobal(L, name);
}

// A global table whose every field is an error that says why.
void set_forbidden_table(lua_State* L, const char* name) {
    lua_newtable(L);
    lua_newtable(L);
    lua_pushstring(L, name);
    lua_pushcclosure(L, forbidden_field, 1);
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, "__index");
    lua_setfield(L, -2, "__newindex");
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_setmetatable(L, -2);
    lua_setglobal(L, name);
}

void set_forbidden_function(lua_State* L, const char* name) {
    lua_pushstring(L, name);
    lua_pushcclosure(L, forbidden_function, 1);
    lua_setglobal(L, name);
}

// os.getenv for the variables a scene may read: those whose names start with GLINT_ (scene
// options such as GLINT_FOCUS in examples/depth-of-field.lua). Any other name is an error:
// the rest of the environment (tokens, paths, user names) is not the scene's business.
int glint_getenv(lua_State* L) {
    const char* name = luaL_checkstring(L, 1);
    if (std::strncmp(name, "GLINT_", 6) != 0) {
        return luaL_error(L,
                          "os.getenv('%s'): a scene may read only variables whose names start "
                          "with GLINT_ (glint render --trusted-scene lifts this)",
                          name);
    }
    const char* value = std::getenv(name);
    if (value)
        lua_pushstring(L, value);
    else
        lua_pushnil(L);
    return 1;
}

// The safe part of the standard library: no file, process, debug or C-module access.
void open_sandboxed_libraries(lua_State* L, const std::string& directory) {
    lua_pushcfunction(L, luaopen_base);
    lua_call(L, 0, 1);  // fills and returns _G
    lua_pop(L, 1);
    open_library(L, LUA_STRLIBNAME, luaopen_string);
    open_library(L, LUA_TABLIBNAME, luaopen_table);
    open_library(L, LUA_MATHLIBNAME, luaopen_math);
    open_library(L, LUA_UTF8LIBNAME, luaopen_utf8);
    open_library(L, LUA_COLIBNAME, luaopen_coroutine);

    lua_getglobal(L, "load");
    lua_pushcclosure(L, text_only_load, 1);
    lua_setglobal(L, "load");
    set_forbidden_function(L, "dofile");
    set_forbidden_function(L, "loadfile");
    lua_pushstring(L, directory.c_str());
    lua_pushcclosure(L, sandbox_require, 1);
    lua_setglobal(L, "require");

    // os: the clock and GLINT_ variables only; the rest errors.
    set_forbidden_table(L, LUA_OSLIBNAME);
    lua_getglobal(L, LUA_OSLIBNAME);
    lua_pushcfunction(L, luaopen_os);
    lua_call(L, 0, 1);
    for (const char* safe : {"clock", "time", "difftime"}) {
        lua_pushstring(L, safe);
        lua_getfield(L, -2, safe);
        lua_rawset(L, -4);  // past the __newindex that refuses the script
    }
    lua_pushstring(L, "getenv");
    lua_pushcfunction(L, glint_getenv);
    lua_rawset(L, -4);
    lua_pop(L, 2);
    for (const char* name : {LUA_IOLIBNAME, LUA_DBLIBNAME, LUA_LOADLIBNAME})
        set_forbidden_table(L, name);
}

// The whole library, for a scene the user trusts; modules beside the scene come first.
void open_trusted_libraries(lua_State* L, const std::string& directory) {
    luaL_openlibs(L);
    lua_getglobal(L, LUA_LOADLIBNAME);
    lua_pushfstring(L, "%s/?.lua;%s/?/init.lua;", directory.c_str(), directory.c_str());
    lua_getfield(L, -2, "path");
    lua_concat(L, 2);
    lua_setfield(L, -2, "path");
    lua_pop(L, 1);
}

// Runs a setup function under a protected call, so that running out of memory while
// opening the libraries is an error, not an abort.
struct Setup {
    bool trusted;
    bool timed;
    const std::string* directory;
};

int setup(lua_State* L) {
    const auto* s = static_cast<const Setup*>(lua_touserdata(L, 1));
    if (s->trusted)
        open_trusted_libraries(L, *s->directory);
    else
        open_sandboxed_libraries(L, *s->directory);
    if (s->timed) note_long_library_calls(L);
    return 0;
}

// Past the time limit and its grace the script is inside one C call (otherwise the count
// hook would have ended it): no Lua error can reach it there, and no C++ exception can
// unwind through Lua's C frames, so the process ends. The script runs before any output
// file is opened, so none is left behind.
[[noreturn]] void end_stuck_script(LuaVm::Limits& limits) {
    std::string where;
    {
        const std::lock_guard lock(limits.mutex);
        where = limits.last_line > 0 ? fmt::format("{}:{}", limits.last_source, limits.last_line)
                                     : limits.chunk_name;
    }
    const std::string message = fmt::format(
        "glint: error: {}: script ran past its time limit of {:g} s inside a call that cannot "
        "be interrupted: a function of Lua's library (a string pattern that backtracks without "
        "end?) or a __gc finaliser (Lua runs those with the script's limits off: one that "
        "loops?)\n",
        where, limits.time_limit);
    std::fputs(message.c_str(), stderr);
    std::fflush(stderr);
    std::_Exit(1);
}

// As the CLI says it for an interrupted render.
[[noreturn]] void end_interrupted_script(int signal) {
    const std::string message = fmt::format("glint: interrupted by {}; no output written\n",
                                            signal == SIGINT    ? "SIGINT"
                                            : signal == SIGTERM ? "SIGTERM"
                                            : signal == SIGHUP  ? "SIGHUP"
                                                                : "a signal");
    std::fputs(message.c_str(), stderr);
    std::fflush(stderr);
    std::_Exit(128 + signal);
}

}  // namespace

// A thread that sleeps until the script's time limit (plus a grace) and ends the process if
// the script is still running then; the count hook ends a script that runs Lua code sooner.
// With an interrupt flag it looks at the flag ten times a second, and ends the process a
// grace after it was raised.
class LuaVm::Watchdog {
public:
    explicit Watchdog(Limits& limits) : m_limits(limits), m_thread([this] { watch(); }) {}
    ~Watchdog() {
        {
            const std::lock_guard lock(m_mutex);
            m_done = true;
        }
        m_wake.notify_one();
        m_thread.join();
    }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    void watch() {
        std::unique_lock lock(m_mutex);
        std::optional<Clock::time_point> interrupted_at;
        while (!m_done) {
            double left = 0.1;
            if (const int signal = interrupt_signal(m_limits); signal != 0) {
                if (!interrupted_at) interrupted_at = Clock::now();
                const double since =
                    std::chrono::duration<double>(Clock::now() - *interrupted_at).count();
                if (since > kWatchdogGraceSeconds) end_interrupted_script(signal);
                left = std::min(left, kWatchdogGraceSeconds - since);
            }
            if (m_limits.time_limit > 0) {
                // Time in glint's functions does not count, so the deadline can move: sleep
                // until it as it stands, then look again.
                const double until_deadline =
                    m_limits.time_limit + kWatchdogGraceSeconds - script_seconds(m_limits);
                if (until_deadline <= 0) end_stuck_script(m_limits);
                left = m_limits.interrupt ? std::min(left, until_deadline) : until_deadline;
            }
            m_wake.wait_for(lock, std::chrono::duration<double>(left));
        }
    }

    Limits& m_limits;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_done = false;
    std::thread m_thread;  // last: it starts once the members above exist
};

LuaVm::LuaVm(const LoaderOptions& options, const std::string& directory)
    : m_limits(std::make_unique<Limits>()) {
    m_limits->memory_limit = options.memory_limit;
    m_limits->instruction_limit = options.instruction_limit;
    m_limits->time_limit = options.time_limit > 0 ? options.time_limit : 0.0;
    m_limits->interrupt = options.interrupt;
    m_limits->start = Clock::now();
    m_state = lua_newstate(limited_alloc, m_limits.get());
    if (!m_state) throw Error("could not start the Lua interpreter");
    lua_sethook(m_state, count_hook, LUA_MASKCOUNT, kHookStep);
    Setup s{options.trusted, m_limits->time_limit > 0, &directory};
    lua_pushcfunction(m_state, setup);
    lua_pushlightuserdata(m_state, &s);
    if (lua_pcall(m_state, 1, 0, 0) != LUA_OK) {
        const std::string message = lua_tostring(m_state, -1) ? lua_tostring(m_state, -1) : "?";
        lua_close(m_state);
        throw Error("could not open the Lua libraries: " + message);
    }
    if (m_limits->time_limit > 0 || m_limits->interrupt)
        m_watchdog = std::make_unique<Watchdog>(*m_limits);
}

// The watchdog watches lua_close too: finalisers are script code.
LuaVm::~LuaVm() {
    lua_close(m_state);
    m_watchdog.reset();
}

std::string LuaVm::memory_message(const std::string& chunk_name) const {
    const std::string where = m_limits->last_line > 0
                                  ? fmt::format("{}:{}", m_limits->last_source, m_limits->last_line)
                                  : chunk_name;
    return fmt::format(
        "{}: script ran past its memory limit of {} MiB (a table that grows "
        "without end?)",
        where, m_limits->memory_limit >> 20);
}

void LuaVm::check_load(int status, const std::string& chunk_name) {
    if (status == LUA_OK) return;
    if (status == LUA_ERRMEM) throw Error(memory_message(chunk_name));
    const char* message = lua_tostring(m_state, -1);
    throw Error(message ? message : chunk_name + ": could not load the script");
}

void LuaVm::call_main(const std::string& chunk_name) {
    m_limits->script = m_state;
    {
        const std::lock_guard lock(m_limits->mutex);
        m_limits->chunk_name = chunk_name;
    }
    lua_pushcfunction(m_state, message_handler);
    lua_insert(m_state, -2);
    const int status = lua_pcall(m_state, 0, 0, -2);
    if (status == LUA_OK) {
        lua_pop(m_state, 1);
        return;
    }
    if (const int signal = interrupt_signal(*m_limits); signal != 0) throw Interrupted(signal);
    if (status == LUA_ERRMEM) throw Error(memory_message(chunk_name));
    const char* message = lua_tostring(m_state, -1);
    throw Error(message ? message : chunk_name + ": unknown Lua error");
}

GlintCallTime::GlintCallTime(lua_State* L) : m_limits(limits_of(L)) {
    const std::lock_guard lock(m_limits.mutex);
    m_limits.in_glint = true;
    m_limits.glint_start = Clock::now();
}

GlintCallTime::~GlintCallTime() {
    const std::lock_guard lock(m_limits.mutex);
    end_glint_time(m_limits, Clock::now());
}

}  // namespace glint
