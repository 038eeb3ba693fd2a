#include <glint/integrator/radiosity_form_factor.h>
#include <glint/math/warp.h>
#include <glint/scene/scene.h>

namespace glint {

Vec3 triangle_point(const ShootingTriangle& t, int k, int samples, const Vec2& u) {
    const Vec2 s((static_cast<float>(k) + u.x) / static_cast<float>(samples), u.y);
    const Vec2 b = warp::square_to_uniform_triangle(s);
    return (1.0f - b.x - b.y) * t.a + b.x * t.b + b.y * t.c;
}

double point_to_triangle_form_factor(const Vec3& x, const Vec3& n_x, const ShootingTriangle& t,
                                     int samples, Rng& rng, const Scene* scene, uint64_t& rays) {
    const double piece = static_cast<double>(t.area) / samples;
    double sum = 0.0;
    for (int k = 0; k < samples; ++k) {
        // Both draws always, so that later strata do not depend on earlier ones' fate.
        const Vec2 u(rng.next_float(), rng.next_float());
        const Vec3 y = triangle_point(t, k, samples, u);
        const Vec3 d = y - x;
        const double r2 = glm::dot(d, d);
        if (!(r2 > 0.0)) continue;
        const double r = std::sqrt(r2);
        const double cos_x = glm::dot(n_x, d) / r;
        const double cos_y = -glm::dot(t.n, d) / r;
        if (cos_x <= 0.0 || cos_y <= 0.0) continue;
        if (scene) {
            ++rays;
            const Vec3 from = offset_ray_origin(x, n_x, d);
            const Vec3 to = offset_ray_origin(y, t.n, -d);
            if (scene->accel().occluded(from, to - from, 0.0f, kShadowRayEnd)) continue;
        }
        sum += cos_x * cos_y * piece / (kPi * r2 + piece);
    }
    return sum;
}

}  // namespace glint
