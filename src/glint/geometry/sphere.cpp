#include <glint/core/error.h>
#include <glint/geometry/sphere.h>
#include <glint/geometry/user_geometry.h>
#include <glint/math/arctangent.h>
#include <glint/math/warp.h>

namespace glint {
namespace {

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
    *args->bounds_o = to_embree_bounds(static_cast<const Sphere*>(args->geometryUserPtr)->bounds());
}

void sphere_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* sphere = static_cast<const Sphere*>(args->geometryUserPtr);
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    const unsigned n = args->N;
    for_each_valid_ray(args->valid, n, [&](unsigned i) {
        // Only the parts the test needs: a whole Ray would also clear its differentials.
        const Vec3 o = packet_origin(rays, n, i), d = packet_direction(rays, n, i);
        float t0, t1;
        if (!sphere->intersect_interval(o, d, t0, t1)) return;
        const float t_near = RTCRayN_tnear(rays, n, i);
        float& t_far = RTCRayN_tfar(rays, n, i);
        const float t = t0 > t_near ? t0 : t1;
        if (!(t > t_near && t < t_far)) return;
        t_far = t;
        const Vec3 p = o + t * d;
        RTCHitN_Ng_x(hits, n, i) = p.x;
        RTCHitN_Ng_y(hits, n, i) = p.y;
        RTCHitN_Ng_z(hits, n, i) = p.z;
        RTCHitN_u(hits, n, i) = t == t0 ? 0.0f : 1.0f;  // which root, for CSG later
        RTCHitN_v(hits, n, i) = 0.0f;
        RTCHitN_primID(hits, n, i) = args->primID;
        RTCHitN_geomID(hits, n, i) = args->geomID;
        RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
    });
}

void sphere_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* sphere = static_cast<const Sphere*>(args->geometryUserPtr);
    RTCRayN* rays = args->ray;
    const unsigned n = args->N;
    for_each_valid_ray(args->valid, n, [&](unsigned i) {
        const Vec3 o = packet_origin(rays, n, i), d = packet_direction(rays, n, i);
        float t0, t1;
        if (!sphere->intersect_interval(o, d, t0, t1)) return;
        const float t_near = RTCRayN_tnear(rays, n, i);
        float& t_far = RTCRayN_tfar(rays, n, i);
        const bool hit = (t0 > t_near && t0 < t_far) || (t1 > t_near && t1 < t_far);
        if (hit) t_far = -kInfinity;  // Embree's convention for "occluded"
    });
}

// 1 - cos(theta_max) of the cone a sphere subtends, from sin^2(theta_max), without the
// cancellation of 1 - sqrt(1 - sin^2) (7% error at a distance of 1000 radii).
float one_minus_cos_cone(float sin2_max) {
    return sin2_max / (1.0f + safe_sqrt(1.0f - sin2_max));
}

}  // namespace

Sphere::Sphere(const Vec3& center, float radius, const Transform& to_parent) {
    if (!(radius > 0.0f) || !std::isfinite(radius)) throw Error("sphere radius must be positive");
    m_to_parent = to_parent * Transform::translate(center) * Transform::scale(Vec3(radius));
    m_parent_to_object = to_parent.inverse();
    const Mat4& m = m_to_parent.inverse_matrix();  // column-major: m[column][row]
    m_scale_and_offset = m[0][0] == m[1][1] && m[1][1] == m[2][2] && m[0][1] == 0.0f &&
                         m[0][2] == 0.0f && m[1][0] == 0.0f && m[1][2] == 0.0f && m[2][0] == 0.0f &&
                         m[2][1] == 0.0f && m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f &&
                         m[3][3] == 1.0f;
    m_scale = m[0][0];
    m_offset = Vec3(m[3]);
}

Bounds3 Sphere::bounds() const {
    Bounds3 unit;
    unit.expand(Vec3(-1.0f));
    unit.expand(Vec3(1.0f));
    return unit.transformed(m_to_parent);
}

