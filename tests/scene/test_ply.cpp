// The PLY reader: ASCII and both binary byte orders read the same mesh, polygons are fanned,
// attributes found by their names, and every malformed or truncated file is an error
// naming the file and where in it, never a crash.
#include <glint/core/error.h>
#include <glint/scene/build.h>
#include <glint/scene/import/ply.h>
#include <glint/scene/lua/lua_loader.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/test_util.h>

#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace glint;
using glint::test::contains;
using glint::test::error_of;

namespace {

// A quad (4 corners: one face) and a triangle, with normals, uvs named s/t, uchar colours,
// an extra vertex property and an extra face property that must be skipped, and an
// element glint does not know (with a list) between them.
struct Sample {
    std::vector<std::array<float, 3>> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    std::vector<std::array<uint8_t, 3>> rgb = {
        {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {51, 51, 51}, {0, 0, 0}};
    std::vector<std::vector<int32_t>> faces = {{0, 1, 2, 3}, {1, 4, 2}};
};

const char* kHeaderTail =
    "element vertex 5\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property double confidence\n"
    "property float s\nproperty float t\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    "element material 1\n"
    "property list uchar short ids\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property ushort flags\n"
    "end_header\n";

std::string ascii_ply(const Sample& s) {
    std::string out = std::string("ply\nformat ascii 1.0\ncomment made by a test\n") + kHeaderTail;
    for (size_t i = 0; i < s.p.size(); ++i) {
        out += fmt::format("{} {} {} 0 0 1 0.5 {} {} {} {} {}\n", s.p[i][0], s.p[i][1], s.p[i][2],
                           s.p[i][0] * 0.5f, s.p[i][1], s.rgb[i][0], s.rgb[i][1], s.rgb[i][2]);
    }
    out += "2 7 8\n";
    for (const auto& f : s.faces) {
        out += std::to_string(f.size());
        for (int32_t i : f) out += " " + std::to_string(i);
        out += " 3\n";
    }
    return out;
}

template <typename T>
void put(std::string& out, T value, bool big) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if (big == (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
}

std::string binary_ply(const Sample& s, bool big) {
    std::string out = std::string("ply\nformat binary_") + (big ? "big" : "little") +
                      "_endian 1.0\n" + kHeaderTail;
    for (size_t i = 0; i < s.p.size(); ++i) {
        for (float v : s.p[i]) put(out, v, big);
        for (float v : {0.0f, 0.0f, 1.0f}) put(out, v, big);
        put(out, 0.5, big);
        put(out, s.p[i][0] * 0.5f, big);
        put(out, s.p[i][1], big);
        for (uint8_t c : s.rgb[i]) put(out, c, big);
    }
    put<uint8_t>(out, 2, big);
    put<int16_t>(out, 7, big);
    put<int16_t>(out, 8, big);
    for (const auto& f : s.faces) {
        put(out, static_cast<uint8_t>(f.size()), big);
        for (int32_t i : f) put(out, i, big);
        put<uint16_t>(out, 3, big);
    }
    return out;
}

void expect_sample(const PlyMesh& ply) {
    const MeshData& m = ply.mesh;
    ASSERT_EQ(m.positions.size(), 5u);
    // The quad fans into (0 1 2) (0 2 3), then the triangle.
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
    EXPECT_EQ(m.positions[2], Vec3(1, 1, 0));
    EXPECT_EQ(m.positions[4], Vec3(2, 0, 0));
    ASSERT_EQ(m.normals.size(), 5u);
    EXPECT_EQ(m.normals[3], Vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), 5u);
    EXPECT_EQ(m.uvs[2], Vec2(0.5f, 1.0f));
    ASSERT_EQ(ply.colors.size(), 5u);
    EXPECT_EQ(ply.colors[1], Vec3(0, 1, 0));
    EXPECT_NEAR(ply.colors[3].x, 0.2f, 1e-6f);
}

std::string ply_error(const std::string& bytes) {
    return error_of([&] { parse_ply(bytes, "test.ply"); });
}

}  // namespace

TEST(Ply, AsciiReadsAttributesAndFansPolygons) {
    expect_sample(parse_ply(ascii_ply(Sample()), "test.ply"));
}

TEST(Ply, BinaryLittleAndBigEndianReadAsAscii) {
    expect_sample(parse_ply(binary_ply(Sample(), false), "test.ply"));
    expect_sample(parse_ply(binary_ply(Sample(), true), "test.ply"));
}

TEST(Ply, OtherUvNamesAndFloatColours) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty float texture_u\nproperty float texture_v\n"
        "property float red\nproperty float green\nproperty float blue\n"
        "element face 1\nproperty list uint8 uint32 vertex_index\nend_header\n"
        "0 0 0 0.25 0.75 0.5 0.5 0.5\n1 0 0 1 0 1 1 1\n0 1 0 0 1 0 0 0\n3 0 1 2\n";
    const PlyMesh ply = parse_ply(text, "test.ply");
    EXPECT_EQ(ply.mesh.uvs[0], Vec2(0.25f, 0.75f));
    EXPECT_EQ(ply.colors[0], Vec3(0.5f));
    EXPECT_TRUE(ply.mesh.normals.empty());
}

