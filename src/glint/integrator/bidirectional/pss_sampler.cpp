#include <glint/core/error.h>
#include <glint/integrator/bidirectional/pss_sampler.h>

#include <cmath>
#include <numbers>

namespace glint {

PssSampler::PssSampler(uint64_t key, float sigma, float large_step_probability)
    : Sampler(1, key), m_sigma(sigma), m_large_step_probability(large_step_probability) {
    reseed(key);
}

void PssSampler::reseed(uint64_t key) {
    m_rng.seed(mix_bits(key));
}

void PssSampler::start_iteration() {
    // The first iteration must make every value it reads: there is no state to perturb.
    const float u = m_rng.next_float();
    m_large_step = m_iteration == 0 || u < m_large_step_probability;
    ++m_iteration;
    m_stream = kCameraStream;
    m_next.fill(0);
}

void PssSampler::set_stream(int stream) {
    if (stream < 0 || stream >= kStreamCount) throw Error("PssSampler: no such stream");
    m_stream = stream;
}

void PssSampler::accept() {
    if (m_large_step) m_last_large_step = m_iteration;
}

void PssSampler::reject() {
    for (Value& v : m_values) {
        if (v.modified != m_iteration) continue;
        v.value = v.backup;
        v.modified = v.backup_modified;
    }
    --m_iteration;
}

float PssSampler::peek(int stream, int index) const {
    const size_t dimension = static_cast<size_t>(index) * kStreamCount + stream;
    return dimension < m_values.size() ? m_values[dimension].value : 0.0f;
}

void PssSampler::start_pixel_sample(Vec2i, int) {
    throw Error("the primary-sample-space sampler is not positioned by pixel and sample index");
}

float PssSampler::get_1d() {
    const int dimension = m_next[m_stream]++ * kStreamCount + m_stream;
    return update(dimension);
}

Vec2 PssSampler::get_2d() {
    const float x = get_1d();
    return Vec2(x, get_1d());
}

std::unique_ptr<Sampler> PssSampler::clone() const {
    return std::make_unique<PssSampler>(*this);
}

float PssSampler::update(int dimension) {
    if (dimension >= static_cast<int>(m_values.size())) m_values.resize(dimension + 1);
    Value& v = m_values[dimension];
    if (v.modified == m_iteration) return v.value;  // read twice in one iteration
    v.backup = v.value;
    v.backup_modified = v.modified;
    if (m_large_step) {
        v.value = m_rng.next_float();
    } else {
        // A large step accepted since this value was last read replaced it (lazily, now).
        if (v.modified < m_last_large_step) {
            v.value = m_rng.next_float();
            v.modified = m_last_large_step;
        }
        // The small steps it missed, one for each accepted iteration since: their sum is
        // normal with variance n sigma^2. Box-Muller from two uniform values.
        const double n = static_cast<double>(m_iteration - v.modified);
        const double u1 = m_rng.next_double(), u2 = m_rng.next_double();
        const double z =
            std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
        double x = v.value + m_sigma * std::sqrt(n) * z;
        x -= std::floor(x);
        // Rounding may give exactly 1 (x a hair below 0 wraps to 1 - 1e-17).
        v.value = x < 1.0 ? static_cast<float>(x) : 0.0f;
        if (v.value >= 1.0f) v.value = std::nextafter(1.0f, 0.0f);
    }
    v.modified = m_iteration;
    return v.value;
}

}  // namespace glint
