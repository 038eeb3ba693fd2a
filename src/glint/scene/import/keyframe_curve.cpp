#include <glint/scene/import/keyframe_curve.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// The short-way spherical blend of unit quaternions a and b (x, y, z, w) by u, into out.
void slerp(const float* a, const float* b, float u, float* out) {
    float dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const float sign = dot < 0.0f ? -1.0f : 1.0f;
    dot = std::abs(dot);
    float wa = 1.0f - u, wb = u;
    // Nearly the same rotation: the blend's sine vanishes, and a linear blend is exact enough.
    if (dot < 0.9995f) {
        const float theta = std::acos(std::min(dot, 1.0f));
        const float sin_theta = std::sin(theta);
        wa = std::sin((1.0f - u) * theta) / sin_theta;
        wb = std::sin(u * theta) / sin_theta;
    }
    for (int c = 0; c < 4; ++c) out[c] = wa * a[c] + sign * wb * b[c];
}

void normalise(float* q) {
    const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (length > 0.0f)
        for (int c = 0; c < 4; ++c) q[c] /= length;
}

}  // namespace

bool KeyframeCurve::valid(const char** reason) const {
    const size_t per_key =
        static_cast<size_t>(components) * (interpolation == Interpolation::kCubicSpline ? 3 : 1);
    if (times.empty()) {
        *reason = "has no keyframes";
        return false;
    }
    if (values.size() != times.size() * per_key) {
        *reason = "has a different number of values than keyframe times";
        return false;
    }
    for (size_t i = 1; i < times.size(); ++i) {
        if (!(times[i] > times[i - 1])) {
            *reason = "has keyframe times that do not increase";
            return false;
        }
    }
    return true;
}

void KeyframeCurve::evaluate(float time, float* out) const {
    const int n = components;
    const bool cubic = interpolation == Interpolation::kCubicSpline;
    const size_t stride = static_cast<size_t>(n) * (cubic ? 3 : 1);
    // The key's value: after the in-tangent for CUBICSPLINE.
    const auto value = [&](size_t key) { return &values[key * stride + (cubic ? n : 0)]; };
    const auto finish = [&] {
        if (n == 4) normalise(out);
    };
    if (times.size() == 1 || !(time > times.front())) {
        std::copy_n(value(0), n, out);
        return finish();
    }
    if (!(time < times.back())) {
        std::copy_n(value(times.size() - 1), n, out);
        return finish();
    }
    const size_t next =
        static_cast<size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin());
    const size_t key = next - 1;
    const float dt = times[next] - times[key];
    const float u = (time - times[key]) / dt;
    switch (interpolation) {
        case Interpolation::kStep:
            std::copy_n(value(key), n, out);
            break;
        case Interpolation::kLinear:
            if (n == 4) {
                slerp(value(key), value(next), u, out);
            } else {
                for (int c = 0; c < n; ++c)
                    out[c] = (1.0f - u) * value(key)[c] + u * value(next)[c];
            }
            break;
        case Interpolation::kCubicSpline: {
            const float* out_tangent = &values[key * stride + 2 * n];
            const float* in_tangent = &values[next * stride];
            const float u2 = u * u, u3 = u2 * u;
            const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
            const float h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
            for (int c = 0; c < n; ++c) {
                out[c] = h00 * value(key)[c] + h10 * dt * out_tangent[c] + h01 * value(next)[c] +
                         h11 * dt * in_tangent[c];
            }
            break;
        }
    }
    finish();
}

}  // namespace glint
