// Writes the images examples/textures.lua uses into examples/textures/, so that nothing is
// downloaded: a uv test grid, a checkerboard, a tile normal map, a lat-long sky, the same
// sky as a mirror-ball light probe, and a torus mesh with uvs. Run by
// scripts/make-example-textures.sh; the output is committed.
#include <glint/film/image.h>
#include <glint/film/image_io.h>
#include <glint/light/environment_mapping.h>
#include <glint/math/vector.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace glint;

namespace {

Vec3 hue(float h) {
    const Vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
    Vec3 c;
    for (int i = 0; i < 3; ++i)
        c[i] = std::clamp(std::abs(std::fmod(h + k[i], 1.0f) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    return c;
}

// 8 x 8 cells: hue follows u, brightness v; dark lines between cells and a white corner
// mark in the cell at u = 0, v = 0, so orientation errors show.
Image uv_grid(int n) {
    Image image = make_image(n, n, {"R", "G", "B"});
    const int cell = n / 8;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const int cx = x / cell, cy = 7 - y / cell;  // cy = 0 at the bottom row (v = 0)
            Vec3 c = hue(cx / 8.0f) * (0.35f + 0.6f * cy / 7.0f);
            const int lx = x % cell, ly = y % cell;
            if (lx < 2 || ly < 2) c = Vec3(0.02f);
            if (cx == 0 && cy == 0 && lx > cell / 4 && lx < cell / 2 && ly > cell / 2 &&
                ly < 3 * cell / 4)
                c = Vec3(0.9f);
            for (int i = 0; i < 3; ++i) image.at(x, y, i) = c[i];
        }
    }
    return image;
}

Image checker(int n, int squares) {
    Image image = make_image(n, n, {"R", "G", "B"});
    const int size = n / squares;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int i = 0; i < 3; ++i)
                image.at(x, y, i) = ((x / size + y / size) % 2 == 0) ? 0.04f : 0.8f;
    return image;
}

// Height of 4 x 4 tiles with bevelled edges and sunken grout, in [0, 1].
float tile_height(float s, float t) {
    const float fs = s * 4.0f - std::floor(s * 4.0f), ft = t * 4.0f - std::floor(t * 4.0f);
    const float edge = std::min({fs, 1.0f - fs, ft, 1.0f - ft});  // distance to the border
    return std::clamp((edge - 0.03f) / 0.08f, 0.0f, 1.0f);
}

// A tangent-space normal map (OpenGL convention, x right, y up) stored raw as (n + 1) / 2,
// not sRGB-encoded, because normal maps are not colours.
void write_normal_map(const std::string& path, int n) {
    Image image = make_image(n, n, {"R", "G", "B"});
    const float step = 1.0f / n, depth = 0.04f;  // relief height in units of the texture
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const float s = (x + 0.5f) * step, t = 1.0f - (y + 0.5f) * step;
            const float dhds = (tile_height(s + step, t) - tile_height(s - step, t)) / (2 * step);
            const float dhdt = (tile_height(s, t + step) - tile_height(s, t - step)) / (2 * step);
            const Vec3 normal = glm::normalize(Vec3(-depth * dhds, -depth * dhdt, 1.0f));
            for (int i = 0; i < 3; ++i) image.at(x, y, i) = normal[i] * 0.5f + 0.5f;
        }
    }
    WriteOptions raw;
    raw.srgb = false;
    write_image(path, image, raw);
}

// A lat-long sky in glint's environment convention (src/glint/light/environment_light.h):
// the top row is the zenith (+y); the left edge looks along +z, the centre column along
// -z. Blue zenith, pale horizon, a sun 35 degrees high in front of a camera looking along
// -z, to its right, and a dim brownish ground below the horizon.
Image sky(int width, int height) {
    Image image = make_image(width, height, {"R", "G", "B"});
    const float sun_elevation = glm::radians(35.0f);
    const Vec3 sun = glm::normalize(Vec3(0.7f * std::cos(sun_elevation), std::sin(sun_elevation),
                                         0.7f * std::cos(sun_elevation)));
    for (int y = 0; y < height; ++y) {
        const float theta = (y + 0.5f) / height * kPi;  // from the zenith
        for (int x = 0; x < width; ++x) {
            const float phi = (x + 0.5f) / width * 2.0f * kPi;
            const Vec3 w(-std::sin(theta) * std::sin(phi), std::cos(theta),
                         std::sin(theta) * std::cos(phi));
            Vec3 c;
            if (w.y > 0.0f) {
                const float a = std::pow(1.0f - w.y, 3.0f);
                c = glm::mix(Vec3(0.25f, 0.45f, 0.9f), Vec3(1.0f, 0.95f, 0.9f), a) * 1.2f;
                // A sun of 4 degrees radius: larger and dimmer than the real one (0.27
                // degrees), for softer shadows and fewer fireflies at few samples.
                if (glm::dot(w, sun) > std::cos(glm::radians(4.0f)))
                    c = Vec3(800.0f, 750.0f, 680.0f);
            } else {
                c = Vec3(0.25f, 0.2f, 0.15f) * (0.5f + 0.5f * std::exp(8.0f * w.y));
            }
            for (int i = 0; i < 3; ++i) image.at(x, y, i) = c[i];
        }
    }
    return image;
}

