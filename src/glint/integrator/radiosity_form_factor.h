#pragma once
// The form factor from a point to a triangle, by ray casting (Wallace, Elmquist and Haines
// 1989): the kernel of the radiosity solver's shooting step, and what its tests check
// against closed forms.
#include <glint/core/rng.h>
#include <glint/math/vector.h>

namespace glint {

class Scene;

/// A triangle that shoots: its corners (world space) and the unit normal of the side it
/// shoots from.
struct ShootingTriangle {
    Vec3 a, b, c;
    Vec3 n;
    float area = 0.0f;
};

/// The form factor F(dA_x -> T) from a differential area at `x` facing `n_x` (unit) to the
/// side of triangle T that faces along T.n: the fraction of the light leaving dA_x
/// diffusely that reaches T (equal, by reciprocity, to what x receives from T per unit of
/// T's radiosity).
///
/// T is cut into `samples` pieces of area A_T / samples, one point y_k drawn in each stratum
/// (a stratified uniform point on the triangle, from `rng`), and each piece is taken as a
/// disc facing x: F = sum_k V(x, y_k) cos_x cos_y dA / (pi r^2 + dA). The disc's exact
/// form factor stays finite when x is close to y_k, where the point-to-point term
/// cos cos dA / (pi r^2) would blow up; for small pieces it is that term. V is 1 when
/// `scene` is null, else whether the segment between the two points (each offset off its
/// surface) is free. Points behind either surface contribute nothing.
/// `rays` counts the visibility rays traced.
double point_to_triangle_form_factor(const Vec3& x, const Vec3& n_x, const ShootingTriangle& t,
                                     int samples, Rng& rng, const Scene* scene, uint64_t& rays);

/// The point of a triangle with stratified sample `k` of `samples` (u in [0, 1)^2 inside
/// that stratum): strata are slices of the first dimension, warped uniformly onto T.
Vec3 triangle_point(const ShootingTriangle& t, int k, int samples, const Vec2& u);

}  // namespace glint
