#pragma once
// One animated property of a glTF node over time (an animation sampler): keyframe times and
// values, interpolated as glTF 2.0 specifies: STEP holds each key's value, LINEAR blends
// neighbours (rotations by slerp, the short way round), CUBICSPLINE follows the Hermite
// curve through each key with its in- and out-tangents. Free of tinygltf: gltf.cpp reads the
// accessors into it.
#include <vector>

namespace glint {

struct KeyframeCurve {
    enum class Interpolation { kStep, kLinear, kCubicSpline };
    Interpolation interpolation = Interpolation::kLinear;
    /// 3 for translation and scale, 4 for a rotation quaternion (x, y, z, w).
    int components = 3;
    /// Keyframe times in seconds, ascending.
    std::vector<float> times;
    /// `components` floats per key; CUBICSPLINE: three such per key (in-tangent, value,
    /// out-tangent), as glTF stores them.
    std::vector<float> values;

    /// Whether times and values agree in count, and times ascend; the reason otherwise.
    bool valid(const char** reason) const;
    /// The value at `time` (held at the first or last key outside their span) into `out`
    /// (`components` floats). Rotations come out unit length.
    void evaluate(float time, float* out) const;
};

}  // namespace glint