bool Sphere::intersect_interval(const Vec3& origin, const Vec3& direction, float& t0,
                                float& t1) const {
    // The matrix products reduce to these when the off-diagonal entries are zero: adding
    // their zero terms changes no bit.
    const Vec3 o =
        m_scale_and_offset ? m_scale * origin + m_offset : m_to_parent.inverse().point(origin);
    const Vec3 d =
        m_scale_and_offset ? m_scale * direction : m_to_parent.inverse().vector(direction);
    const float a = glm::dot(d, d);
    const float b = glm::dot(o, d);
    const float c = glm::dot(o, o) - 1.0f;
    // Discriminant from the distance of the closest approach, which stays accurate for
    // distant rays where b*b - a*c cancels catastrophically: a (1 - |o - (b/a) d|^2), written
    // a - |o x d|^2 (the same by Lagrange's identity) so that a ray that misses, as most do,
    // waits on no division.
    const Vec3 across = glm::cross(o, d);
    const float discriminant = a - glm::dot(across, across);
    if (discriminant < 0.0f) return false;
    const float root = std::sqrt(discriminant);
    const float q = b < 0.0f ? -b + root : -b - root;
    if (q == 0.0f) return false;
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

RTCGeometry Sphere::create_embree_geometry(RTCDevice device) const {
    return make_user_geometry(device, *this, sphere_bounds, sphere_intersect, sphere_occluded);
}

void Sphere::fill_interaction(const Ray& ray, const HitRecord& hit, SurfaceInteraction& si) const {
    Vec3 p_object = Vec3(m_to_parent.inverse_matrix() * Vec4(ray.at(hit.t), 1.0f));
    p_object = glm::normalize(p_object);  // back onto the surface, removing the hit's error
    const float phi_raw = atan2_finite(p_object.z, p_object.x);
    const float phi = phi_raw < 0.0f ? phi_raw + 2.0f * kPi : phi_raw;
    const float theta = std::acos(std::clamp(p_object.y, -1.0f, 1.0f));
    // y is the pole; u runs around it, v from the south pole (0) up to the north pole (1),
    // so that an image's top row lies at the north pole.
    si.uv = Vec2(phi * kInv2Pi, 1.0f - theta * kInvPi);
    const Vec3 dpdu_object(-2.0f * kPi * p_object.z, 0.0f, 2.0f * kPi * p_object.x);
    const float sin_theta = safe_sqrt(1.0f - p_object.y * p_object.y);
    // cos(phi) and sin(phi) from the point itself (x and z over their length round the
    // pole; phi = 0 at the poles, as atan2 gives it there), not from phi: a sine and a
    // cosine fewer per hit.
    const float around = std::sqrt(p_object.x * p_object.x + p_object.z * p_object.z);
    const float cos_phi = around > 0.0f ? p_object.x / around : 1.0f;
    const float sin_phi = around > 0.0f ? p_object.z / around : 0.0f;
    const Vec3 dpdv_object = -kPi * Vec3(p_object.y * cos_phi, -sin_theta, p_object.y * sin_phi);

    si.p = m_to_parent.point(p_object);
    si.p_object = m_parent_to_object.point(si.p);
    si.ng = glm::normalize(m_to_parent.normal(p_object));
    si.dpdu = m_to_parent.vector(dpdu_object);
    si.dpdv = m_to_parent.vector(dpdv_object);
    si.shading = Frame::from_normal_tangent(si.ng, si.dpdu);
}

std::unique_ptr<ShapeSampler> Sphere::make_sampler(const Transform& to_world) const {
    const Transform full = to_world * m_to_parent;
    const Vec3 center = full.point(Vec3(0.0f));
    const Vec3 axes(glm::length(full.vector(Vec3(1, 0, 0))),
                    glm::length(full.vector(Vec3(0, 1, 0))),
                    glm::length(full.vector(Vec3(0, 0, 1))));
    if (max_component(axes) > 1.0001f * min_component(axes)) {
        throw Error("an emissive sphere cannot be scaled non-uniformly");
    }
    return std::make_unique<SphereSampler>(center, axes.x);
}

ShapeSample SphereSampler::sample_area(const Vec2& u, float) const {
    const Vec3 n = warp::square_to_uniform_sphere(u);
    return {m_center + m_radius * n, n, 1.0f / area()};
}

ShapeSample SphereSampler::sample(const Vec3& ref, const Vec2& u, float) const {
    const Vec3 to_center = m_center - ref;
    const float dist2 = glm::dot(to_center, to_center);
    ShapeSample s;
    if (dist2 <= m_radius * m_radius * 1.0001f) {
        // Inside (or on) the sphere: uniform area sampling.
        s.n = warp::square_to_uniform_sphere(u);
        s.p = m_center + m_radius * s.n;
        s.pdf = area_to_solid_angle_pdf(1.0f / area(), ref, s.p, s.n);
        return s;
    }
    // A direction uniform in the cone the sphere subtends, through x = 1 - cos(theta) with
    // sin(theta) from x (for a distant sphere cos(theta) itself is only a few float steps
    // below 1), and the point it reaches found from its angle alpha at the centre rather
    // than by tracing the direction to the sphere: by the sine rule in the triangle ref,
    // centre, point, with s = sin(theta) / sin(theta_max) (at most 1) and the near point,
    // alpha = asin(s) - theta, so that
    //   cos(alpha) = cos(theta) sqrt(1 - s^2) + s sin(theta),
    //   sin(alpha) = sin(theta) (cos(theta) / sin(theta_max) - sqrt(1 - s^2)),
    // neither of which cancels. A shorter chain of square roots and divisions than the
    // traced point, which the renderer waits on at every light sample.
    const float dist = std::sqrt(dist2);
    const float inverse_sin_max = dist / m_radius;
    const float one_minus_cos_max = one_minus_cos_cone(m_radius * m_radius / dist2);
    const float x = u.x * one_minus_cos_max;
    const float sin2_theta = x * (2.0f - x);
    const float sin_theta = std::sqrt(sin2_theta);
    const float cos_theta = 1.0f - x;
    const float s2 = sin2_theta * (inverse_sin_max * inverse_sin_max);
    const float cos_beyond = safe_sqrt(1.0f - s2);  // sqrt(1 - s^2): cos(asin s)
    const float cos_alpha = cos_theta * cos_beyond + sin2_theta * inverse_sin_max;
    const float sin_alpha = std::max(sin_theta * (cos_theta * inverse_sin_max - cos_beyond), 0.0f);
    const float phi = 2.0f * kPi * u.y;
    // The normal: alpha away from the axis back towards ref, on the side of the direction.
    const Frame frame = Frame::from_normal(to_center / dist);
    const float cos_phi = std::cos(phi), sin_phi = std::sin(phi);
    s.n = frame.to_world(Vec3(sin_alpha * cos_phi, sin_alpha * sin_phi, -cos_alpha));
    s.p = m_center + m_radius * s.n;
    s.direction = frame.to_world(Vec3(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta));
    s.pdf = 1.0f / (2.0f * kPi * one_minus_cos_max);
    return s;
}

float SphereSampler::pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    const Vec3 to_center = m_center - ref;
    const float dist2 = glm::dot(to_center, to_center);
    if (dist2 <= m_radius * m_radius * 1.0001f)
        return area_to_solid_angle_pdf(1.0f / area(), ref, p, n);
    return 1.0f / (2.0f * kPi * one_minus_cos_cone(m_radius * m_radius / dist2));
}

}  // namespace glint
