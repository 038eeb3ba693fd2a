#include <glint/core/error.h>
#include <glint/light/environment_mapping.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// The cross's cells (column, row) of the faces, in the order +x, -x, +y, -y, +z, -z.
constexpr int kFaceCell[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {3, 1}, {1, 1}};

// Face coordinates (s right, t up, in [-1, 1]) of a direction on each face, and back; the
// faces as seen from inside (see the header's picture).
Vec3 cube_direction(int face, float s, float t) {
    switch (face) {
        case 0:
            return {1.0f, t, s};
        case 1:
            return {-1.0f, t, -s};
        case 2:
            return {s, 1.0f, t};
        case 3:
            return {s, -1.0f, -t};
        case 4:
            return {-s, t, 1.0f};
        default:
            return {s, t, -1.0f};
    }
}

Vec2 cube_image_point(const Vec3& d) {
    const Vec3 a = glm::abs(d);
    int face;
    float s, t;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x > 0.0f ? 0 : 1;
        s = (d.x > 0.0f ? d.z : -d.z) / a.x;
        t = d.y / a.x;
    } else if (a.y >= a.z) {
        face = d.y > 0.0f ? 2 : 3;
        s = d.x / a.y;
        t = (d.y > 0.0f ? d.z : -d.z) / a.y;
    } else {
        face = d.z > 0.0f ? 4 : 5;
        s = (d.z > 0.0f ? -d.x : d.x) / a.z;
        t = d.y / a.z;
    }
    return {(static_cast<float>(kFaceCell[face][0]) + 0.5f * (s + 1.0f)) / 4.0f,
            (static_cast<float>(kFaceCell[face][1]) + 0.5f * (1.0f - t)) / 3.0f};
}

// Disc coordinates (a right, b up) of image coordinates, and back.
Vec2 disc_of(const Vec2& p) {
    return {2.0f * p.x - 1.0f, 1.0f - 2.0f * p.y};
}
Vec2 image_of_disc(float a, float b) {
    return {0.5f * (a + 1.0f), 0.5f * (1.0f - b)};
}

