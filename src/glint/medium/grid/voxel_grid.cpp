#include <glint/core/error.h>
#include <glint/medium/grid/voxel_grid.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

VoxelGrid::VoxelGrid(GridIndex dims, std::vector<float> values, const Bounds3& bounds)
    : m_dims(dims), m_values(std::move(values)), m_bounds(bounds) {
    if (dims.x < 1 || dims.y < 1 || dims.z < 1 || voxel_count(dims) > kMaxVoxels) {
        throw Error(
            fmt::format("voxel grid: resolution {}x{}x{} must be at least 1 and hold at "
                        "most {} voxels",
                        dims.x, dims.y, dims.z, kMaxVoxels));
    }
    if (m_values.size() != voxel_count(dims)) {
        throw Error(fmt::format("voxel grid: {} values for {}x{}x{} voxels", m_values.size(),
                                dims.x, dims.y, dims.z));
    }
    const Vec3 extent = bounds.extent();
    if (!(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f) ||
        !std::isfinite(extent.x + extent.y + extent.z)) {
        throw Error("voxel grid: the box must have a finite, positive size on every axis");
    }
    for (const float v : m_values) {
        if (!(v >= 0.0f) || !std::isfinite(v)) {
            throw Error(fmt::format("voxel grid: density {} is not a finite value >= 0", v));
        }
        m_max = std::max(m_max, v);
    }
}

float VoxelGrid::density(const Vec3& u) const {
    if (!(u.x >= 0.0f && u.x <= 1.0f && u.y >= 0.0f && u.y <= 1.0f && u.z >= 0.0f && u.z <= 1.0f)) {
        return 0.0f;
    }
    // Continuous voxel coordinates with centres at integers, clamped so that the half voxel
    // beside each face takes the outermost centre's value.
    const Vec3 x = glm::clamp(u * Vec3(m_dims.x, m_dims.y, m_dims.z) - 0.5f, Vec3(0.0f),
                              Vec3(m_dims.x - 1, m_dims.y - 1, m_dims.z - 1));
    const int x0 = std::min(static_cast<int>(x.x), m_dims.x - 1);
    const int y0 = std::min(static_cast<int>(x.y), m_dims.y - 1);
    const int z0 = std::min(static_cast<int>(x.z), m_dims.z - 1);
    const int x1 = std::min(x0 + 1, m_dims.x - 1);
    const int y1 = std::min(y0 + 1, m_dims.y - 1);
    const int z1 = std::min(z0 + 1, m_dims.z - 1);
    const float fx = x.x - x0, fy = x.y - y0, fz = x.z - z0;
    const auto lerp = [](float a, float b, float t) { return a + t * (b - a); };
    const float c00 = lerp(voxel(x0, y0, z0), voxel(x1, y0, z0), fx);
    const float c10 = lerp(voxel(x0, y1, z0), voxel(x1, y1, z0), fx);
    const float c01 = lerp(voxel(x0, y0, z1), voxel(x1, y0, z1), fx);
    const float c11 = lerp(voxel(x0, y1, z1), voxel(x1, y1, z1), fx);
    // A convex combination of the eight corners, so it never exceeds their maximum, which
    // is what makes max_density() a bound.
    return std::max(0.0f, lerp(lerp(c00, c10, fy), lerp(c01, c11, fy), fz));
}

float VoxelGrid::max_density(const Vec3& lo, const Vec3& hi) const {
    // The voxels density() can read for positions in [lo, hi]: the lower corner's cell of
    // the lowest position up to the upper corner's cell of the highest.
    const auto range = [](float a, float b, int n, int& first, int& last) {
        first = std::clamp(static_cast<int>(std::floor(a * n - 0.5f)), 0, n - 1);
        last = std::clamp(static_cast<int>(std::floor(b * n - 0.5f)) + 1, 0, n - 1);
    };
    int x0, x1, y0, y1, z0, z1;
    range(lo.x, hi.x, m_dims.x, x0, x1);
    range(lo.y, hi.y, m_dims.y, y0, y1);
    range(lo.z, hi.z, m_dims.z, z0, z1);
    float result = 0.0f;
    for (int z = z0; z <= z1; ++z) {
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) result = std::max(result, voxel(x, y, z));
        }
    }
    return result;
}

}  // namespace glint
