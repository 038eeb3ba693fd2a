// The scene sandbox: what a script may not do, what it may, and the limits that end a
// runaway script with a message naming its line.
#include <glint/core/error.h>
#include <glint/scene/lua/lua_loader.h>

#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

using namespace glint;
using glint::test::error_of;
using glint::test::TempDir;

namespace {

std::string error_in(const std::string& code, const LoaderOptions& options = {},
                     const std::string& directory = ".") {
    return error_of([&] { load_scene_string(code, "scene.lua", directory, options); });
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

}  // namespace

// Each forbidden call fails on its own line (line 2: the first line is empty), with a
// message that says why and how to allow it.
TEST(Sandbox, ForbiddenCallsAreErrorsNamingTheLine) {
    const char* calls[] = {
        "os.execute('true')",    "io.open('/etc/passwd')",
        "io.popen('ls')",        "package.loadlib('libc.so.6', 'puts')",
        "debug.getregistry()",   "os.exit(0)",
        "os.getenv('HOME')",     "dofile('scene.lua')",
        "loadfile('scene.lua')", "load(string.dump(function() return 1 end))",
    };
    for (const char* call : calls) {
        const std::string message = error_in(std::string("local x = 1\n") + call + "\n");
        EXPECT_NE(message.find("scene.lua:2:"), std::string::npos) << call << ": " << message;
        const bool explains = message.find("--trusted-scene") != std::string::npos ||
                              message.find("text chunks only") != std::string::npos;
        EXPECT_TRUE(explains) << call << ": " << message;
    }
}

// Scene options come from GLINT_ variables (examples/depth-of-field.lua reads GLINT_FOCUS);
// the rest of the environment stays closed (HOME above).
TEST(Sandbox, GlintVariablesAreReadable) {
    ::setenv("GLINT_SANDBOX_TEST", "far", 1);
    ::unsetenv("GLINT_SANDBOX_UNSET");
    EXPECT_EQ(error_in(R"(
        assert(os.getenv("GLINT_SANDBOX_TEST") == "far")
        assert(os.getenv("GLINT_SANDBOX_UNSET") == nil)
    )"),
              "");
    EXPECT_NE(error_in("\nos.getenv('GLINTX')\n").find("scene.lua:2:"), std::string::npos);
}

TEST(Sandbox, SafeLibraryIsThere) {
    EXPECT_EQ(error_in(R"(
        assert(string.format("%d", 3) == "3" and math.floor(2.5) == 2)
        assert(table.concat({"a", "b"}) == "ab" and utf8.char(65) == "A")
        assert(os.clock() >= 0 and os.time() > 0)
        assert(load("return 1 + 1")() == 2)
        assert(coroutine.wrap(function() coroutine.yield(5) end)() == 5)
        assert(getmetatable(glint.translate(1, 2, 3)) == "glint.transform")
    )"),
              "");
}

TEST(Sandbox, RequireLoadsModulesBesideTheScene) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("lib"));
    write_file(dir.file("lib/shapes.lua"),
               "return { ball = function(m) "
               "glint.sphere{ radius = 2, material = m } end }\n");
    const SceneDesc desc = load_scene_string(R"(
        local shapes = require("lib.shapes")
        assert(require("lib.shapes") == shapes)
        shapes.ball(glint.diffuse{})
    )",
                                             "scene.lua", dir.file(""));
    EXPECT_EQ(desc.groups[0].shapes.size(), 1u);

    EXPECT_NE(error_in("require('missing')", {}, dir.file("")).find("scene.lua:1: require"),
              std::string::npos);
    EXPECT_NE(error_in("require('..secret')", {}, dir.file("")).find("scene.lua:1:"),
              std::string::npos);
    // A link out of the scene's folder is refused.
    std::filesystem::create_directory_symlink("/etc", dir.file("etc"));
    write_file(dir.file("outside.lua"), "return 1\n");
    EXPECT_NE(error_in("require('etc.passwd')", {}, dir.file("lib")).find("scene.lua:1:"),
              std::string::npos);
    // Precompiled modules are refused too.
    write_file(dir.file("binary.lua"), "\x1bLua precompiled");
    EXPECT_NE(error_in("require('binary')", {}, dir.file("")).find("binary"), std::string::npos);
}

