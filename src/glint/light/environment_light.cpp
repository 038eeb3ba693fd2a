#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/light/environment_light.h>
#include <glint/light/environment_mapping.h>
#include <glint/math/frame.h>
#include <glint/math/warp.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {

// cos(theta) at the top edge of row `y` of `height` less cos(theta) at its bottom edge,
// as 2 sin(mid) sin(half width): the plain difference of cosines near 1 would cancel.
float row_cos_theta_span(int y, int height) {
    const float mid = kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
    return 2.0f * std::sin(mid) * std::sin(0.5f * kPi / static_cast<float>(height));
}

// Weights of the bilinear lookup's integral over one pixel: the pixel itself and each
// neighbour along one axis (the tent between texel centres, integrated per half pixel).
constexpr float kTentCentre = 0.75f;
constexpr float kTentSide = 0.125f;

bool is_rotation(const Mat3& m) {
    const Mat3 should_be_identity = glm::transpose(m) * m;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (std::abs(should_be_identity[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-4f) return false;
        }
    }
    return glm::determinant(m) > 0.0f;
}

// The image's colour as Spectrum pixels: channels R, G, B found by name, else one grey
// channel (with or without alpha), else the first three.
std::vector<Spectrum> radiance_pixels(const Image& image, const Params& params,
                                      const std::string& path) {
    int rgb[3] = {image.channel_index("R"), image.channel_index("G"), image.channel_index("B")};
    if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0) {
        if (image.num_channels() == 1 || image.num_channels() == 2) {
            rgb[0] = rgb[1] = rgb[2] = 0;
        } else if (image.num_channels() >= 3) {
            rgb[0] = 0;
            rgb[1] = 1;
            rgb[2] = 2;
        } else {
            params.fail(fmt::format("environment map '{}' holds no colour channels", path));
        }
    }
    std::vector<Spectrum> pixels;
    pixels.reserve(static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Rgb value(image.at(x, y, rgb[0]), image.at(x, y, rgb[1]), image.at(x, y, rgb[2]));
            if (!value.is_finite()) {
                params.fail(
                    fmt::format("environment map '{}': pixel ({}, {}) is not finite", path, x, y));
            }
            // Negative values (ringing from resampling) would be negative light.
            const Rgb clipped(std::max(value.r, 0.0f), std::max(value.g, 0.0f),
                              std::max(value.b, 0.0f));
            pixels.push_back(uplift(clipped, RgbRole::illuminant));
        }
    }
    return pixels;
}

}  // namespace

EnvironmentLight::EnvironmentLight(std::vector<Spectrum> radiance, int width, int height,
                                   const Mat3& to_world)
    : m_pixels(std::move(radiance)),
      m_width(width),
      m_height(height),
      m_to_world(to_world),
      m_to_map(glm::transpose(to_world)),
      m_distribution(sampling_weights(), static_cast<size_t>(width), static_cast<size_t>(height)) {
    // Each pixel spans 2 pi / width in phi and cos(theta_top) - cos(theta_bottom) in
    // cos(theta): that is its solid angle.
    const float phi_width = 2.0f * kPi / static_cast<float>(m_width);
    for (int y = 0; y < m_height; ++y) {
        const float solid_angle = phi_width * row_cos_theta_span(y, m_height);
        Spectrum row(0.0f);
        for (int x = 0; x < m_width; ++x) row += pixel(x, y);
        m_radiance_integral += row * solid_angle;
    }
}

