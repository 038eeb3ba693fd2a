// The glint command under hostile conditions: a file-size limit while writing, and
// SIGINT/SIGTERM during a render. Each must end with a non-zero exit and leave nothing
// behind (no output, no temporary file).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kScene = GLINT_SOURCE_DIR "/tests/scenes/small.lua";

std::string glint_binary() {
    const char* path = std::getenv("GLINT_BINARY");
    return path ? path : "glint";
}

class CliRobustness : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_root =
            fs::temp_directory_path() / fmt::format("glint-robust-{}-{}", info->name(), ::getpid());
        fs::remove_all(m_root);
        m_dir = m_root / "out";
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_root); }

    // Starts glint with `args` in m_dir, stderr to m_root/stderr; `limit_bytes` > 0 sets
    // RLIMIT_FSIZE with SIGXFSZ ignored, so writes past it fail with EFBIG; with
    // `default_sigxfsz` the signal keeps its default action (the process would be killed)
    // unless glint itself ignores it.
    pid_t start(const std::vector<std::string>& args, rlim_t limit_bytes = 0,
                bool default_sigxfsz = false) {
        const std::string binary = glint_binary();
        const std::string stderr_path = (m_root / "stderr").string();
        const pid_t pid = ::fork();
        if (pid == 0) {
            if (::chdir(m_dir.c_str()) != 0) ::_exit(120);
            std::FILE* err = std::freopen(stderr_path.c_str(), "w", stderr);
            if (!err) ::_exit(121);
            if (limit_bytes > 0) {
                std::signal(SIGXFSZ, default_sigxfsz ? SIG_DFL : SIG_IGN);
                const rlimit limit{limit_bytes, limit_bytes};
                ::setrlimit(RLIMIT_FSIZE, &limit);
            }
            std::vector<char*> argv;
            argv.push_back(const_cast<char*>(binary.c_str()));
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            ::execv(binary.c_str(), argv.data());
            ::_exit(122);
        }
        return pid;
    }

    // The exit status of `pid`, waiting at most `seconds` (then kills it and fails).
    int wait_for(pid_t pid, double seconds) {
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        int status = 0;
        while (::waitpid(pid, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, &status, 0);
                ADD_FAILURE() << "glint did not stop within " << seconds << " s";
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (WIFEXITED(status)) return WEXITSTATUS(status);
        ADD_FAILURE() << "glint was killed by signal " << WTERMSIG(status);
        return -1;
    }

    std::vector<std::string> leftovers() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_dir))
            names.push_back(entry.path().filename().string());
        return names;
    }

    std::string stderr_text() const {
        std::ifstream in(m_root / "stderr");
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }

    fs::path m_root, m_dir;
};

// Whether `pid` has a handler installed for `signal` (its SigCgt mask in /proc): glint
// installs its handlers first thing, so from then on a signal takes the handler's path.
bool catches(pid_t pid, int signal) {
    std::ifstream in(fmt::format("/proc/{}/status", pid));
    std::string key;
    while (in >> key) {
        if (key == "SigCgt:") {
            std::string mask;
            in >> mask;
            return (std::stoull(mask, nullptr, 16) >> (signal - 1)) & 1u;
        }
    }
    return false;
}

}  // namespace

// The same where SIGXFSZ has its default action, as in a shell with `ulimit -f` (issue 28:
// the signal killed glint mid-write and left its temporaries): glint ignores it itself.
TEST_F(CliRobustness, FileSizeLimitWithTheDefaultSignalLeavesNothing) {
    const pid_t pid = start({"render", kScene, "-o", "a.png", "-o", "b.exr", "--res", "128x128",
                             "--spp", "2", "--quiet"},
                            /*limit_bytes=*/3000, /*default_sigxfsz=*/true);
    EXPECT_EQ(wait_for(pid, 60.0), 1) << stderr_text();
    EXPECT_NE(stderr_text().find("cannot write"), std::string::npos) << stderr_text();
    EXPECT_EQ(leftovers(), std::vector<std::string>{});
}

// A file-size limit makes the EXR write fail part-way (as a full disk would): exit 1, a
// message naming the output, and neither it nor the PNG written before it remain.
TEST_F(CliRobustness, FileSizeLimitFailsAndLeavesNothing) {
    const pid_t pid = start({"render", kScene, "-o", "a.png", "-o", "b.exr", "--res", "128x128",
                             "--spp", "2", "--quiet"},
                            /*limit_bytes=*/3000);
    EXPECT_EQ(wait_for(pid, 60.0), 1) << stderr_text();
    EXPECT_NE(stderr_text().find("cannot write"), std::string::npos) << stderr_text();
    EXPECT_EQ(leftovers(), std::vector<std::string>{});
}