TEST(Sandbox, TrustedSceneHasTheFullLibrary) {
    TempDir dir;
    write_file(dir.file("data.txt"), "7\n");
    const std::string code = "local f = assert(io.open('" + dir.file("data.txt") +
                             "'))\n assert(f:read('n') == 7)\n f:close()\n"
                             "assert(os.getenv and debug.getregistry and package.loadlib)\n";
    EXPECT_NE(error_in(code), "");
    LoaderOptions trusted;
    trusted.trusted = true;
    EXPECT_EQ(error_in(code, trusted), "");
}

// `while true do end` ends with the budget's message naming its line, also when the
// script catches the error and carries on.
TEST(Sandbox, InstructionBudgetEndsEndlessLoops) {
    LoaderOptions options;
    options.instruction_limit = 20'000'000;
    const auto start = std::chrono::steady_clock::now();
    const std::string message = error_in("local x = 0\nwhile true do x = x + 1 end\n", options);
    EXPECT_NE(message.find("scene.lua:2: script ran past its instruction budget"),
              std::string::npos)
        << message;
    const std::string caught =
        error_in("while true do\n pcall(function() while true do end end)\nend\n", options);
    EXPECT_NE(caught.find("instruction budget"), std::string::npos) << caught;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// The time limit ends a loop that the instruction budget would let run (here none), with
// the line, also when the script catches the error and carries on.
TEST(Sandbox, TimeLimitEndsEndlessLoops) {
    LoaderOptions options;
    options.instruction_limit = 0;
    options.time_limit = 0.25;
    const auto start = std::chrono::steady_clock::now();
    const std::string message = error_in("local x = 0\nwhile true do x = x + 1 end\n", options);
    EXPECT_NE(message.find("scene.lua:2: script ran past its time limit of 0.25 s"),
              std::string::npos)
        << message;
    const std::string caught =
        error_in("while true do\n pcall(function() while true do end end)\nend\n", options);
    EXPECT_NE(caught.find("time limit"), std::string::npos) << caught;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// Time inside glint's own functions (here an import of a model that takes longer than the
// whole limit) does not count against the script.
TEST(Sandbox, TimeInGlintFunctionsDoesNotCount) {
    TempDir dir;
    {
        std::ofstream obj(dir.file("grid.obj"));
        const int n = 400;
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x) obj << "v " << x << ' ' << y << " 0\n";
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const int a = y * (n + 1) + x + 1;
                obj << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
            }
    }
    // The loop after the imports runs the count hook, which checks the time.
    const std::string code =
        "local m = glint.diffuse{}\n"
        "for i = 1, 4 do glint.import{ file = 'grid.obj', material = m } end\n"
        "local x = 0\n"
        "for i = 1, 100000 do x = x + i end\n";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(error_in(code, {}, dir.file("")), "");
    const double import_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    LoaderOptions options;
    options.time_limit = import_seconds / 4;
    EXPECT_EQ(error_in(code, options, dir.file("")), "")
        << "imports took " << import_seconds << " s";
}

// The library functions the time limit watches (string.find, rep, ...) are called through a
// closure that notes the line; their errors still name the function and the script's line.
TEST(Sandbox, WatchedLibraryFunctionsKeepTheirMessages) {
    EXPECT_NE(error_in("\nstring.rep()\n").find("scene.lua:2: bad argument #1 to 'rep'"),
              std::string::npos)
        << error_in("\nstring.rep()\n");
    EXPECT_NE(error_in("\n\n('x'):find({})\n").find("scene.lua:3: bad argument #1 to 'find'"),
              std::string::npos)
        << error_in("\n\n('x'):find({})\n");
    EXPECT_EQ(error_in(R"lua(
        assert(("a1b2"):gsub("%d", "") == "ab" and string.match("key=7", "=(%d)") == "7")
        local n = 0
        for _ in ("a b c"):gmatch("%a") do n = n + 1 end
        assert(n == 3 and table.concat({1, 2}, ",") == "1,2" and ("x"):rep(3) == "xxx")
    )lua"),
              "");
}

TEST(Sandbox, MemoryLimitEndsGrowingTables) {
    LoaderOptions options;
    options.memory_limit = size_t{32} << 20;
    const std::string message =
        error_in("local t = {}\nlocal i = 0\nwhile true do i = i + 1; t[i] = {i} end\n", options);
    EXPECT_NE(message.find("scene.lua:3: script ran past its memory limit of 32 MiB"),
              std::string::npos)
        << message;
    // A big string at once, too.
    EXPECT_NE(error_in("local s = string.rep('x', 1 << 30)\n", options).find("memory limit"),
              std::string::npos);
}

