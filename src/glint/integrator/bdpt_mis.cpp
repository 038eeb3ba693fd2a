#include <glint/integrator/bdpt_mis.h>

namespace glint {

float strategy_weight(std::span<const MisVertex> path, int s, bool delta_light,
                      MisHeuristic heuristic) {
    const int k = static_cast<int>(path.size());
    // A delta vertex's densities are stored as 0 and stand for the same discrete choice
    // on both sides: they count as 1 in a ratio.
    auto remap = [](float pdf) { return pdf != 0.0f ? static_cast<double>(pdf) : 1.0; };
    auto term = [&](double ratio) {
        return heuristic == MisHeuristic::kPower ? ratio * ratio : ratio;
    };
    double sum = 1.0;  // the strategy itself
    // Fewer light vertices: strategy i takes x_i from the camera's walk instead.
    double ratio = 1.0;
    for (int i = s - 1; i >= 0; --i) {
        ratio *= remap(path[i].pdf_camera) / remap(path[i].pdf_light);
        const bool possible = i == 0 ? !delta_light : !path[i].delta && !path[i - 1].delta;
        if (possible) sum += term(ratio);
    }
    // More light vertices: strategy i + 1 takes x_i from the light's walk; at least the lens
    // stays with the camera.
    ratio = 1.0;
    for (int i = s; i < k - 1; ++i) {
        ratio *= remap(path[i].pdf_light) / remap(path[i].pdf_camera);
        if (!path[i].delta && !path[i + 1].delta) sum += term(ratio);
    }
    return static_cast<float>(1.0 / sum);
}

}  // namespace glint
