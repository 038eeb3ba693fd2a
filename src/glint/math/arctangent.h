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
/// The polynomial goes by Estrin's scheme (pairs, then pairs of pairs): a chain of about
/// five multiply-adds where Horner's rule made one of nine, which the callers waited on.
[[gnu::always_inline]] inline float atan2_finite(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float big = std::max(ax, ay), small = std::min(ax, ay);
    const float a = big > 0.0f ? small / big : 0.0f;
    // atan(a) = a P(s), s = a^2, as a + a (P(s) - 1): the small correction rounds less.
    const float s = a * a, s2 = s * s, s4 = s2 * s2;
    const float q01 = -0.3333303671f + 0.1999187203f * s;
    const float q23 = -0.1419779779f + 0.1061837064f * s;
    const float q45 = -0.07456854826f + 0.04213762359f * s;
    const float q67 = -0.01573124912f + 0.002766283502f * s;
    const float q = (q01 + q23 * s2) + (q45 + q67 * s2) * s4;
    float angle = a + a * (-1.82e-8f + s * q);  // atan(a), in [0, pi/4]
    if (ay > ax) angle = 0.5f * kPi - angle;
    if (std::signbit(x)) angle = kPi - angle;
    return std::copysign(angle, y);
}

}  // namespace glint