// The weight of a pixel is the integral of the lookup's luminance over it (the bilinear
// lookup integrates to a 3 x 3 tent stencil of pixel values), times the mean sin(theta)
// of its row, which converts map area to solid angle. So a pixel weighs nothing only
// where the lookup is black throughout. A floor at a thousandth of the mean weight keeps
// every direction sampleable all the same, so no direction with radiance ever has a zero
// light-sampling density (which multiple importance sampling relies on).
std::vector<float> EnvironmentLight::sampling_weights() const {
    if (m_width <= 0 || m_height <= 0 ||
        m_pixels.size() != static_cast<size_t>(m_width) * static_cast<size_t>(m_height)) {
        throw Error(fmt::format("EnvironmentLight: {} pixels for a {} x {} image", m_pixels.size(),
                                m_width, m_height));
    }
    std::vector<float> along_rows(m_pixels.size());
    for (int y = 0; y < m_height; ++y) {
        for (int x = 0; x < m_width; ++x) {
            const int left = (x + m_width - 1) % m_width, right = (x + 1) % m_width;
            along_rows[y * m_width + x] =
                kTentCentre * pixel(x, y).luminance() +
                kTentSide * (pixel(left, y).luminance() + pixel(right, y).luminance());
        }
    }
    std::vector<float> weights(m_pixels.size());
    double sum = 0.0;
    for (int y = 0; y < m_height; ++y) {
        const int above = std::max(y - 1, 0), below = std::min(y + 1, m_height - 1);
        const float row_angle = kPi / static_cast<float>(m_height);
        const float mean_sin_theta = row_cos_theta_span(y, m_height) / row_angle;
        for (int x = 0; x < m_width; ++x) {
            const float tent =
                kTentCentre * along_rows[y * m_width + x] +
                kTentSide * (along_rows[above * m_width + x] + along_rows[below * m_width + x]);
            weights[y * m_width + x] = tent * mean_sin_theta;
            sum += weights[y * m_width + x];
        }
    }
    const float floor = static_cast<float>(1e-3 * sum / static_cast<double>(weights.size()));
    for (float& w : weights) w = std::max(w, floor);
    return weights;
}

void EnvironmentLight::preprocess(const Vec3& scene_center, float scene_radius) {
    m_center = scene_center;
    m_radius = scene_radius;
}

Spectrum EnvironmentLight::lookup(const Vec2& uv) const {
    // Texel centres sit at (i + 0.5) / size; u wraps around the sphere, v stops at the poles.
    const float fx = uv.x * static_cast<float>(m_width) - 0.5f;
    const float fy = uv.y * static_cast<float>(m_height) - 0.5f;
    const float x_floor = std::floor(fx), y_floor = std::floor(fy);
    const float tx = fx - x_floor, ty = fy - y_floor;
    auto wrap = [&](int x) { return ((x % m_width) + m_width) % m_width; };
    auto clamp_row = [&](int y) { return std::clamp(y, 0, m_height - 1); };
    const int x0 = wrap(static_cast<int>(x_floor)), x1 = wrap(static_cast<int>(x_floor) + 1);
    const int y0 = clamp_row(static_cast<int>(y_floor)),
              y1 = clamp_row(static_cast<int>(y_floor) + 1);
    const Spectrum rgb = (pixel(x0, y0) * (1.0f - tx) + pixel(x1, y0) * tx) * (1.0f - ty) +
                         (pixel(x0, y1) * (1.0f - tx) + pixel(x1, y1) * tx) * ty;
    if (!spectral_mode_active()) return rgb;
    // The pixels were uplifted when no wavelengths were active: they hold RGB, which spectral
    // mode reads at the path's wavelengths.
    const auto v = rgb.stored();
    return uplift(Rgb(v[0], v[1], v[2]), RgbRole::illuminant);
}

Vec3 EnvironmentLight::direction_of(const Vec2& uv) const {
    const float theta = kPi * uv.y, phi = 2.0f * kPi * uv.x;
    const float sin_theta = std::sin(theta);
    const Vec3 in_map(-sin_theta * std::sin(phi), std::cos(theta), sin_theta * std::cos(phi));
    return glm::normalize(m_to_world * in_map);
}

Vec2 EnvironmentLight::uv_of(const Vec3& world_direction) const {
    return uv_in_map(glm::normalize(m_to_map * world_direction));
}

Vec2 EnvironmentLight::uv_in_map(const Vec3& d) {
    float phi = std::atan2(-d.x, d.z);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    return Vec2(std::min(phi / (2.0f * kPi), kOneMinusEpsilon),
                std::min(theta / kPi, kOneMinusEpsilon));
}

