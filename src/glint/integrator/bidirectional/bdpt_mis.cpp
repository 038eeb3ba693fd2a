#include <glint/integrator/bidirectional/bdpt_mis.h>

namespace glint {

float strategy_weight(std::span<const MisVertex> path, int s, bool delta_light,
                      MisHeuristic heuristic) {
    return vcm_strategy_weight(path, s, false, delta_light, 0.0f, heuristic);
}

float vcm_strategy_weight(std::span<const MisVertex> path, int s, bool merge, bool delta_light,
                          float merge_eta, MisHeuristic heuristic, float light_tracing_count) {
    const int k = static_cast<int>(path.size());
    // A delta vertex's densities are stored as 0 and stand for the same discrete choice
    // on both sides: they count as 1 in a ratio.
    auto remap = [](float pdf) { return pdf != 0.0f ? static_cast<double>(pdf) : 1.0; };
    auto term = [&](double ratio) {
        return heuristic == MisHeuristic::kPower ? ratio * ratio : ratio;
    };
    // Every density below is relative to p_s, that of the connection with s light vertices.
    const bool merging = merge_eta > 0.0f;
    const double eta = merge_eta;
    auto can_merge = [&](int i) {
        return merging && i >= 1 && i <= k - 2 && !path[i].delta && path[i].merge_scale > 0.0f;
    };
    // The merge at x_i relative to p_s, given ratio = p_i / p_s.
    auto merge_term = [&](int i, double ratio) {
        return term(ratio * remap(path[i].pdf_light) * eta * path[i].merge_scale);
    };
    // The sample count of connection j: light tracing (j = k - 1) is done n_L / n_C times per
    // camera subpath, every other connection once.
    const double light_tracing = light_tracing_count;
    auto count = [&](int j) { return j == k - 1 ? light_tracing : 1.0; };
    double own = term(count(s));
    double sum = own;  // the strategy itself
    if (merge) {
        // The merge at x_s; the connection s counts as any other strategy.
        own = merge_term(s, 1.0);
        const bool connection = s == 0 ? !delta_light : !path[s].delta && !path[s - 1].delta;
        sum = own + (connection ? 1.0 : 0.0);
    } else if (can_merge(s)) {
        sum += merge_term(s, 1.0);
    }
    // Fewer light vertices: strategy i takes x_i from the camera's walk instead.
    double ratio = 1.0;
    for (int i = s - 1; i >= 0; --i) {
        ratio *= remap(path[i].pdf_camera) / remap(path[i].pdf_light);
        const bool possible = i == 0 ? !delta_light : !path[i].delta && !path[i - 1].delta;
        if (possible) sum += term(ratio);
        if (can_merge(i)) sum += merge_term(i, ratio);
    }
    // More light vertices: strategy i + 1 takes x_i from the light's walk; at least the lens
    // stays with the camera.
    ratio = 1.0;
    for (int i = s; i < k - 1; ++i) {
        ratio *= remap(path[i].pdf_light) / remap(path[i].pdf_camera);
        if (!path[i].delta && !path[i + 1].delta) sum += term(ratio * count(i + 1));
        if (can_merge(i + 1)) sum += merge_term(i + 1, ratio);
    }
    return static_cast<float>(own / sum);
}

}  // namespace glint
