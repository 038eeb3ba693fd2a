#pragma once
// The radiosity mesh: the scene's diffuse and emitting triangle surfaces cut into patches
// (the shooters of progressive refinement) and elements (the receivers, subdivided where the
// radiosity changes quickly), with radiosity stored at the element vertices.
//
// Every input triangle is cut by a uniform n x n grid into n^2 patches, n chosen so that no
// patch edge exceeds the patch size. Each patch is the root of a quadtree of elements: an
// element splits into four at its edge midpoints. Vertices are shared inside an input
// triangle (the grid's, and the midpoints of edges split by both neighbours); across input
// triangles they are not shared, but both copies sit at the same point and receive the same
// radiosity. An element next to a split one keeps its edge whole (a T-vertex): the display
// interpolates across that edge without the midpoint.
//
// Spheres, quadrics and CSG solids are not meshed: they occlude in the solve, and the
// display pass shades them itself (radiosity.h). Neither are mirrors, glass and glossy
// surfaces: only materials whose BSDF is purely diffuse reflection, and emitters.
#include <glint/core/spectrum.h>
#include <glint/geometry/shape.h>
#include <glint/integrator/radiosity/radiosity_form_factor.h>

#include <array>
#include <optional>
#include <unordered_map>
#include <vector>

namespace glint {

class Scene;

/// A point where radiosity is stored. Two sides: side 0 is where `n` points.
struct RadiosityVertex {
    Vec3 p;        ///< world position where form factors are evaluated
    Vec3 n;        ///< unit normal of its input triangle (by the winding, in world space)
    Spectrum rho;  ///< diffuse reflectance of the surface there
    std::array<Spectrum, 2> b{Spectrum(0.0f), Spectrum(0.0f)};  ///< reflected radiosity, W m^-2
    /// The part of `b` that came straight from the lights (what the hybrid's direct pass
    /// computes exactly instead).
    std::array<Spectrum, 2> b_direct{Spectrum(0.0f), Spectrum(0.0f)};
};

/// A triangle of the quadtree under a patch.
struct RadiosityElement {
    std::array<uint32_t, 3> v;  ///< vertex indices
    std::array<Vec2, 3> uv;    ///< the corners in the input triangle's barycentrics (Embree's u, v)
    int32_t first_child = -1;  ///< the four children are consecutive; -1 for a leaf
    uint32_t patch = 0;
    float area = 0.0f;
};

/// A shooter: one cell of an input triangle's grid.
struct RadiosityPatch {
    ShootingTriangle triangle;  ///< corners, front normal (side 0) and area
    uint32_t element = 0;       ///< its root element
    Spectrum rho;               ///< mean reflectance (for the ambient term)
    /// Radiosity leaving each side that has not been shot yet (W m^-2), emission included
    /// until the first shot; and the part of it that is emission.
    std::array<Spectrum, 2> unshot{Spectrum(0.0f), Spectrum(0.0f)};
    std::array<Spectrum, 2> unshot_emission{Spectrum(0.0f), Spectrum(0.0f)};
};

/// Which placed shape a meshed input triangle came from.
struct RadiosityTriangle {
    uint32_t first_patch = 0;  ///< its n^2 patches are consecutive, row by row
    uint32_t grid = 1;         ///< n
};

/// Where a hit lies in the mesh: the leaf element and the hit's barycentric weights of its
/// three vertices.
struct RadiosityLocation {
    uint32_t element = 0;
    Vec3 weights{1.0f, 0.0f, 0.0f};
};

class RadiosityMesh {
public:
    /// Meshes `scene`'s diffuse and emitting triangle surfaces (patch edges at most
    /// `patch_size`, > 0). Throws glint::Error when that would make more than `max_patches`.
    static RadiosityMesh build(const Scene& scene, float patch_size, size_t max_patches);

    /// The leaf element a hit lies on, or nullopt when the hit's surface is not meshed.
    std::optional<RadiosityLocation> locate(const HitRecord& hit) const;
    /// Gouraud interpolation of a per-vertex quantity at a location.
    template <typename Get>
    Spectrum interpolate(const RadiosityLocation& at, Get&& get) const {
        const RadiosityElement& e = elements[at.element];
        return get(vertices[e.v[0]]) * at.weights.x + get(vertices[e.v[1]]) * at.weights.y +
               get(vertices[e.v[2]]) * at.weights.z;
    }
    /// Splits leaf `element` into four (its midpoints shared with a neighbour that split
    /// already); the new vertices' radiosity is interpolated from the edge's ends. Returns
    /// the index of the first child; the vertices made are appended to `vertices`.
    uint32_t split(uint32_t element);
    /// Longest edge of an element, in world units.
    float longest_edge(uint32_t element) const;

    /// Memory the mesh holds per leaf element (vertices, elements, patches and input
    /// triangles, as stored; the lookup tables left out), for the solve's summary.
    double bytes_per_element() const;

    /// A hash of what the solve depends on, taken by build(): every patch's corners and
    /// emission and every vertex's reflectance. A saved solution is only valid for a mesh
    /// with the same fingerprint.
    uint64_t fingerprint_at_build = 0;

    std::vector<RadiosityVertex> vertices;
    std::vector<RadiosityElement> elements;
    std::vector<RadiosityPatch> patches;
    std::vector<RadiosityTriangle> triangles;
    /// Cohen et al.'s ambient term at the end of the solve: the radiosity the unshot light
    /// would still add, spread evenly (W m^-2, times the reflectance where it is shown).
    Spectrum ambient{0.0f};
    /// The area lights that are meshed (their patches shoot); other lights shoot by sampling.
    std::vector<const Light*> meshed_lights;

private:
    uint64_t fingerprint() const;

    struct Surface {
        uint32_t first_triangle = 0;
    };
    // The point of input triangle `triangle` at barycentrics `uv`, in world space.
    Vec3 point_of_triangle(size_t triangle, const Vec2& uv) const;
    // (top geometry << 32 | local geometry) -> index into m_surfaces.
    std::unordered_map<uint64_t, Surface> m_surfaces;
    // Per input triangle: its world corners, for new vertices.
    std::vector<std::array<Vec3, 3>> m_corners;
    // Midpoints made so far: (smaller vertex << 32 | larger vertex) -> vertex.
    std::unordered_map<uint64_t, uint32_t> m_midpoints;
    std::vector<uint32_t> m_patch_triangle;  // input triangle of each patch
};

}  // namespace glint
