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
/// The unoccluded form factor is exact (the contour integral over T's edges, T clipped to
/// the half-space in front of x); visibility comes from rays (Wallace et al. 1989): T is cut
/// into `samples` strata of area dA = A_T / samples, a point y_k drawn in each (from `rng`),
/// and the result is the exact form factor times the visible fraction of the strata, each
/// weighted by its disc form factor cos_x cos_y dA / (pi r^2 + dA). Fully visible or fully
/// hidden triangles are thus exact whatever their size and distance, which the disc sum
/// alone is not near a shared edge (it misses up to a third there). With `scene` null
/// nothing occludes. `rays` counts the visibility rays traced.
double point_to_triangle_form_factor(const Vec3& x, const Vec3& n_x, const ShootingTriangle& t,
                                     int samples, Rng& rng, const Scene* scene, uint64_t& rays);

/// The point of a triangle with stratified sample `k` of `samples` (u in [0, 1)^2 inside
/// that stratum): strata are slices of the first dimension, warped uniformly onto T.
Vec3 triangle_point(const ShootingTriangle& t, int k, int samples, const Vec2& u);

}  // namespace glint
