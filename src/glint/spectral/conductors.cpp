#include <glint/spectral/conductors.h>

#include <glint/spectral/conductor_data.h>
#include <glint/spectral/spectrum_to_rgb.h>

#include <glint/core/strings.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace glint::spectral {
namespace {

struct Entry {
    std::vector<std::string> names;  // the symbol first, then aliases
    ConductorData data;
};

const std::vector<Entry>& all_conductors() {
    static const std::vector<Entry> table = {
        {{"Au", "gold"}, ConductorData("Au", data::kGoldJohnsonChristy)},
        {{"Ag", "silver"}, ConductorData("Ag", data::kSilverJohnsonChristy)},
        {{"Cu", "copper"}, ConductorData("Cu", data::kCopperJohnsonChristy)},
        {{"Al", "aluminium", "aluminum"}, ConductorData("Al", data::kAluminiumRakic)},
    };
    return table;
}

}  // namespace

ConductorData::ConductorData(std::string name, std::vector<Sample> samples)
    : m_name(std::move(name)), m_samples(std::move(samples)) {
    if (m_samples.empty()) throw std::invalid_argument("a conductor needs measured samples");
    m_rgb_eta = quantity_to_rgb([this](double nm) { return eval(float(nm)).eta; });
    m_rgb_k = quantity_to_rgb([this](double nm) { return eval(float(nm)).k; });
}

ComplexIor ConductorData::eval(float nm) const {
    if (nm <= m_samples.front().nm) return {m_samples.front().eta, m_samples.front().k};
    if (nm >= m_samples.back().nm) return {m_samples.back().eta, m_samples.back().k};
    const auto hi = std::upper_bound(m_samples.begin(), m_samples.end(), nm,
                                     [](float v, const Sample& s) { return v < s.nm; });
    const auto lo = hi - 1;
    const float t = (nm - lo->nm) / (hi->nm - lo->nm);
    return {lo->eta + t * (hi->eta - lo->eta), lo->k + t * (hi->k - lo->k)};
}

const ConductorData* named_conductor(std::string_view name) {
    const std::string wanted = to_lower(name);
    for (const Entry& e : all_conductors())
        for (const std::string& n : e.names)
            if (to_lower(n) == wanted) return &e.data;
    return nullptr;
}

std::vector<std::string> conductor_names() {
    std::vector<std::string> names;
    for (const Entry& e : all_conductors())
        names.insert(names.end(), e.names.begin(), e.names.end());
    return names;
}

}  // namespace glint::spectral
