#pragma once
// A density field sampled on a dense grid of voxels over an axis-aligned box: what a
// heterogeneous medium scales its coefficients by. Grid files (NanoVDB, OpenVDB) and the
// procedural cloud are all turned into one of these, so the tracking code sees one kind of
// field and the majorant grid can bound it exactly.
//
// Coordinates: `u` is the position in the box normalised to [0, 1]^3. Voxel (i, j, k) holds
// the density at its centre, u = ((i, j, k) + 0.5) / dims. Between centres the density is
// trilinear; between the outermost centres and the box's faces it is the nearest centre's
// (clamped); outside the box it is 0.
#include <glint/math/bounds.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <vector>

namespace glint {

/// An integer voxel index or resolution.
struct GridIndex {
    int x = 0, y = 0, z = 0;
    int operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
    friend bool operator==(const GridIndex&, const GridIndex&) = default;
};

class VoxelGrid {
public:
    /// The most voxels glint holds densely (2^27, 512 MiB of floats). A file whose bounding
    /// box holds more is refused before anything is allocated.
    static constexpr uint64_t kMaxVoxels = uint64_t{1} << 27;

    /// `values` in x-fastest order, dims.x * dims.y * dims.z of them, all finite and >= 0;
    /// `bounds` the box the grid covers (world or medium space). Throws glint::Error
    /// otherwise.
    VoxelGrid(GridIndex dims, std::vector<float> values, const Bounds3& bounds);

    const GridIndex& dims() const { return m_dims; }
    const Bounds3& bounds() const { return m_bounds; }
    float voxel(int x, int y, int z) const {
        return m_values[(static_cast<size_t>(z) * m_dims.y + y) * m_dims.x + x];
    }
    float max_value() const { return m_max; }

    /// The density at normalised position u (trilinear; 0 outside [0, 1]^3).
    float density(const Vec3& u) const;

    /// An upper bound of density(u) over the box [lo, hi] of normalised positions: the
    /// largest voxel whose value the trilinear interpolation can weigh inside it. Exact for a
    /// region that covers whole voxels.
    float max_density(const Vec3& lo, const Vec3& hi) const;

    /// The normalised position of a point given in the space of bounds().
    Vec3 normalised(const Vec3& p) const { return (p - m_bounds.min) / m_bounds.extent(); }

private:
    GridIndex m_dims;
    std::vector<float> m_values;
    Bounds3 m_bounds;
    float m_max = 0.0f;
};

/// Voxel count of `dims` as 64 bits (the product of three ints can overflow 32).
inline uint64_t voxel_count(const GridIndex& dims) {
    return static_cast<uint64_t>(dims.x) * static_cast<uint64_t>(dims.y) *
           static_cast<uint64_t>(dims.z);
}

}  // namespace glint