class CliSignal : public CliRobustness, public ::testing::WithParamInterface<int> {};

// A signal during a long render stops it at the next tile: exit 128 + signal, nothing
// written.
TEST_P(CliSignal, StopsTheRenderAndLeavesNothing) {
    const int signal = GetParam();
    const pid_t pid = start({"render", kScene, "-o", "a.png", "-o", "b.exr", "--res", "1024x1024",
                             "--spp", "1024", "--quiet"});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!catches(pid, signal) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    // Into the scene build or the render (this render would take minutes).
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    ::kill(pid, signal);
    EXPECT_EQ(wait_for(pid, 30.0), 128 + signal) << stderr_text();
    EXPECT_NE(stderr_text().find("interrupted"), std::string::npos) << stderr_text();
    EXPECT_EQ(leftovers(), std::vector<std::string>{});
}

// A signal while the scene script runs stops it too, whether it runs Lua code (the count
// hook sees the flag) or is stuck inside one C call (the loader's watchdog ends the process
// a second later); the time limit is far away.
TEST_P(CliSignal, StopsARunawayScript) {
    const int signal = GetParam();
    const std::string scripts[] = {
        "local x = 0\nwhile true do x = x + 1 end\n",
        "local s = string.rep('a', 100000)\nlocal found = s:find('.-.-.-.-.-b')\n",
    };
    for (const std::string& script : scripts) {
        const std::string scene = (m_root / "runaway.lua").string();
        std::ofstream(scene) << script;
        const pid_t pid = start({"render", scene, "-o", "a.png", "--script-time-limit", "600"});
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!catches(pid, signal) && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        std::this_thread::sleep_for(std::chrono::milliseconds(500));  // into the script
        const auto sent = std::chrono::steady_clock::now();
        ::kill(pid, signal);
        EXPECT_EQ(wait_for(pid, 20.0), 128 + signal) << script << stderr_text();
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count(),
                  5.0);
        EXPECT_NE(stderr_text().find("interrupted"), std::string::npos) << stderr_text();
        EXPECT_EQ(leftovers(), std::vector<std::string>{});
    }
}

// The long phases that report no progress of their own stop too (issue 28: they ran to their
// end first): the MLT bootstrap, photon emission for a photon map, the radiosity solve. Each
// scene's phase takes far longer than the 5 s allowed after the signal. SIGINT stops each
// phase; SIGTERM and SIGHUP, which reach the same handler, the first.
TEST_P(CliSignal, StopsTheLongPhasesBeforeTheTiles) {
    const int signal = GetParam();
    if (glint::test::kSanitizerBuild)
        GTEST_SKIP() << "its time bound holds for the normal build; the sanitizers' bootstraps "
                        "alone take longer";
    const char* phases[] = {
        "integrator = 'mlt', mlt_bootstrap = 20000000, mlt_chains = 16",
        "integrator = 'photon', photons = 2000000, caustic_photons = 2000000, max_depth = 64",
        "integrator = 'radiosity', radiosity_patch_size = 4, radiosity_unshot = 1e-9",
    };
    for (const char* phase : phases) {
        // Every signal takes the one handler: SIGINT checks each phase, the others the first
        // (each phase costs seconds of waiting).
        if (signal != SIGINT && phase != phases[0]) continue;
        SCOPED_TRACE(phase);
        const std::string scene = (m_root / "phase.lua").string();
        std::ofstream(scene) << glint::test::example_with_settings(
            "cornell-box.lua", std::string("width = 16, height = 16, spp = 1, ") + phase);
        const pid_t pid = start({"render", scene, "-o", "a.png", "--quiet"});
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!catches(pid, signal) && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // into the phase
        const auto sent = std::chrono::steady_clock::now();
        ::kill(pid, signal);
        EXPECT_EQ(wait_for(pid, 60.0), 128 + signal) << stderr_text();
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count(),
                  5.0);
        EXPECT_NE(stderr_text().find("interrupted"), std::string::npos) << stderr_text();
        EXPECT_EQ(leftovers(), std::vector<std::string>{});
    }
}

INSTANTIATE_TEST_SUITE_P(Signals, CliSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& info) {
                             return std::string(info.param == SIGINT    ? "SIGINT"
                                                : info.param == SIGTERM ? "SIGTERM"
                                                                        : "SIGHUP");
                         });
