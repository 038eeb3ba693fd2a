#include <glint/integrator/radiosity/radiosity_form_factor.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/math/warp.h>
#include <glint/scene/scene.h>

#include <array>

namespace glint {
namespace {

using DVec3 = glm::dvec3;

// The unoccluded form factor from dA_x (normal n) to a convex polygon (Lambert 1760;
// Baum, Rushmeier and Winget 1989): F = 1/(2 pi) sum_i gamma_i n . unit(R_i x R_i+1), R_i
// the corners seen from x and gamma_i the angle between consecutive ones. The polygon is
// first clipped to the half-space in front of dA_x, since the formula counts what lies
// behind the tangent plane too.
double polygon_form_factor(const DVec3& x, const DVec3& n, const std::array<DVec3, 3>& corners) {
    std::array<DVec3, 4> clipped;
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        const DVec3& a = corners[i];
        const DVec3& b = corners[(i + 1) % 3];
        const double da = glm::dot(n, a - x), db = glm::dot(n, b - x);
        if (da >= 0.0) clipped[count++] = a;
        if ((da >= 0.0) != (db >= 0.0) && count < 4)
            clipped[count++] = a + (b - a) * (da / (da - db));
    }
    if (count < 3) return 0.0;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        const DVec3 r0 = clipped[i] - x, r1 = clipped[(i + 1) % count] - x;
        const DVec3 c = glm::cross(r0, r1);
        const double length = glm::length(c);
        if (!(length > 0.0)) continue;
        const double angle = std::atan2(length, glm::dot(r0, r1));
        sum += angle * glm::dot(n, c) / length;
    }
    return std::abs(sum) / (2.0 * kPi);
}

}  // namespace

Vec3 triangle_point(const ShootingTriangle& t, int k, int samples, const Vec2& u) {
    const Vec2 s((static_cast<float>(k) + u.x) / static_cast<float>(samples), u.y);
    const Vec2 b = warp::square_to_uniform_triangle(s);
    return (1.0f - b.x - b.y) * t.a + b.x * t.b + b.y * t.c;
}

double point_to_triangle_form_factor(const Vec3& x, const Vec3& n_x, const ShootingTriangle& t,
                                     int samples, Rng& rng, const Scene* scene, uint64_t& rays) {
    // x behind the shooting side sees none of it (the triangle is planar).
    if (!(glm::dot(t.n, x - t.a) > 0.0f)) {
        for (int k = 0; k < 2 * samples; ++k) rng.next_float();
        return 0.0;
    }
    const double exact =
        polygon_form_factor(DVec3(x), DVec3(n_x), {DVec3(t.a), DVec3(t.b), DVec3(t.c)});
    const double piece = static_cast<double>(t.area) / samples;
    double weight = 0.0, visible = 0.0;
    for (int k = 0; k < samples; ++k) {
        // Both draws always, so that later strata do not depend on earlier ones' fate.
        const Vec2 u(rng.next_float(), rng.next_float());
        if (!scene || !(exact > 0.0)) continue;
        const Vec3 y = triangle_point(t, k, samples, u);
        const Vec3 d = y - x;
        const double r2 = glm::dot(d, d);
        if (!(r2 > 0.0)) continue;
        const double r = std::sqrt(r2);
        const double cos_x = glm::dot(n_x, d) / r;
        const double cos_y = -glm::dot(t.n, d) / r;
        if (cos_x <= 0.0 || cos_y <= 0.0) continue;
        const double w = cos_x * cos_y * piece / (kPi * r2 + piece);
        weight += w;
        ++rays;
        const Vec3 from = offset_ray_origin(x, n_x, d);
        const Vec3 to = offset_ray_origin(y, t.n, -d);
        // Surfaces that only bound media (interfaces) let the exchange through.
        if (!transmittance(*scene, from, to).is_black()) visible += w;
    }
    if (!scene) return exact;
    return weight > 0.0 ? exact * (visible / weight) : 0.0;
}

}  // namespace glint
