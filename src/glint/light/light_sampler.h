#pragma once
// Chooses one light, with a known probability for MIS. Two distributions:
// - by emitted power alone, independent of any point: where light paths, photons and the
//   bidirectional methods start (sample(u), pmf(light));
// - for a receiving point, for next-event estimation (sample(p, u), pmf(p, light)): the
//   light tree (light_tree.h) by default, or the power distribution again when the scene
//   asks for light_sampler = "power".
#include <glint/light/light.h>
#include <glint/light/light_tree.h>

#include <memory>
#include <optional>
#include <vector>

namespace glint {

enum class LightSelection {
    kPower,  ///< in proportion to power, the same everywhere
    kTree,   ///< a light tree, by each light's estimated contribution at the point
};

class LightSampler {
public:
    LightSampler() = default;
    // Assigns each light its index.
    explicit LightSampler(const std::vector<std::unique_ptr<Light>>& lights,
                          LightSelection selection = LightSelection::kPower);

    struct Choice {
        const Light* light = nullptr;
        float pmf = 0.0f;
        /// The piece of the light the tree chose (Light::piece_count), or kWholeLight where
        /// the light was chosen as a whole (by power).
        uint32_t piece = kWholeLight;
    };
    static constexpr uint32_t kWholeLight = LightTree::kWholeLight;
    /// A light in proportion to power (the start of a light path).
    Choice sample(float u) const {
        // One light (a Cornell box, a studio key light) is common: no search for it.
        if (m_lights.size() == 1) return {m_lights.front(), m_pmf.front()};
        return sample_among_several(u);
    }
    /// The probability that sample(u) returns `light`.
    float pmf(const Light& light) const;

    /// A light for next-event estimation at `p`, a point with unit normal `n` (zero for
    /// none); no light only when the scene has none.
    Choice sample(const Vec3& p, const Vec3& n, float u) const {
        if (!m_tree) return sample(u);
        const LightTree::Choice c = m_tree->sample(p, n, u);
        return {c.light, c.pmf, c.piece};
    }
    /// The probability that sample(p, n, u) returns `light` (a light of one piece: an
    /// infinite light, a sphere, a rectangle).
    float pmf(const Vec3& p, const Vec3& n, const Light& light) const {
        return m_tree ? m_tree->pmf(p, n, light) : pmf(light);
    }
    /// The probability that sample(p, n, u) returns piece `piece` of `light` (with power
    /// selection: the light itself, whichever piece).
    float pmf(const Vec3& p, const Vec3& n, const Light& light, uint32_t piece) const {
        return m_tree ? m_tree->pmf(p, n, light, piece) : pmf(light);
    }
    /// A point on the chosen light, seen from `ref`: within the chosen piece, or anywhere on
    /// the light when it was chosen whole.
    static std::optional<LightSample> sample_li(const Choice& choice, const Vec3& ref,
                                                const Vec2& u, float u_select) {
        return choice.piece == kWholeLight
                   ? choice.light->sample_li(ref, u, u_select)
                   : choice.light->sample_li_piece(ref, u, u_select, choice.piece);
    }
    /// The density with which next-event estimation from `p` (normal `n`) finds the point
    /// `on_light` (a hit on the area light on_light.area_light): choosing the light or its
    /// piece, times sample_li's density for the point. What MIS weighs a BSDF-sampled hit
    /// on an emitter with.
    float pdf_li(const Vec3& p, const Vec3& n, const SurfaceInteraction& on_light) const {
        const Light& light = *on_light.area_light;
        if (!m_tree) return pmf(light) * light.pdf_li(p, on_light);
        const uint32_t piece = light.piece_count() > 1 ? on_light.primitive : 0;
        return m_tree->pmf(p, n, light, piece) * light.pdf_li_piece(p, on_light, piece);
    }

    bool empty() const { return m_lights.empty(); }
    /// The selection the scene asked for (a scene of one light, which needs no tree, still
    /// says kTree when it asked for one).
    LightSelection selection() const { return m_selection; }
    /// The tree, when next-event estimation uses one (not for a single light of one piece).
    const LightTree* tree() const { return m_tree ? &*m_tree : nullptr; }

private:
    Choice sample_among_several(float u) const;

    std::vector<const Light*> m_lights;
    std::vector<float> m_pmf;
    std::vector<float> m_cdf;
    std::optional<LightTree> m_tree;
    LightSelection m_selection = LightSelection::kPower;
};

/// The light selection that the render setting `light_sampler` names ("tree", "power").
LightSelection light_selection_named(const std::string& name);

}  // namespace glint