// A lat-long map as a light probe of `size` x `size` pixels in `mapping`'s layout
// (environment_mapping.h): each probe pixel reads the lat-long map bilinearly in its
// direction; outside the ball's disc stays black, as in a photograph cropped to the ball.
Image probe_of(const Image& latlong, EnvironmentMapping mapping, int size) {
    Image image = make_image(size, size, {"R", "G", "B"});
    auto texel = [&](int x, int y, int c) {
        x = (x % latlong.width + latlong.width) % latlong.width;
        y = std::clamp(y, 0, latlong.height - 1);
        return latlong.at(x, y, c);
    };
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const auto d =
                environment_direction(mapping, Vec2((x + 0.5f) / size, (y + 0.5f) / size));
            if (!d) continue;
            const Vec2 p = environment_image_point(EnvironmentMapping::kLatLong, *d);
            const float fx = p.x * latlong.width - 0.5f, fy = p.y * latlong.height - 0.5f;
            const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
            const float tx = fx - ix, ty = fy - iy;
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) =
                    (1 - tx) * (1 - ty) * texel(ix, iy, c) + tx * (1 - ty) * texel(ix + 1, iy, c) +
                    (1 - tx) * ty * texel(ix, iy + 1, c) + tx * ty * texel(ix + 1, iy + 1, c);
            }
        }
    }
    return image;
}

// An RGB image as a half-float EXR: a probe of a smooth sky needs no more, at a third of
// the size.
void write_half_exr(const std::string& path, const Image& image) {
    WriteOptions half;
    half.half = true;
    write_image(path, image, half);
}

// A torus around y with major radius R and minor radius r, uvs around both circles.
void write_torus(const std::string& path, float R, float r, int rings, int sides) {
    std::ofstream out(path);
    out << "# torus written by examples/make_textures.cpp\n";
    for (int i = 0; i <= rings; ++i) {
        for (int j = 0; j <= sides; ++j) {
            const float u = static_cast<float>(i) / rings, v = static_cast<float>(j) / sides;
            const float a = u * 2.0f * kPi, b = v * 2.0f * kPi;
            const Vec3 p((R + r * std::cos(b)) * std::cos(a), r * std::sin(b),
                         (R + r * std::cos(b)) * std::sin(a));
            out << fmt::format("v {:.6f} {:.6f} {:.6f}\nvt {:.6f} {:.6f}\n", p.x, p.y, p.z, u, v);
        }
    }
    auto index = [&](int i, int j) { return i * (sides + 1) + j + 1; };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                      d = index(i, j + 1);
            // Counter-clockwise seen from outside.
            out << fmt::format("f {0}/{0} {1}/{1} {2}/{2}\nf {0}/{0} {2}/{2} {3}/{3}\n", a, d, c,
                               b);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path dir = argc > 1 ? argv[1] : "examples/textures";
    std::filesystem::create_directories(dir);
    try {
        write_image((dir / "uv-grid.png").string(), uv_grid(512));
        write_image((dir / "checker.png").string(), checker(256, 8));
        write_normal_map((dir / "tiles-normal.png").string(), 256);
        const Image latlong_sky = sky(512, 256);
        write_image((dir / "sky.exr").string(), latlong_sky);
        write_half_exr((dir / "sky-mirror-ball.exr").string(),
                       probe_of(latlong_sky, EnvironmentMapping::kMirrorBall, 128));
        write_torus((dir / "torus.obj").string(), 0.6f, 0.25f, 48, 24);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_textures: %s\n", e.what());
        return 1;
    }
    std::printf("wrote the example textures to %s\n", dir.string().c_str());
    return 0;
}
