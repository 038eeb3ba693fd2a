// Partial renders (`glint render --samples A:B`), `glint merge` and MPI jobs (`mpirun -np 3
// glint render`): the image of the parts is the single-process render's, bit for bit.
#include <glint/film/image_io.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace glint;
using glint::test::run_command;
using glint::test::run_glint;
namespace fs = std::filesystem;

namespace {

const std::string kCornell = GLINT_SOURCE_DIR "/examples/cornell-box.lua";

class ClusterTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() / fmt::format("glint-cluster-{}-{}-{}",
                                                        info->test_suite_name(), info->name(),
                                                        ::getpid());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string out(const std::string& name) const { return (m_dir / name).string(); }

    fs::path m_dir;
};

// Same size, channels and float bits.
void expect_identical(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, b.channels);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        differing += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
    EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " values";
}

// The render settings of the bit-identity tests: small, few samples, each integrator's
// extra work kept small.
std::string render_flags(const std::string& integrator) {
    std::string flags = fmt::format("--integrator {} --res 24x18 --spp 8 --quiet", integrator);
    if (integrator == "photon") flags += " --photons 3000";
    return flags;
}

class MergeTest : public ClusterTest, public ::testing::WithParamInterface<const char*> {};

// Parts of uneven size, given to merge out of order, add up to the whole render exactly.
TEST_P(MergeTest, UnevenSplitMergesToTheWholeRenderBitForBit) {
    const std::string flags = render_flags(GetParam());
    const auto whole =
        run_glint(fmt::format("render {} {} -o {}", kCornell, flags, out("whole.exr")));
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    const char* ranges[] = {"0:3", "3:4", "4:8"};
    std::string parts;
    for (int i = 0; i < 3; ++i) {
        const std::string part = out(fmt::format("part{}.exr", i));
        const auto r = run_glint(
            fmt::format("render {} {} --samples {} -o {}", kCornell, flags, ranges[i], part));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        parts = part + " " + parts;  // reversed: the order of the parts does not matter
    }
    const auto merged = run_glint(fmt::format("merge {} -o {} --quiet", parts, out("merged.exr")));
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    EXPECT_EQ(merged.output.find("warning"), std::string::npos) << merged.output;
    expect_identical(read_image(out("merged.exr")), read_image(out("whole.exr")));
}

INSTANTIATE_TEST_SUITE_P(TileIntegrators, MergeTest,
                         ::testing::Values("path", "whitted", "photon"));

TEST_F(ClusterTest, MergeRefusesOverlapsAndOtherRendersAndWarnsOfGaps) {
    const std::string flags = render_flags("path");
    for (const char* range : {"0:4", "2:6", "6:8"}) {
        const auto r = run_glint(fmt::format("render {} {} --samples {} -o {}", kCornell, flags,
                                             range, out(fmt::format("{}.exr", range[0]))));
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    auto r = run_glint(fmt::format("merge {} {} -o {}", out("0.exr"), out("2.exr"), out("m.exr")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("overlaps"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out("m.exr")));

    r = run_glint(fmt::format("merge {} {} -o {}", out("0.exr"), out("6.exr"), out("m.exr")));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("6 of the render's 8 samples"), std::string::npos) << r.output;

    const auto other = run_glint(fmt::format("render {} {} --seed 7 --samples 4:8 -o {}", kCornell,
                                             flags, out("seed7.exr")));
    ASSERT_EQ(other.exit_code, 0) << other.output;
    r = run_glint(fmt::format("merge {} {} -o {}", out("0.exr"), out("seed7.exr"), out("n.exr")));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("parts of different renders"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out("n.exr")));

    r = run_glint(fmt::format("merge {} -o {}", kCornell, out("n.exr")));
    EXPECT_EQ(r.exit_code, 1) << r.output;
}

TEST_F(ClusterTest, SamplesFlagIsChecked) {
    for (const char* bad : {"4:2", "3", "a:b", "-1:2"}) {
        const auto r = run_glint(
            fmt::format("render {} --samples {} -o {} --quiet", kCornell, bad, out("x.exr")));
        EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    }
    auto r = run_glint(
        fmt::format("render {} --spp 4 --samples 0:8 -o {} --quiet", kCornell, out("x.exr")));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("B <= spp"), std::string::npos) << r.output;
    r = run_glint(
        fmt::format("render {} --spp 4 --samples 0:2 -o {} --quiet", kCornell, out("x.png")));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("EXR files only"), std::string::npos) << r.output;
    r = run_glint(fmt::format("render {} --spp 4 --samples 0:2 --integrator bdpt -o {} --quiet",
                              kCornell, out("x.exr")));
    EXPECT_NE(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("renders whole images"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out("x.exr")));
}

// MPI: run only where glint was built with it and mpirun exists. Open MPI refuses to start
// as root unless two variables say so; the README's test command runs as root on a fresh
// machine (and in CI's containers), so the test sets them for the jobs it starts.
class MpiTest : public ClusterTest {
protected:
    void SetUp() override {
        ClusterTest::SetUp();
#ifndef GLINT_TEST_MPI
        GTEST_SKIP() << "glint was built without MPI";
#endif
        if (run_command("command -v mpirun").exit_code != 0) GTEST_SKIP() << "no mpirun";
        if (geteuid() == 0) {
            setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
            setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
        }
        // Under the sanitizers, Open MPI's components (shared objects it loads and unloads
        // itself, so LeakSanitizer cannot name them for a suppression) keep allocations to
        // the end of the process. The ranks skip the leak check; glint's own code is checked
        // for leaks by every other test, which renders the same paths in one process.
        const std::string asan = std::getenv("ASAN_OPTIONS") ? std::getenv("ASAN_OPTIONS") : "";
        if (!asan.ends_with("detect_leaks=0")) {
            const std::string options = asan + (asan.empty() ? "" : ":") + "detect_leaks=0";
            setenv("ASAN_OPTIONS", options.c_str(), 1);
        }
    }
    void write_script(const std::string& name, const std::string& text) const {
        std::ofstream(out(name)) << text;
    }
    std::string mpirun(int ranks) const {
        return fmt::format("mpirun --oversubscribe -np {} {}", ranks, test::glint_binary());
    }
};

