#include <glint/core/error.h>
#include <glint/geometry/csg/solid_shape.h>
#include <glint/geometry/user_geometry.h>

#include <fmt/format.h>

namespace glint {
namespace {

IntervalScratch& thread_scratch() {
    thread_local IntervalScratch scratch;
    return scratch;
}

void solid_bounds(const RTCBoundsFunctionArguments* args) {
    *args->bounds_o =
        to_embree_bounds(static_cast<const SolidShape*>(args->geometryUserPtr)->bounds());
}

void solid_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* shape = static_cast<const SolidShape*>(args->geometryUserPtr);
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for_each_valid_ray(args->valid, args->N, [&](unsigned i) {
        const std::optional<Crossing> crossing =
            shape->first_hit(ray_from_packet(rays, args->N, i));
        if (!crossing) return;
        RTCRayN_tfar(rays, args->N, i) = crossing->t;
        RTCHitN_Ng_x(hits, args->N, i) = crossing->normal.x;
        RTCHitN_Ng_y(hits, args->N, i) = crossing->normal.y;
        RTCHitN_Ng_z(hits, args->N, i) = crossing->normal.z;
        RTCHitN_u(hits, args->N, i) = 0.0f;
        RTCHitN_v(hits, args->N, i) = 0.0f;
        // One Embree primitive per solid, so the primitive id is free to carry the part.
        RTCHitN_primID(hits, args->N, i) = static_cast<unsigned>(crossing->leaf);
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
    });
}

void solid_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* shape = static_cast<const SolidShape*>(args->geometryUserPtr);
    for_each_valid_ray(args->valid, args->N, [&](unsigned i) {
        if (shape->any_hit(ray_from_packet(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;
    });
}

}  // namespace

SolidShape::SolidShape(std::shared_ptr<const Solid> solid, std::string name)
    : m_solid(std::move(solid)), m_name(std::move(name)) {
    if (!m_solid->is_bounded()) {
        throw Error(
            fmt::format("the {} is unbounded: give it 'bounds = {{{{xmin, ymin, zmin}}, {{xmax, "
                        "ymax, zmax}}}}' "
                        "or intersect it with a finite solid",
                        m_solid->describe()));
    }
    m_bounds = m_solid->bounds();
}

std::optional<Crossing> SolidShape::first_hit(const Ray& ray) const {
    IntervalScratch& scratch = thread_scratch();
    IntervalList& spans = scratch.acquire();
    m_solid->intervals(ray, spans, scratch);
    const Crossing* crossing = first_crossing_after(spans, ray.t_min);
    std::optional<Crossing> result;
    if (crossing && crossing->t < ray.t_max) result = *crossing;
    scratch.release(1);
    return result;
}

bool SolidShape::any_hit(const Ray& ray) const {
    return first_hit(ray).has_value();
}

RTCGeometry SolidShape::create_embree_geometry(RTCDevice device) const {
    return make_user_geometry(device, *this, solid_bounds, solid_intersect, solid_occluded);
}

void SolidShape::fill_interaction(const Ray& ray, const HitRecord& hit,
                                  SurfaceInteraction& si) const {
    si.p = ray.at(hit.t);
    si.p_object = si.p;
    si.ng = glm::normalize(hit.normal);
    // Solids have no uv, but bump and normal maps need a tangent frame that varies smoothly
    // over the surface: u runs around the y axis and v towards +y, as on a sphere, which
    // matches the "spherical" and "cylindrical" texture projections.
    const Vec3 around_y = glm::cross(si.ng, Vec3(0.0f, 1.0f, 0.0f));
    const float length = glm::length(around_y);
    si.dpdu = length > 1e-4f ? around_y / length : Frame::from_normal(si.ng).s();
    si.dpdv = glm::cross(si.dpdu, si.ng);
    si.shading = Frame::from_normal_tangent(si.ng, si.dpdu);
    si.uv = Vec2(0.0f);
    si.part = static_cast<int>(hit.primitive);
}

std::unique_ptr<ShapeSampler> SolidShape::make_sampler(const Transform&) const {
    throw Error(fmt::format(
        "a CSG {} cannot emit light (use an emissive sphere, quad or mesh as the light)",
        m_solid->describe()));
}

}  // namespace glint