// A pixel covers 2 pi / width in phi and row_cos_theta_span in cos(theta); the map-space
// density is constant over it, so the solid-angle density is that over width * height times
// the pixel's solid angle.
float EnvironmentLight::direction_pdf(const Vec2& uv) const {
    const int row = std::min(static_cast<int>(uv.y * static_cast<float>(m_height)), m_height - 1);
    const float pixel_solid_angle =
        2.0f * kPi * row_cos_theta_span(row, m_height) / static_cast<float>(m_width);
    return m_distribution.pdf(uv) /
           (static_cast<float>(m_width) * static_cast<float>(m_height) * pixel_solid_angle);
}

EnvironmentLight::DirectionSample EnvironmentLight::sample_direction(const Vec2& u) const {
    const Distribution2D::ContinuousSample s = m_distribution.sample_continuous(u);
    // Where the sample fell inside its row, reused as a uniform fraction of the row's
    // cos(theta) span (from its top edge down).
    const float rows = static_cast<float>(m_height);
    const int row = std::min(static_cast<int>(s.point.y * rows), m_height - 1);
    const float fraction = std::clamp(s.point.y * rows - static_cast<float>(row), 0.0f, 1.0f);
    const float theta_top = kPi * static_cast<float>(row) / rows;
    // cos(theta_top) - cos(theta) = fraction * span, written without cancellation:
    // cos(theta) = cos(theta_top) - fraction * span.
    const float cos_theta =
        std::clamp(std::cos(theta_top) - fraction * row_cos_theta_span(row, m_height), -1.0f, 1.0f);
    DirectionSample d;
    d.uv = Vec2(s.point.x, std::min(std::acos(cos_theta) / kPi, kOneMinusEpsilon));
    // Keep the sample in its own row whatever rounding did.
    d.uv.y = std::clamp(d.uv.y, static_cast<float>(row) / rows,
                        std::nextafter(static_cast<float>(row + 1) / rows, 0.0f));
    d.direction = direction_of(d.uv);
    d.pdf = direction_pdf(d.uv);
    return d;
}

std::optional<LightSample> EnvironmentLight::sample_li(const Vec3& ref, const Vec2& u,
                                                       float) const {
    const DirectionSample d = sample_direction(u);
    if (!(d.pdf > 0.0f)) return std::nullopt;
    LightSample ls;
    ls.L = lookup(d.uv);
    if (ls.L.is_black()) return std::nullopt;
    ls.wi = d.direction;
    ls.pdf = d.pdf;
    // Farther than anything in the scene, whatever side of it `ref` is on.
    ls.p = ref + ls.wi * (2.0f * m_radius + glm::length(ref - m_center));
    return ls;
}

float EnvironmentLight::pdf_li_escaped(const Vec3& direction) const {
    return direction_pdf(uv_of(direction));
}

Spectrum EnvironmentLight::le_escaped(const Vec3& direction) const {
    return lookup(uv_of(direction));
}

// A direction towards the sky as sample_li draws it; the photon starts on the disk of
// the scene's radius that faces it, tangent to the bounding sphere on the sky's side,
// and travels back into the scene. Its weight is Le / (p(omega) p(disk point)).
std::optional<LightEmission> EnvironmentLight::sample_le(const Vec2& u_position,
                                                         const Vec2& u_direction, float) const {
    const DirectionSample d = sample_direction(u_direction);
    if (!(d.pdf > 0.0f)) return std::nullopt;
    const Spectrum L = lookup(d.uv);
    if (L.is_black()) return std::nullopt;
    const Vec3 to_sky = d.direction;
    const Frame frame = Frame::from_normal(to_sky);
    const Vec2 disk = warp::square_to_uniform_disk_concentric(u_position);
    LightEmission e;
    e.ray = Ray{m_center + m_radius * (to_sky + disk.x * frame.s() + disk.y * frame.t()), -to_sky};
    e.Le = L;
    e.pdf_pos = 1.0f / (kPi * m_radius * m_radius);
    e.pdf_dir = d.pdf;
    return e;
}

