#include <glint/light/light_sampler.h>

#include <algorithm>

namespace glint {
namespace {

LightTree build_tree(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<LightTree::Entry> bounded;
    std::vector<const Light*> unbounded;
    bounded.reserve(lights.size());
    for (const std::unique_ptr<Light>& light : lights) {
        const uint32_t pieces = light->piece_count();
        if (pieces > 1) {
            // Every piece (an emitting mesh's triangle) a leaf of its own.
            for (uint32_t piece = 0; piece < pieces; ++piece) {
                if (std::optional<LightBounds> b = light->piece_bounds(piece))
                    bounded.push_back({light.get(), *b, piece, false});
            }
        } else if (std::optional<LightBounds> b = light->bounds()) {
            bounded.push_back({light.get(), *b, 0, true});
        } else {
            unbounded.push_back(light.get());
        }
    }
    return LightTree(std::move(bounded), std::move(unbounded), lights.size());
}

}  // namespace

LightSampler::LightSampler(const std::vector<std::unique_ptr<Light>>& lights,
                           LightSelection selection) {
    double total = 0.0;
    std::vector<double> weights;
    for (size_t i = 0; i < lights.size(); ++i) {
        lights[i]->set_index(static_cast<int>(i));
        m_lights.push_back(lights[i].get());
        const double w = std::max(0.0f, lights[i]->power().luminance());
        weights.push_back(w);
        total += w;
    }
    // Lights with no measurable power (all black) fall back to a uniform choice.
    if (!(total > 0.0)) {
        std::fill(weights.begin(), weights.end(), 1.0);
        total = static_cast<double>(weights.size());
    }
    double running = 0.0;
    for (double w : weights) {
        m_pmf.push_back(static_cast<float>(w / total));
        running += w / total;
        m_cdf.push_back(static_cast<float>(running));
    }
    if (!m_cdf.empty()) m_cdf.back() = 1.0f;
    // One light of one piece (a Cornell box's lamp) is chosen with probability 1 either
    // way: the power distribution's one-light shortcut does it without a tree walk.
    const bool one_choice = lights.size() == 1 && lights.front()->piece_count() == 1;
    // No lights (a scene lit only by a glowing medium, or not at all): no tree, and every
    // choice is empty.
    if (selection == LightSelection::kTree && !one_choice && !lights.empty())
        m_tree = build_tree(lights);
    m_selection = selection;
}

LightSampler::Choice LightSampler::sample_among_several(float u) const {
    if (m_lights.empty()) return {};
    auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), u);
    size_t i = std::min<size_t>(it - m_cdf.begin(), m_lights.size() - 1);
    while (m_pmf[i] == 0.0f && i > 0) --i;  // never pick a zero-probability light
    return {m_lights[i], m_pmf[i]};
}

float LightSampler::pmf(const Light& light) const {
    const int i = light.index();
    return (i >= 0 && static_cast<size_t>(i) < m_pmf.size()) ? m_pmf[i] : 0.0f;
}

LightSelection light_selection_named(const std::string& name) {
    return name == "power" ? LightSelection::kPower : LightSelection::kTree;
}

}  // namespace glint
