#pragma once
// Chooses one light for next-event estimation, in proportion to emitted power so that
// bright lights get the samples; every choice has a known probability for MIS.
#include <glint/light/light.h>

#include <memory>
#include <vector>

namespace glint {

class LightSampler {
public:
    LightSampler() = default;
    // Assigns each light its index.
    explicit LightSampler(const std::vector<std::unique_ptr<Light>>& lights);

    struct Choice {
        const Light* light = nullptr;
        float pmf = 0.0f;
    };
    Choice sample(float u) const {
        // One light (a Cornell box, a studio key light) is common: no search for it.
        if (m_lights.size() == 1) return {m_lights.front(), m_pmf.front()};
        return sample_among_several(u);
    }
    float pmf(const Light& light) const;
    bool empty() const { return m_lights.empty(); }

private:
    Choice sample_among_several(float u) const;

    std::vector<const Light*> m_lights;
    std::vector<float> m_pmf;
    std::vector<float> m_cdf;
};

}  // namespace glint
