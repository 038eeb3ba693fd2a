#pragma once
// atan2 for float arguments, inline. The renderer asks it for every hit on a sphere (its u
// coordinate) and for every equiangular distance: in the preview in fog, glibc's atan2f
// (three calls deep: a wrapper, atan2 and atan) cost about 100 cycles a call, 2.3 % of a
// frame. This one is a division, a polynomial and three selects.
//
// The angle is reduced to a = min(|x|, |y|) / max(|x|, |y|) in [0, 1], whose arc tangent
// a P(a^2) comes from a polynomial P of degree 8 in a^2, fitted (a Chebyshev fit of
// atan(sqrt(s)) / sqrt(s) on [0, 1], made with mpmath's chebyfit) to within 1.8e-8 of
// the exact value; then pi/2 - angle where |y| > |x|, pi - angle where x < 0, and the sign
// of y. tests/math/test_arctangent.cpp holds it to within 2 units in the last place of the
// correctly rounded atan2 over every range of ratios, and to its values on the axes and at
// signed zeros. Its arguments must be finite (glibc's handles infinities too).
#include <glint/math/vector.h>

#include <algorithm>
#include <cmath>

namespace glint {

/// atan2(y, x) in [-pi, pi] for finite y and x, within 2 ulp of the correctly rounded value.
inline float atan2_finite(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float big = std::max(ax, ay), small = std::min(ax, ay);
    const float a = big > 0.0f ? small / big : 0.0f;
    const float s = a * a;
    float p = 0.002766283502f;
    p = p * s - 0.01573124912f;
    p = p * s + 0.04213762359f;
    p = p * s - 0.07456854826f;
    p = p * s + 0.1061837064f;
    p = p * s - 0.1419779779f;
    p = p * s + 0.1999187203f;
    p = p * s - 0.3333303671f;
    p = p * s + 0.9999999818f;
    float angle = a * p;  // atan(a), in [0, pi/4]
    if (ay > ax) angle = 0.5f * kPi - angle;
    if (std::signbit(x)) angle = kPi - angle;
    return std::copysign(angle, y);
}

}  // namespace glint