// The direction's density is sample_li's for the way back to the sky; every origin on the
// disc is equally likely.
EmissionPdf EnvironmentLight::pdf_le(const Ray& ray, const Vec3&) const {
    return {1.0f / (kPi * m_radius * m_radius), direction_pdf(uv_of(-ray.direction))};
}

Spectrum EnvironmentLight::power() const {
    return m_radiance_integral * (kPi * m_radius * m_radius);
}

// glint.environment{...}: image-based lighting from a light probe (mappings in the header
// and in environment_mapping.h; other layouts are resampled to lat-long once, at load).
//   file       string     required  any image glint reads (film/image_io.h), relative to the script's folder;
//                                    float files linear, integer files sRGB-decoded
//   mapping    string     "latlong" "latlong", "mirror_ball", "angular" or "cube_cross"
//   rotation   float      0         degrees about +y (right-handed: 90 turns -z to -x)
//   transform  transform  identity  a further rotation, after `rotation`; translation ignored
//   intensity  spectrum   1         >= 0, multiplies the image
std::unique_ptr<Light> make_environment_light(const Params& params, const std::string& directory) {
    std::filesystem::path path = params.get_string("file");
    // One turn at most: the sine of a float far from zero has no correct digits left.
    const float rotation = std::fmod(params.get_float("rotation", 0.0f), 360.0f);
    const Mat3 placement = Mat3(params.get_transform("transform").matrix());
    const Rgb intensity_rgb = params.get_rgb("intensity", Rgb(1.0f));
    const std::string mapping_name = params.get_string("mapping", "latlong");
    const std::optional<EnvironmentMapping> mapping = environment_mapping_named(mapping_name);
    if (!mapping) {
        params.fail(
            fmt::format("'mapping' must be \"latlong\", \"mirror_ball\", \"angular\" "
                        "or \"cube_cross\", not \"{}\"",
                        mapping_name));
    }
    if (intensity_rgb.min_value() < 0.0f) params.fail("'intensity' must not be negative");
    const Spectrum intensity = uplift(intensity_rgb, RgbRole::unbounded);
    if (!is_rotation(placement))
        params.fail("'transform' must be a rotation (no scale, shear or mirroring)");

    if (path.is_relative()) path = std::filesystem::path(directory) / path;
    if (!std::filesystem::is_regular_file(path))
        params.fail(fmt::format("environment map '{}' does not exist", path.string()));
    Image image;
    try {
        image = read_image(path.string());
    } catch (const Error& e) {
        params.fail(fmt::format("cannot read environment map: {}", e.what()));
    }
    if (image.width <= 0 || image.height <= 0)
        params.fail(fmt::format("environment map '{}' holds no image", path.string()));
    LatLongImage map;
    try {
        map = to_latlong(*mapping, radiance_pixels(image, params, path.string()), image.width,
                         image.height);
    } catch (const Error& e) {
        params.fail(fmt::format("environment map '{}': {}", path.string(), e.what()));
    }
    // The map's sums (its sampling weights, over up to 2^40 pixels, and its power) are
    // taken in float: radiance beyond this overflows them, so it is refused here, naming
    // the pixel (of the lat-long map the probe became), rather than failing later inside
    // the sampling tables.
    constexpr float kMaxRadiance = 1e18f;
    for (size_t i = 0; i < map.pixels.size(); ++i) {
        map.pixels[i] *= intensity;
        const float largest = map.pixels[i].max_value();
        if (!(largest <= kMaxRadiance)) {
            params.fail(fmt::format(
                "environment map '{}': pixel ({}, {}) times 'intensity' is {:g}, beyond the "
                "largest radiance an environment may hold ({:g}); scale the map down",
                path.string(), i % static_cast<size_t>(map.width),
                i / static_cast<size_t>(map.width), largest, kMaxRadiance));
        }
    }
    const Mat3 spin = Mat3(Transform::rotate(rotation, Vec3(0.0f, 1.0f, 0.0f)).matrix());
    return std::make_unique<EnvironmentLight>(std::move(map.pixels), map.width, map.height,
                                              placement * spin);
}

}  // namespace glint
