// Build time and memory of the light tree over many emissive triangles (issue 31): n
// triangles (default 10^6) scattered over a sphere's surface, each a light with the bounds
// an emissive triangle has (its box, its normal, power by area), then one LightTree; then
// the same triangles as one emitting mesh, whose triangles are the tree's leaves.
// Usage: glint_bench_light_tree_build [n]
#include <glint/core/rng.h>
#include <glint/geometry/mesh.h>
#include <glint/light/area_light.h>
#include <glint/light/light.h>
#include <glint/light/light_sampler.h>
#include <glint/light/light_tree.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

using namespace glint;

namespace {

// A light that only has bounds: the tree reads nothing else while it is built.
class BoundsOnlyLight final : public Light {
public:
    explicit BoundsOnlyLight(const LightBounds& b) : m_bounds(b) {}
    std::optional<LightEmission> sample_le(const Vec2&, const Vec2&, float) const override {
        return std::nullopt;
    }
    EmissionPdf pdf_le(const Ray&, const Vec3&) const override { return {}; }
    Spectrum emitted(const Vec3&, const Vec3&, const Vec3&) const override {
        return Spectrum(0.0f);
    }
    std::optional<LightSample> sample_li(const Vec3&, const Vec2&, float) const override {
        return std::nullopt;
    }
    Spectrum power() const override { return Spectrum(m_bounds.phi); }
    bool is_delta() const override { return false; }
    std::optional<LightBounds> bounds() const override { return m_bounds; }

private:
    LightBounds m_bounds;
};

}  // namespace

int main(int argc, char** argv) {
    const size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    Rng rng(1);
    std::vector<BoundsOnlyLight> lights;
    lights.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const float z = 1.0f - 2.0f * rng.next_float(), phi = 6.2831853f * rng.next_float();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Vec3 c(10.0f * r * std::cos(phi), 10.0f * r * std::sin(phi), 10.0f * z);
        LightBounds b;
        b.bounds.expand(c - Vec3(0.01f));
        b.bounds.expand(c + Vec3(0.01f));
        b.phi = 1e-4f * (0.5f + rng.next_float());
        b.normals = DirectionCone{glm::normalize(c), 1.0f, false};
        b.cos_theta_e = 0.0f;
        lights.emplace_back(b);
        lights.back().set_index(static_cast<int>(i));
    }
    auto start = std::chrono::steady_clock::now();
    std::vector<LightTree::Entry> entries;
    entries.reserve(n);
    for (const BoundsOnlyLight& light : lights) entries.push_back({&light, *light.bounds()});
    const LightTree tree(std::move(entries), {}, n);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print("{} lights: tree built in {:.3f} s, {} nodes, {:.1f} MB\n", n, seconds,
               tree.node_count(), static_cast<double>(tree.memory_bytes()) / 1e6);

    // The same triangles as one emitting mesh, as a scene holds it: one AreaLight whose
    // pieces (its triangles) are the tree's leaves, built by the LightSampler.
    MeshData mesh;
    mesh.positions.reserve(3 * n);
    for (const BoundsOnlyLight& light : lights) {
        const Vec3 c = light.bounds()->bounds.center();
        const Frame frame = Frame::from_normal(glm::normalize(c));
        const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.push_back(c + 0.01f * frame.s());
        mesh.positions.push_back(c + 0.01f * frame.t());
        mesh.positions.push_back(c - 0.01f * frame.s());
        for (uint32_t k = 0; k < 3; ++k) mesh.indices.push_back(first + k);
    }
    lights.clear();
    lights.shrink_to_fit();
    const TriangleMesh shape("emitter", std::move(mesh));
    std::vector<std::unique_ptr<Light>> scene_lights;
    start = std::chrono::steady_clock::now();
    scene_lights.push_back(
        std::make_unique<AreaLight>(shape.make_sampler(Transform()), Spectrum(1.0f), false));
    const LightSampler sampler(scene_lights, LightSelection::kTree);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print(
        "one mesh of {} emitting triangles: light and tree built in {:.3f} s, {} nodes, "
        "{:.1f} MB\n",
        scene_lights.front()->piece_count(), seconds, sampler.tree()->node_count(),
        static_cast<double>(sampler.tree()->memory_bytes()) / 1e6);
    return 0;
}
