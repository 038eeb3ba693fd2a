#pragma once
// Warps from the unit square to common domains, each with its density. Every warp here
// has a chi-square test in tests/math/test_warp.cpp.
#include <glint/math/vector.h>

namespace glint::warp {

Vec2 square_to_uniform_disk_concentric(const Vec2& u);

Vec3 square_to_cosine_hemisphere(const Vec2& u);
float cosine_hemisphere_pdf(const Vec3& w);

Vec3 square_to_uniform_hemisphere(const Vec2& u);
float uniform_hemisphere_pdf(const Vec3& w);

Vec3 square_to_uniform_sphere(const Vec2& u);
float uniform_sphere_pdf();

// Directions within `cos_theta_max` of +z, uniform in solid angle.
Vec3 square_to_uniform_cone(const Vec2& u, float cos_theta_max);
float uniform_cone_pdf(const Vec3& w, float cos_theta_max);

// Barycentric coordinates (b1, b2) uniform over a triangle.
Vec2 square_to_uniform_triangle(const Vec2& u);

}  // namespace glint::warp
