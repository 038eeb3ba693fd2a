#pragma once
// Embree scene management: one Embree scene per group prototype, placed in the world by
// Embree instances (one level, which is what Debian's Embree supports), plus the shapes
// of the root group directly in the world scene.
#include <glint/geometry/shape.h>

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint {

// Rays traced together as one Embree packet, and the per-lane arrays that go with them.
// Lanes are picked by a bit mask (bit i for lane i).
inline constexpr int kPacketWidth = 8;
template <typename T>
using PerLane = std::array<T, kPacketWidth>;
// Calls f(lane) for each lane set in `lanes`, in increasing order.
template <typename Function>
[[gnu::always_inline]] inline void for_each_lane(uint32_t lanes, Function&& f) {
    for (; lanes != 0; lanes &= lanes - 1) f(std::countr_zero(lanes));
}

class Accel {
public:
    Accel();
    ~Accel();
    Accel(const Accel&) = delete;
    Accel& operator=(const Accel&) = delete;

    // A new, empty prototype scene; returns its id.
    int add_prototype();
    // Adds `shape` to prototype `prototype` (or to the world scene when -1); returns the
    // geometry id it gets there. The shape must outlive the Accel.
    unsigned add_shape(int prototype, const Shape& shape);
    // Places a prototype in the world; returns the world geometry id of the instance.
    unsigned add_instance(int prototype, const Transform& to_world);
    // Builds all BVHs. Throws glint::Error when Embree reports a problem.
    void commit();

    // The closest hit along `ray`, written into `hit`; false (and `hit` untouched) when the
    // ray escapes. Inline and into the caller's record: the renderer calls it once per
    // bounce, and a returned optional<HitRecord> costs a copy and a default initialisation.
    bool intersect(const Ray& ray, HitRecord& hit) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh;
        rh.ray = embree_ray(ray.origin, ray.direction, ray.t_min, ray.t_max);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(m_world, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        hit.t = rh.ray.tfar;
        hit.primitive = rh.hit.primID;
        hit.barycentric = Vec2(rh.hit.u, rh.hit.v);
        hit.normal = Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
        const bool instanced = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
        hit.top_geometry = instanced ? rh.hit.instID[0] : rh.hit.geomID;
        hit.local_geometry = instanced ? rh.hit.geomID : RTC_INVALID_GEOMETRY_ID;
        return true;
    }
    std::optional<HitRecord> intersect(const Ray& ray) const {
        std::optional<HitRecord> result(std::in_place);
        if (!intersect(ray, *result)) result.reset();
        return result;
    }
    bool occluded(const Ray& ray) const;
    // The same for a segment given by its parts, for shadow rays, which need no Ray (and so
    // no differentials) built and copied. Inline: the path tracer traces one per bounce.
    bool occluded(const Vec3& origin, const Vec3& direction, float t_min, float t_max) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay r = embree_ray(origin, direction, t_min, t_max);
        rtcOccluded1(m_world, &context, &r);
        return r.tfar < 0.0f;  // Embree sets tfar to -inf when something blocks the segment
    }

    // Closest hits of the rays in the lanes set in `active`, traced together: each hit lane's
    // record in `hits` is written as intersect() writes it. Returns the lanes that hit.
    // `coherent` says the rays start close together and point the same way (the camera
    // rays of one pixel), so Embree traverses them as a group; otherwise it follows each
    // ray on its own, still sharing the packet's setup. Same hits as intersect() per lane;
    // a lone active lane goes through intersect() itself.
    uint32_t intersect_packet(const PerLane<const Ray*>& rays, uint32_t active,
                              PerLane<HitRecord>& hits, bool coherent) const;
    // The lanes among `active` whose segment origins[i] + t directions[i], t in
    // [0, t_max], is blocked; as occluded() per lane.
    uint32_t occluded_packet(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                             float t_max, uint32_t active, bool coherent) const;

    static const char* embree_version();

private:
    // The segment [t_min, t_max] of origin + t direction as Embree takes it: every ray
    // visible to every geometry, at time 0.
    static RTCRay embree_ray(const Vec3& origin, const Vec3& direction, float t_min, float t_max) {
        RTCRay r;
        r.org_x = origin.x;
        r.org_y = origin.y;
        r.org_z = origin.z;
        r.dir_x = direction.x;
        r.dir_y = direction.y;
        r.dir_z = direction.z;
        r.tnear = t_min;
        r.tfar = t_max;
        r.time = 0.0f;
        r.mask = 0xffffffffu;
        r.id = 0;
        r.flags = 0;
        return r;
    }
    void check_device(const char* what) const;

    RTCDevice m_device = nullptr;
    RTCScene m_world = nullptr;
    std::vector<RTCScene> m_prototypes;
};

}  // namespace glint
