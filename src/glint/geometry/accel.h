#pragma once
// Embree scene management: one Embree scene per group prototype, placed in the world by
// Embree instances (one level, which is what Debian's Embree supports), plus the shapes
// of the root group directly in the world scene.
#include <glint/geometry/shape.h>
#include <glint/math/motion_transform.h>

#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
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

/// The pass-through surfaces (Accel::set_pass_through) one traversal went past, in order
/// along the ray (Accel::intersect_passing): the interfaces that bound media, which a walk
/// carrying a medium crosses without scattering.
struct PassedSurfaces {
    static constexpr int kCapacity = 8;
    std::array<HitRecord, kCapacity> hits;
    int count = 0;
};

/// Every query's context: Embree's, and for a query that records pass-through surfaces
/// where it keeps them (null for every other query, for which those surfaces are hits as
/// any other).
struct QueryContext {
    RTCIntersectContext embree;
    PassedSurfaces* passed = nullptr;
    bool overflowed = false;  ///< more than PassedSurfaces::kCapacity came by
    /// A packet query's records instead, one per lane (each ray's id is its lane), and the
    /// lanes that overflowed theirs.
    PassedSurfaces* lanes = nullptr;
    uint32_t overflowed_lanes = 0;
};

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
    // Places a prototype on a moving transform: Embree interpolates the keys' parts
    // (TransformParts) over the ray's time as MotionTransform::at does.
    unsigned add_instance(int prototype, const MotionTransform& to_world);
    // Marks a shape of the world scene (not of a prototype) as one intersect_passing() goes
    // past; every other query still stops at it. Before commit().
    void set_pass_through(unsigned world_geometry);
    // Builds all BVHs. Throws glint::Error when Embree reports a problem.
    void commit();

    // The closest hit along `ray`, written into `hit`; false (and `hit` untouched) when the
    // ray escapes. Inline and into the caller's record: the renderer calls it once per
    // bounce, and a returned optional<HitRecord> costs a copy and a default initialisation.
    bool intersect(const Ray& ray, HitRecord& hit) const {
        if (!embree_accepts(ray.origin, ray.direction, ray.t_min, ray.t_max)) [[unlikely]]
            return drop_ray();
        QueryContext context;
        rtcInitIntersectContext(&context.embree);
        return closest_hit(ray, context, hit);
    }
    std::optional<HitRecord> intersect(const Ray& ray) const {
        std::optional<HitRecord> result(std::in_place);
        if (!intersect(ray, *result)) result.reset();
        return result;
    }
    // intersect() past the pass-through surfaces, in one traversal: the closest hit of any
    // other surface, and in `passed` the pass-through surfaces before it (before the ray's
    // end on a miss), in order. Where more come by than `passed` holds, or one is of a kind
    // Embree cannot skip (user geometry: spheres, quadrics), it is the hit, as for
    // intersect(): the caller crosses it and traces on.
    bool intersect_passing(const Ray& ray, HitRecord& hit, PassedSurfaces& passed) const;
    // intersect_passing() for the rays in the lanes set in `active`, traced together as
    // intersect_packet() traces them: each lane's hit and crossings as intersect_passing()
    // gives them for that ray alone (a lane whose crossings overflow is traced again alone).
    // Returns the lanes that hit.
    uint32_t intersect_packet_passing(const PerLane<const Ray*>& rays, uint32_t active,
                                      PerLane<HitRecord>& hits, PerLane<PassedSurfaces>& passed,
                                      bool coherent) const;
    // occluded() past the pass-through surfaces, in one any-hit traversal: whether another
    // surface blocks `ray`'s segment, and when none does, in `passed` the pass-through
    // surfaces along it, in order. nullopt when more came by than `passed` holds (then ask
    // intersect_passing()). Only exact when every surface a walk should pass is marked
    // pass-through and Embree skips it (no user geometry): the scene decides.
    std::optional<bool> occluded_passing(const Ray& ray, PassedSurfaces& passed) const;
    bool occluded(const Ray& ray) const;
    // The same for a segment given by its parts, for shadow rays, which need no Ray (and so
    // no differentials) built and copied. Inline: the path tracer traces one per bounce.
    bool occluded(const Vec3& origin, const Vec3& direction, float t_min, float t_max,
                  float time = 0.0f) const {
        if (!embree_accepts(origin, direction, t_min, t_max)) [[unlikely]]
            return drop_ray();
        QueryContext context;
        rtcInitIntersectContext(&context.embree);
        RTCRay r = embree_ray(origin, direction, t_min, t_max, time);
        rtcOccluded1(m_world, &context.embree, &r);
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
    // [0, t_max], at scene time times[i], is blocked; as occluded() per lane.
    uint32_t occluded_packet(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                             const PerLane<float>& times, float t_max, uint32_t active,
                             bool coherent) const;
    // occluded_passing() for the lanes set in `active`, traced together as occluded_packet()
    // traces them: returns the blocked lanes; each lane that is not blocked gets in `passed`
    // the pass-through surfaces along its segment, in order, as occluded_passing() gives them
    // for that ray alone. Lanes whose crossings overflowed the record are neither: they are
    // set in `overflowed` (occluded_passing()'s nullopt), for the caller to trace otherwise.
    uint32_t occluded_packet_passing(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                                     const PerLane<float>& times, float t_max, uint32_t active,
                                     PerLane<PassedSurfaces>& passed, uint32_t& overflowed,
                                     bool coherent) const;

    /// Rays not traced because Embree would reject them (see embree_accepts()): each was
    /// answered as a miss, or as an unblocked shadow ray. Counted over every query so far,
    /// from any thread. A correct renderer never makes one; the count is there so that a
    /// bug upstream costs a few black or wrongly lit samples and a warning, not an abort
    /// inside Embree (which checks rays with assertions).
    uint64_t dropped_rays() const { return m_dropped_rays.load(std::memory_order_relaxed); }
    /// Bytes Embree holds now (its BVHs and its own copies of vertices and indices), as its
    /// device memory monitor reports them.
    int64_t embree_bytes() const { return m_embree_bytes.load(std::memory_order_relaxed); }

    /// Whether Embree takes this ray: every component of origin and direction at most
    /// 1.844e18 in magnitude (Embree's FLT_LARGE: not NaN, not infinite, not so large that
    /// its traversal overflows) and t_min, t_max not NaN (t_max may be infinite). What
    /// Embree's own ray validity check asks.
    static bool embree_accepts(const Vec3& origin, const Vec3& direction, float t_min,
                               float t_max) {
        // All eight tests in two 4-wide compares (GCC/Clang vector extensions, which map to
        // SSE or NEON): done one by one they cost some 30 instructions per ray, 3 % of the
        // path tracer's. A NaN fails every comparison; |t| <= inf only refuses NaN.
        using Float4 = float __attribute__((vector_size(16)));
        using Int4 = int32_t __attribute__((vector_size(16)));
        constexpr float kLarge = 1.844e18f;  // Embree's FLT_LARGE
        const Float4 a = {origin.x, origin.y, origin.z, direction.x};
        const Float4 b = {direction.y, direction.z, t_min, t_max};
        const Float4 a_limit = {kLarge, kLarge, kLarge, kLarge};
        const Float4 b_limit = {kLarge, kLarge, kInfinity, kInfinity};
        const Int4 abs_mask = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
        const Float4 abs_a = reinterpret_cast<Float4>(reinterpret_cast<Int4>(a) & abs_mask);
        const Float4 abs_b = reinterpret_cast<Float4>(reinterpret_cast<Int4>(b) & abs_mask);
        const Int4 ok = (abs_a <= a_limit) & (abs_b <= b_limit);  // -1 where it passes
        uint64_t halves[2];
        std::memcpy(halves, &ok, sizeof(halves));
        return (halves[0] & halves[1]) == ~uint64_t{0};
    }

    static const char* embree_version();

private:
    // Embree's closest hit along `ray` (already accepted) under `context`, written into `hit`;
    // false on a miss.
    bool closest_hit(const Ray& ray, QueryContext& context, HitRecord& hit) const {
        RTCRayHit rh;
        rh.ray = embree_ray(ray.origin, ray.direction, ray.t_min, ray.t_max, ray.time);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(m_world, &context.embree, &rh);
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
    // Readies `context` for a query that records the pass-through surfaces in `passed`
    // (emptied); false, with the ray counted as dropped, where Embree would refuse it.
    bool start_recording(const Ray& ray, PassedSurfaces& passed, QueryContext& context) const;
    // The packet query both intersect_packet() and intersect_packet_passing() make, under
    // `context` (recording per lane or not); returns the lanes that hit.
    uint32_t packet_closest_hits(const PerLane<const Ray*>& rays, uint32_t active,
                                 PerLane<HitRecord>& hits, QueryContext& context,
                                 bool coherent) const;
    // The shadow packet both occluded_packet() and occluded_packet_passing() trace, under
    // `context`; returns the blocked lanes (of `active`, less those Embree refuses).
    uint32_t packet_blocked(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                            const PerLane<float>& times, float t_max, uint32_t& active,
                            QueryContext& context, bool coherent) const;
    // Sorts the crossings a recording query found along the ray, drops repeats and those
    // not before `end`.
    static void order_crossings(PassedSurfaces& passed, float end);
    // Counts a ray embree_accepts() refused; returns false (a miss, or not blocked).
    // Out of line: the hot callers only pay for the test.
    [[gnu::cold, gnu::noinline]] bool drop_ray(uint64_t count = 1) const;

    // The segment [t_min, t_max] of origin + t direction as Embree takes it: every ray
    // visible to every geometry, at scene time `time` (Embree's time: motion keys spread
    // over [0, 1]; the camera keeps every ray's time there, as Embree requires).
    static RTCRay embree_ray(const Vec3& origin, const Vec3& direction, float t_min, float t_max,
                             float time) {
        RTCRay r;
        r.org_x = origin.x;
        r.org_y = origin.y;
        r.org_z = origin.z;
        r.dir_x = direction.x;
        r.dir_y = direction.y;
        r.dir_z = direction.z;
        r.tnear = t_min;
        r.tfar = t_max;
        r.time = time;
        r.mask = 0xffffffffu;
        r.id = 0;
        r.flags = 0;
        return r;
    }
    void check_device(const char* what) const;

    RTCDevice m_device = nullptr;
    RTCScene m_world = nullptr;
    std::vector<RTCScene> m_prototypes;
    mutable std::atomic<uint64_t> m_dropped_rays{0};
    std::atomic<int64_t> m_embree_bytes{0};  // written by Embree's memory monitor
};

}  // namespace glint