// The lat-long map's direction at (u, v) (environment_light.h).
Vec3 latlong_direction(float u, float v) {
    const float theta = kPi * v, phi = 2.0f * kPi * u;
    return {-std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

class SourceImage {
public:
    SourceImage(const std::vector<Spectrum>& pixels, int width, int height)
        : m_pixels(pixels), m_width(width), m_height(height) {}

    // Bilinear between texel centres, clamped to the texels [x0, x1) x [y0, y1). With
    // `in_disc`, texels whose centre lies outside the inscribed disc (what a probe holds
    // around the ball: black or the room) take no part, and the others' weights are
    // renormalised, so the rim does not darken.
    Spectrum lookup(const Vec2& p, int x0, int y0, int x1, int y1, bool in_disc) const {
        const float x = p.x * static_cast<float>(m_width) - 0.5f;
        const float y = p.y * static_cast<float>(m_height) - 0.5f;
        const float fx = std::floor(x), fy = std::floor(y);
        const float tx = x - fx, ty = y - fy;
        const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
        Spectrum sum(0.0f);
        float weight_sum = 0.0f;
        for (int dj = 0; dj < 2; ++dj) {
            for (int di = 0; di < 2; ++di) {
                const int i = std::clamp(ix + di, x0, x1 - 1), j = std::clamp(iy + dj, y0, y1 - 1);
                if (in_disc) {
                    const Vec2 centre(
                        (static_cast<float>(i) + 0.5f) / static_cast<float>(m_width),
                        (static_cast<float>(j) + 0.5f) / static_cast<float>(m_height));
                    const Vec2 ab = disc_of(centre);
                    if (glm::dot(ab, ab) > 1.0f) continue;
                }
                const float w = (di ? tx : 1.0f - tx) * (dj ? ty : 1.0f - ty);
                sum += m_pixels[static_cast<size_t>(j) * static_cast<size_t>(m_width) +
                                static_cast<size_t>(i)] *
                       w;
                weight_sum += w;
            }
        }
        return weight_sum > 0.0f ? sum * (1.0f / weight_sum) : Spectrum(0.0f);
    }

    // The source's radiance towards d: a cube face is read on its own texels, so that
    // neighbouring cells of the cross do not bleed into it.
    Spectrum radiance(EnvironmentMapping mapping, const Vec3& d) const {
        const Vec2 p = environment_image_point(mapping, d);
        if (mapping != EnvironmentMapping::kCubeCross)
            return lookup(p, 0, 0, m_width, m_height, true);
        const int face_size = m_width / 4;
        const int col = std::clamp(static_cast<int>(p.x * 4.0f), 0, 3);
        const int row = std::clamp(static_cast<int>(p.y * 3.0f), 0, 2);
        return lookup(p, col * face_size, row * face_size, (col + 1) * face_size,
                      (row + 1) * face_size, false);
    }

private:
    const std::vector<Spectrum>& m_pixels;
    int m_width, m_height;
};

}  // namespace

std::optional<EnvironmentMapping> environment_mapping_named(const std::string& name) {
    if (name == "latlong") return EnvironmentMapping::kLatLong;
    if (name == "mirror_ball") return EnvironmentMapping::kMirrorBall;
    if (name == "angular") return EnvironmentMapping::kAngular;
    if (name == "cube_cross") return EnvironmentMapping::kCubeCross;
    return std::nullopt;
}

Vec2 environment_image_point(EnvironmentMapping mapping, const Vec3& d) {
    switch (mapping) {
        case EnvironmentMapping::kLatLong: {
            const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
            float phi = std::atan2(-d.x, d.z);
            if (phi < 0.0f) phi += 2.0f * kPi;
            return {phi / (2.0f * kPi), theta / kPi};
        }
        case EnvironmentMapping::kMirrorBall:
        case EnvironmentMapping::kAngular: {
            const float across = std::sqrt(d.x * d.x + d.y * d.y);
            if (!(across > 0.0f)) return image_of_disc(0.0f, d.z >= 0.0f ? 0.0f : 1.0f);
            const float angle = std::acos(std::clamp(d.z, -1.0f, 1.0f));
            const float radius =
                mapping == EnvironmentMapping::kMirrorBall ? std::sin(0.5f * angle) : angle / kPi;
            return image_of_disc(d.x * radius / across, d.y * radius / across);
        }
        case EnvironmentMapping::kCubeCross:
            break;
    }
    return cube_image_point(d);
}

std::optional<Vec3> environment_direction(EnvironmentMapping mapping, const Vec2& p) {
    switch (mapping) {
        case EnvironmentMapping::kLatLong:
            return latlong_direction(p.x, p.y);
        case EnvironmentMapping::kMirrorBall: {
            const Vec2 ab = disc_of(p);
            const float r2 = glm::dot(ab, ab);
            if (r2 > 1.0f) return std::nullopt;
            const Vec3 n(ab.x, ab.y, std::sqrt(1.0f - r2));
            return glm::normalize(2.0f * n.z * n - Vec3(0.0f, 0.0f, 1.0f));
        }
        case EnvironmentMapping::kAngular: {
            const Vec2 ab = disc_of(p);
            const float r = std::sqrt(glm::dot(ab, ab));
            if (r > 1.0f) return std::nullopt;
            if (r == 0.0f) return Vec3(0.0f, 0.0f, 1.0f);
            const float angle = kPi * r;
            const float s = std::sin(angle) / r;
            return Vec3(ab.x * s, ab.y * s, std::cos(angle));
        }
        case EnvironmentMapping::kCubeCross:
            break;
    }
    const int col = static_cast<int>(std::floor(p.x * 4.0f));
    const int row = static_cast<int>(std::floor(p.y * 3.0f));
    for (int face = 0; face < 6; ++face) {
        if (kFaceCell[face][0] != col || kFaceCell[face][1] != row) continue;
        const float s = 2.0f * (p.x * 4.0f - static_cast<float>(col)) - 1.0f;
        const float t = 1.0f - 2.0f * (p.y * 3.0f - static_cast<float>(row));
        return glm::normalize(cube_direction(face, s, t));
    }
    return std::nullopt;
}

LatLongImage to_latlong(EnvironmentMapping mapping, std::vector<Spectrum> pixels, int width,
                        int height) {
    if (mapping == EnvironmentMapping::kLatLong) return {std::move(pixels), width, height};
    int out_height = height;
    if (mapping == EnvironmentMapping::kCubeCross) {
        if (width % 4 != 0 || width / 4 * 3 != height)
            throw Error(
                fmt::format("a cube_cross map must be 4 faces wide and 3 high, with "
                            "square faces; this image is {} x {}",
                            width, height));
        out_height = 2 * (width / 4);
    } else if (width != height) {
        throw Error(
            fmt::format("a mirror_ball or angular map must be square; this image is "
                        "{} x {}",
                        width, height));
    }
    const SourceImage source(pixels, width, height);
    LatLongImage out;
    out.height = out_height;
    out.width = 2 * out_height;
    out.pixels.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height));
    constexpr int kSub = 4;
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            Spectrum sum(0.0f);
            for (int j = 0; j < kSub; ++j) {
                for (int i = 0; i < kSub; ++i) {
                    const float u =
                        (static_cast<float>(x) + (static_cast<float>(i) + 0.5f) / kSub) /
                        static_cast<float>(out.width);
                    const float v =
                        (static_cast<float>(y) + (static_cast<float>(j) + 0.5f) / kSub) /
                        static_cast<float>(out.height);
                    sum += source.radiance(mapping, latlong_direction(u, v));
                }
            }
            out.pixels[static_cast<size_t>(y) * static_cast<size_t>(out.width) +
                       static_cast<size_t>(x)] = sum * (1.0f / (kSub * kSub));
        }
    }
    return out;
}

}  // namespace glint