// Every prefix of a binary file (cut anywhere: header, vertices, lists) is an error, and
// one that names the file.
TEST(Ply, EveryTruncationIsAnError) {
    for (bool big : {false, true}) {
        const std::string bytes = binary_ply(Sample(), big);
        for (size_t n = 0; n < bytes.size(); ++n) {
            const std::string message = ply_error(bytes.substr(0, n));
            ASSERT_TRUE(contains(message, "test.ply")) << "cut at " << n << ": " << message;
        }
    }
    const std::string text = ascii_ply(Sample());
    for (size_t n = 0; n + 1 < text.size(); ++n) {
        // Cutting the ASCII text in the middle of the last number leaves a shorter, valid
        // number; every other cut loses a value.
        if (n >= text.size() - 3) continue;
        const std::string message = ply_error(text.substr(0, n));
        ASSERT_TRUE(contains(message, "test.ply")) << "cut at " << n << ": " << message;
    }
}

TEST(Ply, MalformedFilesNameWhatIsWrong) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_TRUE(contains(ply_error(head + verts + "3 0 1 3\n"), "refers to vertex 3"));
    EXPECT_TRUE(contains(ply_error(head + verts + "3 0 1 -1\n"), "test.ply:13: face 0 refers"));
    EXPECT_TRUE(contains(ply_error(head + verts + "2 0 1\n"), "face 0 has 2 corners"));
    EXPECT_TRUE(contains(ply_error(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), "test.ply:11:"));
    EXPECT_TRUE(contains(ply_error(head + "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n"), "'x' is not a number"));
    EXPECT_TRUE(contains(ply_error("plx\n"), "not a PLY file"));
    EXPECT_TRUE(contains(ply_error("ply\nformat ascii 2.0\nend_header\n"), "test.ply:2:"));
    EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty half x\n"),
                         "unknown property type 'half'"));
    EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement face 1\n"
                                  "property list uchar float vertex_indices\nend_header\n"),
                         "integer type"));
    EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 3\n"), "no 'end_header'"));
    // A count that the bytes left cannot hold is refused before anything is allocated.
    const std::string liar =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
        "property float x\nproperty float y\nproperty float z\nend_header\n";
    EXPECT_TRUE(contains(ply_error(liar + std::string(24, '\0')), "claims 4000000000"));
    EXPECT_TRUE(contains(ply_error(head + verts), "ends inside element 'face' 0 of 1"));
    EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                  "property float y\nproperty float z\nend_header\n0 0 0\n"),
                         "contains no faces"));
}

// glint.mesh{ file = "x.ply" } builds the mesh; the transform applies.
TEST(Ply, LoadsThroughGlintMesh) {
    test::TempDir dir;
    std::ofstream(dir.file("quad.ply"), std::ios::binary) << binary_ply(Sample(), false);
    const SceneDesc desc =
        load_scene_string(fmt::format("glint.mesh{{ file = '{}', material = glint.diffuse{{}}, "
                                      "transform = glint.translate(0, 0, 5) }}",
                                      dir.file("quad.ply")),
                          "scene.lua");
    const auto scene = build_scene(desc, parse_render_settings(nullptr));
    EXPECT_EQ(scene->stats().triangles, 3u);
    EXPECT_FLOAT_EQ(scene->stats().bounds.min.z, 5.0f);
    EXPECT_TRUE(contains(error_of([&] { load_ply(dir.file("missing.ply")); }), "missing.ply"));
}
