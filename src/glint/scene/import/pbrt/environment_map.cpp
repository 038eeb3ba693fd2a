// pbrt-v4's image infinite light. pbrt-v4 stores environment maps in the equal-area
// octahedral square (Clarberg 2008; pbrt-v4's EqualAreaSquareToSphere), with +z of the
// light's space at the square's centre; glint reads latitude-longitude images with +y up.
// The square is resampled into a latitude-longitude image with the light's transform and
// the scene's mirror baked in, written once to glint's image cache and used as glint's
// environment.
#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/film/image_io.h>
#include <glint/scene/import/pbrt/translator.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {

namespace fs = std::filesystem;

// The inverse of pbrt-v4's EqualAreaSquareToSphere: a unit direction to [0, 1]^2.
Vec2 equal_area_square_of(const Vec3& w) {
    const float r = std::sqrt(std::max(0.0f, 1.0f - std::abs(w.z)));
    const float phi = std::atan2(std::abs(w.y), std::abs(w.x));  // [0, pi/2]
    const float diagonal_sum = w.z >= 0.0f ? r : 2.0f - r;       // |u| + |v|
    const float difference = r * (4.0f * phi / kPi - 1.0f);      // |v| - |u|
    const float u = std::copysign((diagonal_sum - difference) / 2.0f, w.x);
    const float v = std::copysign((diagonal_sum + difference) / 2.0f, w.y);
    return Vec2((u + 1.0f) / 2.0f, (v + 1.0f) / 2.0f);
}

// Bilinear lookup of channel c at uv (0, 0 the top-left corner of the file), pixels
// clamped at the edges.
float bilinear(const Image& image, int channel, const Vec2& uv) {
    const float x = uv.x * image.width - 0.5f, y = uv.y * image.height - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    auto at = [&](int px, int py) {
        px = std::clamp(px, 0, image.width - 1);
        py = std::clamp(py, 0, image.height - 1);
        return image.at(px, py, channel);
    };
    return (1 - fx) * (1 - fy) * at(x0, y0) + fx * (1 - fy) * at(x0 + 1, y0) +
           (1 - fx) * fy * at(x0, y0 + 1) + fx * fy * at(x0 + 1, y0 + 1);
}

// R, G, B (or one grey channel) of a read image.
std::array<int, 3> rgb_channels(const Image& image, const std::string& file) {
    auto find = [&](const char* name) {
        for (size_t i = 0; i < image.channels.size(); ++i)
            if (image.channels[i] == name) return static_cast<int>(i);
        return -1;
    };
    const int r = find("R"), g = find("G"), b = find("B");
    if (r >= 0 && g >= 0 && b >= 0) return {r, g, b};
    if (image.channels.size() >= 1) return {0, 0, 0};
    throw Error(fmt::format("'{}' has no channels", file));
}

}  // namespace

Vec2 pbrt_equal_area_square_of(const Vec3& w) {
    return equal_area_square_of(w);
}

Image latlong_from_equal_area(const Image& square, const Mat3& light_from_world,
                              const std::string& file) {
    const std::array<int, 3> channel = rgb_channels(square, file);
    const int height = std::max(square.height, 2), width = 2 * height;
    Image out = make_image(width, height, {"R", "G", "B"});
    for (int y = 0; y < height; ++y) {
        const float theta = kPi * (y + 0.5f) / height;
        for (int x = 0; x < width; ++x) {
            // glint's direction for this pixel (light/environment_light.cpp's mapping).
            const float phi = 2.0f * kPi * (x + 0.5f) / width;
            const Vec3 world(-std::sin(theta) * std::sin(phi), std::cos(theta),
                             std::sin(theta) * std::cos(phi));
            const Vec2 uv = equal_area_square_of(glm::normalize(light_from_world * world));
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = std::max(0.0f, bilinear(square, channel[c], uv));
        }
    }
    return out;
}

void PbrtTranslator::environment_map(const PbrtEntity& e, const std::string& name,
                                     const Mat4& to_world, double scale) {
    const std::string file = resolve(name);
    Image square;
    try {
        square = read_image(file);
    } catch (const Error& error) {
        throw Error(fmt::format("{}: LightSource \"infinite\": {}", e.where.str(), error.what()));
    }
    if (square.width != square.height)
        throw Error(
            fmt::format("{}: LightSource \"infinite\": '{}' is {}x{}; pbrt-v4's environment "
                        "maps are square (equal-area octahedral)",
                        e.where.str(), file, square.width, square.height));
    if (e.params.has("L"))
        warn(e.where, "LightSource", "infinite: \"L\" with \"filename\" (L is ignored)");
    const Mat3 light_from_world = glm::inverse(Mat3(to_world));
    // The cache name follows the source file and the rotation, so that the same scene reuses
    // it and a changed file or transform makes a new one.
    std::error_code ec;
    const auto stamp = fs::last_write_time(file, ec).time_since_epoch().count();
    uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
    auto mix = [&](const void* data, size_t size) {
        for (size_t i = 0; i < size; ++i)
            hash = (hash ^ static_cast<const unsigned char*>(data)[i]) * 0x100000001b3ull;
    };
    mix(file.data(), file.size());
    mix(&stamp, sizeof stamp);
    mix(&light_from_world, sizeof light_from_world);
    // A private folder of this user's own (core/file_access.h): another user could otherwise
    // plant a link or a different map under the predictable name.
    fs::path dir;
    try {
        dir = private_cache_folder("glint-pbrt-environments");
    } catch (const Error& error) {
        throw Error(fmt::format("{}: LightSource \"infinite\": {}", e.where.str(), error.what()));
    }
    const fs::path path = dir / fmt::format("{:016x}.exr", hash);
    if (!fs::is_regular_file(fs::symlink_status(path, ec)))
        write_image(path.string(), latlong_from_equal_area(square, light_from_world, file));
    Params p("environment", where(e.where));
    p.set("file", path.string());
    if (scale != 1.0) p.set("intensity", scale);
    if (has_infinite_light()) {
        warn(e.where, "LightSource", "a second infinite light is not supported (ignored)");
        ++m_skipped["lights"];
        return;
    }
    m_desc.lights.push_back(std::move(p));
}

}  // namespace glint
