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
    };
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
        return {c.light, c.pmf};
    }
    /// The probability that sample(p, n, u) returns `light`.
    float pmf(const Vec3& p, const Vec3& n, const Light& light) const {
        return m_tree ? m_tree->pmf(p, n, light) : pmf(light);
    }

    bool empty() const { return m_lights.empty(); }
    LightSelection selection() const {
        return m_tree ? LightSelection::kTree : LightSelection::kPower;
    }
    /// The tree, when next-event estimation uses one.
    const LightTree* tree() const { return m_tree ? &*m_tree : nullptr; }

private:
    Choice sample_among_several(float u) const;

    std::vector<const Light*> m_lights;
    std::vector<float> m_pmf;
    std::vector<float> m_cdf;
    std::optional<LightTree> m_tree;
};

/// The light selection that the render setting `light_sampler` names ("tree", "power").
LightSelection light_selection_named(const std::string& name);

}  // namespace glint
