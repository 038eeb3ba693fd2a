#include <glint/camera/camera.h>
#include <glint/view/reprojection.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace glint {
namespace {

// How far along an escaped ray its point is put: far enough that a translation of the
// camera does not move it on the film, near enough for float precision.
constexpr float kMissDepth = 1e6f;

bool same_surface(const GeometryBuffer& current, std::size_t i, const GeometryBuffer& previous,
                  std::size_t j, float expected_depth, const ReprojectionTolerances& tol) {
    if (!current.hit(i)) return !previous.hit(j);
    if (previous.object_id[j] != current.object_id[i]) return false;
    if (std::abs(previous.depth[j] - expected_depth) > tol.relative_depth * expected_depth)
        return false;
    return glm::dot(previous.normal[j], current.normal[i]) >= tol.min_normal_cosine;
}

HistoryTaps taps_of(const GeometryBuffer& current, std::size_t i, const Ray& ray,
                    const GeometryBuffer& previous, const Camera& previous_camera,
                    const ReprojectionTolerances& tol) {
    HistoryTaps taps;
    const Vec3 point =
        ray.origin + (current.hit(i) ? current.depth[i] : kMissDepth) * ray.direction;
    const std::optional<FilmProjection> projected = previous_camera.project(point);
    // Off the previous frame there is no history, even where a tap at its edge would reach.
    if (!projected || !(projected->film.x >= 0.0f && projected->film.y >= 0.0f &&
                        projected->film.x <= static_cast<float>(previous.width) &&
                        projected->film.y <= static_cast<float>(previous.height)))
        return taps;
    // Pixel centres sit at half-integers: the taps are the four centres around the position.
    const float fx = projected->film.x - 0.5f, fy = projected->film.y - 0.5f;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
    float total = 0.0f;
    int kept = 0;
    for (int k = 0; k < 4; ++k) {
        const int x = x0 + (k & 1), y = y0 + (k >> 1);
        const float w = ((k & 1) ? tx : 1.0f - tx) * ((k >> 1) ? ty : 1.0f - ty);
        if (w < tol.min_weight || x < 0 || y < 0 || x >= previous.width || y >= previous.height)
            continue;
        const std::size_t j = static_cast<std::size_t>(y) * previous.width + x;
        if (!same_surface(current, i, previous, j, projected->depth, tol)) continue;
        taps.index[kept] = static_cast<int32_t>(j);
        taps.weight[kept] = w;
        total += w;
        ++kept;
    }
    for (int k = 0; k < kept; ++k) taps.weight[k] /= total;
    return taps;
}

}  // namespace

std::vector<HistoryTaps> reproject(const GeometryBuffer& current, const Camera& current_camera,
                                   const GeometryBuffer& previous, const Camera& previous_camera,
                                   const ReprojectionTolerances& tolerances) {
    std::vector<HistoryTaps> result(current.size());
    tbb::parallel_for(
        tbb::blocked_range<int>(0, current.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                for (int x = 0; x < current.width; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * current.width + x;
                    const Ray ray =
                        current_camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
                    result[i] = taps_of(current, i, ray, previous, previous_camera, tolerances);
                }
            }
        });
    return result;
}

}  // namespace glint