// Handles cannot be forged or reached, and a finaliser after a failed script finds glint
// closed rather than a freed scene (AddressSanitizer caught the use after free).
TEST(Sandbox, HandlesAndFinalisersAreSafe) {
    EXPECT_NE(error_in("setmetatable(glint.diffuse{}, {})").find("scene.lua:1:"),
              std::string::npos);
    EXPECT_NE(
        error_in("glint.add(setmetatable({}, {__name = 'glint.handle'}))").find("scene.lua:1:"),
        std::string::npos);
    EXPECT_EQ(error_in(R"(
        local m = glint.diffuse{}
        setmetatable({}, {__gc = function() glint.sphere{ radius = 1, material = m } end})
        error("boom")
    )"),
              "scene.lua:4: boom");
}

// A finaliser that adds a group while another glint call is reading its arguments (so the
// groups move in memory): the shape and the placement still land in their group. The calls
// are made from a loaded chunk, one per line, so that each call's location is a new string:
// the garbage collector steps, and runs the finalisers, inside the glint calls.
TEST(Sandbox, FinalisersDuringAGlintCallLoseNothing) {
    const std::string code = R"lua(
        local m = glint.diffuse{}
        local g = glint.group()
        local h = glint.group()
        h:sphere{ radius = 1, material = m }
        local p = { radius = 0.01, material = m }
        local lines = {}
        for i = 1, 3000 do lines[i] = "g:sphere(p) g:place(h)" end
        local calls = load("local g, h, p = ...\n" .. table.concat(lines, "\n"), "=calls")
        local finaliser = { __gc = function() glint.group() end }
        for i = 1, 3000 do setmetatable({}, finaliser) end
        collectgarbage("incremental", 1, 1000)
        calls(g, h, p)
    )lua";
    const SceneDesc desc = load_scene_string(code, "scene.lua", ".", {});
    ASSERT_GT(desc.groups.size(), 100u);  // the finalisers ran
    EXPECT_EQ(desc.groups[1].shapes.size(), 3000u);
    EXPECT_EQ(desc.groups[1].instances.size(), 3000u);
}

// What a finaliser run by lua_close after a failed script gets from glint, seen through a
// file (a trusted scene may write one).
TEST(Sandbox, FinalisersAfterTheScriptFindGlintClosed) {
    TempDir dir;
    LoaderOptions trusted;
    trusted.trusted = true;
    const std::string code = R"(
        local m = glint.diffuse{}
        setmetatable({}, {__gc = function()
            local ok, message = pcall(glint.sphere, { radius = 1, material = m })
            local f = io.open(")" +
                             dir.file("gc.txt") +
                             R"(", "w")
            f:write(tostring(ok), " ", tostring(message))
            f:close()
        end})
        error("boom")
    )";
    EXPECT_NE(error_in(code, trusted).find("boom"), std::string::npos);
    const std::string seen = test::read_text(dir.file("gc.txt"));
    EXPECT_NE(seen.find("false"), std::string::npos) << seen;
    EXPECT_NE(seen.find("once the scene script has ended"), std::string::npos) << seen;
}

// load() with a reader function: the guard in front of load looks only at a string's
// first byte, so a binary chunk handed over piece by piece must be refused by the mode.
TEST(Sandbox, LoadRefusesBinaryChunksFromAReader) {
    const std::string message = error_in(R"(
        local bytes = string.dump(function() return 1 end)
        local given = false
        local f, why = load(function()
            if given then return nil end
            given = true
            return bytes
        end)
        assert(f == nil, "a binary chunk was loaded")
        error(why)
    )");
    EXPECT_NE(message.find("scene.lua:10:"), std::string::npos) << message;
    EXPECT_NE(message.find("binary"), std::string::npos) << message;
    // Given one byte at a time as well.
    const std::string bytewise = error_in(R"(
        local bytes = string.dump(function() return 1 end)
        local i = 0
        local f, why = load(function() i = i + 1; return i <= #bytes and bytes:sub(i, i) or nil end)
        assert(f == nil, "a binary chunk was loaded")
        error(why)
    )");
    EXPECT_NE(bytewise.find("binary"), std::string::npos) << bytewise;
}

TEST(Sandbox, NonStringErrorsNameTheLine) {
    EXPECT_EQ(error_in("\nerror(42)\n"),
              "scene.lua:2: error(42): the script raised a number, not a message");
    EXPECT_EQ(error_in("\n\nerror({})\n"),
              "scene.lua:3: the script raised an error whose value is a table, not a message");
    EXPECT_EQ(error_in("error(setmetatable({}, {__tostring = function() return 'mine' end}))"),
              "scene.lua:1: mine");
}