class MpiImageTest : public MpiTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(MpiImageTest, ThreeRanksGiveTheSingleProcessImage) {
    std::string flags = fmt::format("--integrator {} --res 24x18 --spp 6 --quiet", GetParam());
    if (std::string(GetParam()) == "sppm") flags += " --photons 2000";
    const auto single =
        run_glint(fmt::format("render {} {} -o {}", kCornell, flags, out("single.exr")));
    ASSERT_EQ(single.exit_code, 0) << single.output;
    const auto job = run_command(
        fmt::format("{} render {} {} -o {} 2>&1", mpirun(3), kCornell, flags, out("mpi.exr")));
    ASSERT_EQ(job.exit_code, 0) << job.output;
    expect_identical(read_image(out("mpi.exr")), read_image(out("single.exr")));
}

INSTANTIATE_TEST_SUITE_P(Integrators, MpiImageTest,
                         ::testing::Values("path", "whitted", "sppm", "vcm"));

// vcm's light subpaths cross the ranks with their medium vertices (the medium by index, the
// hero's weights r_u): in fog too the job's image is the single process's.
TEST_F(MpiTest, VcmInFogGivesTheSingleProcessImage) {
    const std::string scene = GLINT_SOURCE_DIR "/examples/foggy-cornell.lua";
    const std::string flags = "--integrator vcm --res 24x18 --spp 6 --quiet";
    const auto single =
        run_glint(fmt::format("render {} {} -o {}", scene, flags, out("single.exr")));
    ASSERT_EQ(single.exit_code, 0) << single.output;
    const auto job = run_command(
        fmt::format("{} render {} {} -o {} 2>&1", mpirun(3), scene, flags, out("mpi.exr")));
    ASSERT_EQ(job.exit_code, 0) << job.output;
    expect_identical(read_image(out("mpi.exr")), read_image(out("single.exr")));
}

// bdpt's strategies are not shared among ranks (docs/cluster.md): refused before any
// rendering.
TEST_F(MpiTest, IntegratorsThatCannotBeSpreadAreRefused) {
    const auto job = run_command(fmt::format("{} render {} --integrator bdpt --spp 6 -o {} 2>&1",
                                             mpirun(3), kCornell, out("x.exr")));
    EXPECT_NE(job.exit_code, 0) << job.output;
    EXPECT_NE(job.output.find("every rank: --integrator: integrator 'bdpt' cannot be spread"),
              std::string::npos)
        << job.output;
    EXPECT_FALSE(fs::exists(out("x.exr")));
}

TEST_F(MpiTest, RankMissingTheSceneIsNamedAndNothingIsWritten) {
    // The scene is in the working directory of every rank but rank 1, as on a cluster where
    // one machine lacks the file.
    fs::copy_file(kCornell, out("scene.lua"));
    write_script("rank.sh",
                 fmt::format("if [ \"$OMPI_COMM_WORLD_RANK\" = 1 ]; then cd /; else cd {}; fi\n"
                             "exec {} render scene.lua --spp 6 --res 24x18 -o {} --quiet\n",
                             m_dir.string(), test::glint_binary(), out("x.exr")));
    const auto job =
        run_command(fmt::format("mpirun --oversubscribe -np 3 bash {} 2>&1", out("rank.sh")));
    EXPECT_NE(job.exit_code, 0) << job.output;
    EXPECT_NE(job.output.find("rank 1: cannot"), std::string::npos) << job.output;
    EXPECT_EQ(job.output.find("rank 0:"), std::string::npos) << job.output;
    EXPECT_FALSE(fs::exists(out("x.exr")));
}

TEST_F(MpiTest, KilledRankFailsTheRunCleanly) {
    // A render long enough to be killed in; rank 1 is killed once all three have started.
    write_script("kill.sh",
                 fmt::format("{} render {} --res 64x64 --spp 100000 -o {} --quiet > {} 2>&1 &\n"
                             "job=$!\n"
                             "for i in $(seq 1 300); do\n"
                             "  kids=$(pgrep -P $job -d ' ' glint)\n"
                             "  [ $(echo $kids | wc -w) -ge 3 ] && break\n"
                             "  sleep 0.1\n"
                             "done\n"
                             "sleep 1\n"
                             "kill -KILL $(echo $kids | cut -d' ' -f2)\n"
                             "wait $job\n",
                             mpirun(3), kCornell, out("x.exr"), out("log.txt")));
    const auto run = run_command(fmt::format("bash {} 2>&1", out("kill.sh")));
    EXPECT_NE(run.exit_code, 0) << run.output;
    EXPECT_FALSE(fs::exists(out("x.exr")));
    const std::string log = test::read_text(out("log.txt"));
    EXPECT_NE(log.find("rank 1"), std::string::npos) << log;
    EXPECT_NE(log.find("signal 9"), std::string::npos) << log;
}

}  // namespace
