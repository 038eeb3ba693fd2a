// The OBJ parser: indices resolved strictly, values finite, faces fanned in linear time,
// errors naming the file and line.
#include <glint/core/error.h>
#include <glint/scene/import/obj.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

using namespace glint;

namespace {

MeshData parse(const std::string& text) {
    std::istringstream in(text);
    return parse_obj(in, "test.obj");
}

// The message of the Error that parsing `text` throws ("" if none).
std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST(Obj, IndicesAreOneBasedAndNegativeCountsBack) {
    const MeshData a = parse(kTriangle + "f 1 2 3\n");
    const MeshData b = parse(kTriangle + "f -3 -2 -1\n");
    ASSERT_EQ(a.indices.size(), 3u);
    ASSERT_EQ(b.positions.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.positions[a.indices[i]], b.positions[b.indices[i]]);
    EXPECT_EQ(a.positions[a.indices[1]], Vec3(1, 0, 0));
}

TEST(Obj, NormalsAndUvsKeptOnlyWhenEveryCornerHasThem) {
    const MeshData full =
        parse(kTriangle + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n" + "f 1/1/1 2/2/1 3/3/1\n");
    EXPECT_EQ(full.normals.size(), 3u);
    EXPECT_EQ(full.uvs.size(), 3u);
    EXPECT_EQ(full.uvs[full.indices[1]], Vec2(1, 0));
    const MeshData partial = parse(kTriangle + "vn 0 0 1\nf 1//1 2//1 3\n");
    EXPECT_TRUE(partial.normals.empty());
    EXPECT_TRUE(partial.uvs.empty());
}

TEST(Obj, OutOfRangeIndicesNameFileLineAndCounts) {
    EXPECT_NE(error_of(kTriangle + "f 1 2 100\n").find("test.obj:4: face refers to vertex 100"),
              std::string::npos);
    EXPECT_NE(error_of(kTriangle + "vn 0 0 1\nf 1//9 2//9 3//9\n").find("test.obj:5:"),
              std::string::npos);
    EXPECT_NE(error_of(kTriangle + "vt 0 0\nf 1/5 2/5 3/5\n").find("uv 5"), std::string::npos);
    EXPECT_NE(error_of(kTriangle + "f -4 1 2\n").find("vertex -4"), std::string::npos);
    EXPECT_NE(error_of(kTriangle + "f 0 1 2\n").find("index 0"), std::string::npos);
    // The last vertex (3) is the one index that must pass: an off-by-one fails here.
    EXPECT_EQ(error_of(kTriangle + "f 1 2 3\n"), "");
    EXPECT_NE(error_of(kTriangle + "f 1 2 4\n"), "");
}

TEST(Obj, IndicesDoNotWrap) {
    // 2^32 + 1 is vertex 1 after a 32-bit wrap; it must be out of range instead.
    EXPECT_NE(error_of(kTriangle + "f 4294967297 2 3\n").find("vertex 4294967297"),
              std::string::npos);
    EXPECT_NE(error_of(kTriangle + "f 1 2 99999999999999999999\n").find("too large"),
              std::string::npos);
    EXPECT_NE(error_of(kTriangle + "f 1 2 3x\n"), "");
}

TEST(Obj, NumbersMustBeFinite) {
    EXPECT_NE(error_of("v nan nan nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("test.obj:1:"),
              std::string::npos);
    EXPECT_NE(error_of("v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n").find("test.obj:2:"),
              std::string::npos);
    EXPECT_NE(error_of(kTriangle + "vn 0 nan 1\nf 1//1 2//1 3//1\n"), "");
    EXPECT_NE(error_of("v 0 0 0\nv 1e40 0 0\nv 0 1 0\nf 1 2 3\n").find("range"), std::string::npos);
    EXPECT_NE(error_of("v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("found 2"), std::string::npos);
}

// A 200 000-corner face becomes 199 998 triangles in a fan, quickly (ear clipping took
// minutes).
TEST(Obj, LargeFaceIsFannedInLinearTime) {
    const int n = 200000;
    std::ostringstream text;
    for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n;
        text << "v " << std::cos(a) << ' ' << std::sin(a) << " 0\n";
    }
    text << 'f';
    for (int i = 1; i <= n; ++i) text << ' ' << i;
    text << '\n';
    const auto start = std::chrono::steady_clock::now();
    const MeshData mesh = parse(text.str());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(mesh.indices.size(), 3u * (n - 2));
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        ASSERT_EQ(mesh.indices[t], mesh.indices[0]);
        ASSERT_EQ(mesh.indices[t + 2], mesh.indices[t + 1] + 1);
    }
    EXPECT_LT(seconds, 5.0);
}
