#include <glint/core/error.h>
#include <glint/geometry/accel.h>

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>

namespace glint {

Accel::Accel() {
    m_device = rtcNewDevice(nullptr);
    if (!m_device) throw Error("could not create the Embree device");
    // Counts what Embree allocates (and frees) on this device; Accel does not move (its
    // atomics make it immovable), so `this` stays valid for the device's life.
    rtcSetDeviceMemoryMonitorFunction(
        m_device,
        [](void* user, ssize_t bytes, bool) {
            static_cast<Accel*>(user)->m_embree_bytes.fetch_add(bytes, std::memory_order_relaxed);
            return true;
        },
        this);
    m_world = rtcNewScene(m_device);
    rtcSetSceneBuildQuality(m_world, RTC_BUILD_QUALITY_HIGH);
}

Accel::~Accel() {
    for (RTCScene scene : m_prototypes) rtcReleaseScene(scene);
    if (m_world) rtcReleaseScene(m_world);
    if (m_device) rtcReleaseDevice(m_device);
}

void Accel::check_device(const char* what) const {
    const RTCError error = rtcGetDeviceError(m_device);
    if (error != RTC_ERROR_NONE) {
        throw Error(
            fmt::format("Embree failed while {} (error code {})", what, static_cast<int>(error)));
    }
}

int Accel::add_prototype() {
    RTCScene scene = rtcNewScene(m_device);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    m_prototypes.push_back(scene);
    return static_cast<int>(m_prototypes.size()) - 1;
}

unsigned Accel::add_shape(int prototype, const Shape& shape) {
    RTCGeometry geometry = shape.create_embree_geometry(m_device);
    const unsigned id =
        rtcAttachGeometry(prototype < 0 ? m_world : m_prototypes.at(prototype), geometry);
    rtcReleaseGeometry(geometry);
    check_device("adding a shape");
    return id;
}

unsigned Accel::add_instance(int prototype, const Transform& to_world) {
    RTCGeometry instance = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, m_prototypes.at(prototype));
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                            &to_world.matrix()[0][0]);
    rtcCommitGeometry(instance);
    const unsigned id = rtcAttachGeometry(m_world, instance);
    rtcReleaseGeometry(instance);
    check_device("placing a group instance");
    return id;
}

unsigned Accel::add_instance(int prototype, const MotionTransform& to_world) {
    if (!to_world.is_moving()) return add_instance(prototype, to_world.key(0));
    if (to_world.key_count() > RTC_MAX_TIME_STEP_COUNT) {
        throw Error(fmt::format("a motion has {} keys; Embree takes at most {}",
                                to_world.key_count(), RTC_MAX_TIME_STEP_COUNT));
    }
    RTCGeometry instance = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, m_prototypes.at(prototype));
    rtcSetGeometryTimeStepCount(instance, static_cast<unsigned>(to_world.key_count()));
    for (size_t step = 0; step < to_world.key_count(); ++step) {
        const TransformParts& parts = to_world.parts(step);
        RTCQuaternionDecomposition embree_parts;
        rtcInitQuaternionDecomposition(&embree_parts);
        embree_parts.scale_x = parts.scale.x;
        embree_parts.scale_y = parts.scale.y;
        embree_parts.scale_z = parts.scale.z;
        embree_parts.skew_xy = parts.shear.x;
        embree_parts.skew_xz = parts.shear.y;
        embree_parts.skew_yz = parts.shear.z;
        embree_parts.quaternion_r = parts.rotation.w;
        embree_parts.quaternion_i = parts.rotation.x;
        embree_parts.quaternion_j = parts.rotation.y;
        embree_parts.quaternion_k = parts.rotation.z;
        embree_parts.translation_x = parts.translation.x;
        embree_parts.translation_y = parts.translation.y;
        embree_parts.translation_z = parts.translation.z;
        rtcSetGeometryTransformQuaternion(instance, static_cast<unsigned>(step), &embree_parts);
    }
    rtcCommitGeometry(instance);
    const unsigned id = rtcAttachGeometry(m_world, instance);
    rtcReleaseGeometry(instance);
    check_device("placing a moving group instance");
    return id;
}

void Accel::commit() {
    for (RTCScene scene : m_prototypes) rtcCommitScene(scene);
    rtcCommitScene(m_world);
    check_device("building the acceleration structure");
}

bool Accel::drop_ray(uint64_t count) const {
    m_dropped_rays.fetch_add(count, std::memory_order_relaxed);
    return false;
}

namespace {

// The filter of pass-through surfaces: in a recording query (QueryContext::passed) each hit
// is noted and refused, so the traversal goes on past it; in any other query it stands.
// Embree may offer one triangle more than once (its high-quality build splits references,
// and a packet traversal offers a lane the triangles of leaves its neighbours reached): a
// triangle already noted is refused without a second note, so that repeats cannot fill the
// record; order_crossings() removes the repeats that remain (the two triangles of an edge).
bool already_noted(const PassedSurfaces& passed, unsigned primitive, unsigned geometry) {
    for (int k = 0; k < passed.count; ++k)
        if (passed.hits[k].primitive == primitive && passed.hits[k].top_geometry == geometry)
            return true;
    return false;
}

void pass_through_filter(const RTCFilterFunctionNArguments* args) {
    auto* context = reinterpret_cast<QueryContext*>(args->context);
    if (!context->passed && !context->lanes) return;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        // A packet query's ray carries its lane as its id.
        const unsigned lane = context->lanes ? RTCRayN_id(args->ray, args->N, i) : 0;
        PassedSurfaces* passed = context->lanes ? &context->lanes[lane] : context->passed;
        if (already_noted(*passed, RTCHitN_primID(args->hit, args->N, i),
                          RTCHitN_geomID(args->hit, args->N, i))) {
            args->valid[i] = 0;
            continue;
        }
        if (passed->count == PassedSurfaces::kCapacity) {
            context->overflowed = true;
            context->overflowed_lanes |= 1u << lane;
            continue;  // kept as a hit; intersect_passing() then traces without recording
        }
        args->valid[i] = 0;
        HitRecord& hit = passed->hits[passed->count++];
        hit.t = RTCRayN_tfar(args->ray, args->N, i);  // the candidate hit's distance
        hit.primitive = RTCHitN_primID(args->hit, args->N, i);
        hit.barycentric = Vec2(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
        hit.normal = Vec3(RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                          RTCHitN_Ng_z(args->hit, args->N, i));
        hit.top_geometry = RTCHitN_geomID(args->hit, args->N, i);
        hit.local_geometry = RTC_INVALID_GEOMETRY_ID;  // world shapes only
    }
}

}  // namespace

void Accel::set_pass_through(unsigned world_geometry) {
    RTCGeometry geometry = rtcGetGeometry(m_world, world_geometry);
    rtcSetGeometryIntersectFilterFunction(geometry, pass_through_filter);
    rtcSetGeometryOccludedFilterFunction(geometry, pass_through_filter);
    rtcCommitGeometry(geometry);
    check_device("marking a pass-through surface");
}

bool Accel::start_recording(const Ray& ray, PassedSurfaces& passed, QueryContext& context) const {
    passed.count = 0;
    if (!embree_accepts(ray.origin, ray.direction, ray.t_min, ray.t_max)) [[unlikely]]
        return drop_ray();
    rtcInitIntersectContext(&context.embree);
    context.passed = &passed;
    return true;
}

bool Accel::intersect_passing(const Ray& ray, HitRecord& hit, PassedSurfaces& passed) const {
    QueryContext context;
    if (!start_recording(ray, passed, context)) return false;
    const bool found = closest_hit(ray, context, hit);
    if (context.overflowed) [[unlikely]] {
        // Surfaces stacked deeper than the record: the first one is the hit.
        passed.count = 0;
        return intersect(ray, hit);
    }
    // Only those before the hit: the filter saw candidates that a closer hit found later
    // made moot.
    order_crossings(passed, found ? hit.t : ray.t_max);
    return found;
}

std::optional<bool> Accel::occluded_passing(const Ray& ray, PassedSurfaces& passed) const {
    QueryContext context;
    if (!start_recording(ray, passed, context)) return false;  // dropped: not blocked
    RTCRay r = embree_ray(ray.origin, ray.direction, ray.t_min, ray.t_max, ray.time);
    rtcOccluded1(m_world, &context.embree, &r);
    if (context.overflowed) [[unlikely]] {
        passed.count = 0;
        return std::nullopt;
    }
    const bool blocked = r.tfar < 0.0f;
    if (blocked)
        passed.count = 0;
    else
        order_crossings(passed, ray.t_max);
    return blocked;
}

// In order along the ray, each crossing once, and only those before `end`. A crossing comes
// twice as the same triangle offered again, or as the two triangles of an edge the ray goes
// through: one shape at the same distance.
void Accel::order_crossings(PassedSurfaces& passed, float end) {
    // Most queries pass nothing or one surface: no sort then (a call that cost 1.5 % of the
    // preview in fog).
    if (passed.count <= 1) {
        if (passed.count == 1 && !(passed.hits[0].t < end)) passed.count = 0;
        return;
    }
    // By insertion (a handful at most, mostly two: the fog box's two faces), which keeps
    // equal distances in the order they came, as std::sort does on so few.
    for (int i = 1; i < passed.count; ++i) {
        if (!(passed.hits[i].t < passed.hits[i - 1].t)) continue;
        const HitRecord moving = passed.hits[i];
        int j = i;
        for (; j > 0 && moving.t < passed.hits[j - 1].t; --j) passed.hits[j] = passed.hits[j - 1];
        passed.hits[j] = moving;
    }
    int kept = 0;
    for (int i = 0; i < passed.count; ++i) {
        const HitRecord& h = passed.hits[i];
        if (!(h.t < end)) break;
        const HitRecord* last = kept > 0 ? &passed.hits[kept - 1] : nullptr;
        const bool repeat =
            last && last->top_geometry == h.top_geometry &&
            (last->primitive == h.primitive || h.t - last->t <= 1e-6f * std::max(1.0f, h.t));
        if (!repeat) passed.hits[kept++] = h;
    }
    passed.count = kept;
}

bool Accel::occluded(const Ray& ray) const {
    return occluded(ray.origin, ray.direction, ray.t_min, ray.t_max);
}

namespace {

// Embree's 8-wide calls take an int per lane: -1 traces it, 0 leaves it out. Embree loads
// the mask with an aligned 256-bit load, so it must be 32-byte aligned: a plain
// std::array<int, 8> is only 4-byte aligned and worked by luck of the stack layout.
struct alignas(32) EmbreeValid {
    int lanes[kPacketWidth];
};

// Lanes are handled here by selects and bit masks rather than branches: whether a lane is
// active or hit something has no pattern a branch predictor could learn.
EmbreeValid embree_valid(uint32_t active) {
    EmbreeValid valid;
    for (int lane = 0; lane < kPacketWidth; ++lane)
        valid.lanes[lane] = -static_cast<int>((active >> lane) & 1u);
    return valid;
}

// Lane `lane` of an Embree packet: the segment [t_min, t_max] of origin + t direction, seen
// by every geometry, at scene time `time` (as embree_ray() for single rays).
void set_packet_ray(RTCRay8& packet, int lane, const Vec3& origin, const Vec3& direction,
                    float t_min, float t_max, float time) {
    packet.org_x[lane] = origin.x;
    packet.org_y[lane] = origin.y;
    packet.org_z[lane] = origin.z;
    packet.dir_x[lane] = direction.x;
    packet.dir_y[lane] = direction.y;
    packet.dir_z[lane] = direction.z;
    packet.tnear[lane] = t_min;
    packet.tfar[lane] = t_max;
    packet.time[lane] = time;
    packet.mask[lane] = 0xffffffffu;
    packet.id[lane] = 0;
    packet.flags[lane] = 0;
}

// Whether `lanes` (not empty) holds one lane. Not std::has_single_bit: without POPCNT in
// the baseline instruction set that is a library call.
bool is_single_lane(uint32_t lanes) {
    return (lanes & (lanes - 1)) == 0;
}

// The lanes of a filled packet that Embree takes (Accel::embree_accepts for each lane), in
// 4-wide vector compares over the packet's own arrays (GCC/Clang vector extensions: SSE on
// x86-64): checking the packet once costs a few instructions per ray, where checking each
// ray before it is copied in cost ~30.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

[[gnu::always_inline]] inline Float4 magnitudes(const float* lanes) {
    Float4 v;
    std::memcpy(&v, lanes, sizeof(v));
    return reinterpret_cast<Float4>(reinterpret_cast<Int4>(v) & 0x7fffffff);
}

// Bit i set where lane i of `mask` (each lane 0 or -1) is set.
[[gnu::always_inline]] inline uint32_t lane_bits(Int4 mask) {
#if defined(__SSE__)
    return static_cast<uint32_t>(__builtin_ia32_movmskps(reinterpret_cast<Float4>(mask)));
#else
    return (mask[0] & 1u) | (mask[1] & 2u) | (mask[2] & 4u) | (mask[3] & 8u);
#endif
}

uint32_t embree_accepted_lanes(const RTCRay8& packet) {
    constexpr float kLarge = 1.844e18f;  // Embree's FLT_LARGE, as in embree_accepts
    const Float4 large = {kLarge, kLarge, kLarge, kLarge};
    const Float4 infinite = {kInfinity, kInfinity, kInfinity, kInfinity};
    uint32_t lanes = 0;
    for (int first = 0; first < kPacketWidth; first += 4) {
        const Int4 ok = (magnitudes(packet.org_x + first) <= large) &
                        (magnitudes(packet.org_y + first) <= large) &
                        (magnitudes(packet.org_z + first) <= large) &
                        (magnitudes(packet.dir_x + first) <= large) &
                        (magnitudes(packet.dir_y + first) <= large) &
                        (magnitudes(packet.dir_z + first) <= large) &
                        (magnitudes(packet.tnear + first) <= infinite) &
                        (magnitudes(packet.tfar + first) <= infinite);
        lanes |= lane_bits(ok) << first;
    }
    return lanes;
}

// Leaves out of `active` the lanes of `packet` Embree would refuse, counting them with
// `drop`; false when no lane is left.
template <typename Drop>
bool keep_accepted_lanes(const RTCRay8& packet, uint32_t& active, Drop&& drop) {
    const uint32_t accepted = embree_accepted_lanes(packet) & active;
    if (accepted == active) [[likely]]
        return true;
    drop(static_cast<uint64_t>(std::popcount(active & ~accepted)));
    active = accepted;
    return active != 0;
}

void init_context(QueryContext& context, bool coherent) {
    rtcInitIntersectContext(&context.embree);
    context.embree.flags =
        coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
}

}  // namespace

uint32_t Accel::intersect_packet(const PerLane<const Ray*>& rays, uint32_t active,
                                 PerLane<HitRecord>& hits, bool coherent) const {
    // A lone ray costs less on its own than as a packet of one (intersect() checks it).
    if (is_single_lane(active)) {
        const int lane = std::countr_zero(active);
        return intersect(*rays[lane], hits[lane]) ? active : 0;
    }
    QueryContext context;
    return packet_closest_hits(rays, active, hits, context, coherent);
}

uint32_t Accel::intersect_packet_passing(const PerLane<const Ray*>& rays, uint32_t active,
                                         PerLane<HitRecord>& hits, PerLane<PassedSurfaces>& passed,
                                         bool coherent) const {
    if (is_single_lane(active)) {
        const int lane = std::countr_zero(active);
        return intersect_passing(*rays[lane], hits[lane], passed[lane]) ? active : 0;
    }
    for_each_lane(active, [&](int lane) { passed[lane].count = 0; });
    QueryContext context;
    context.lanes = passed.data();
    const uint32_t hit_lanes = packet_closest_hits(rays, active, hits, context, coherent);
    uint32_t result = 0;
    for_each_lane(active, [&](int lane) {
        const Ray& ray = *rays[lane];
        if ((context.overflowed_lanes >> lane) & 1u) [[unlikely]] {
            // As intersect_passing() does for it alone (which may overflow in turn).
            if (intersect_passing(ray, hits[lane], passed[lane])) result |= 1u << lane;
            return;
        }
        const bool hit = (hit_lanes >> lane) & 1u;
        order_crossings(passed[lane], hit ? hits[lane].t : ray.t_max);
        if (hit) result |= 1u << lane;
    });
    return result;
}

uint32_t Accel::packet_closest_hits(const PerLane<const Ray*>& rays, uint32_t active,
                                    PerLane<HitRecord>& hits, QueryContext& context,
                                    bool coherent) const {
    static_assert(kPacketWidth == 8, "the packet calls below are Embree's 8-wide ones");
    alignas(32) RTCRayHit8 packet;
    const int first = std::countr_zero(active);
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        // Inactive lanes get a valid ray too, so no lane holds uninitialised floats.
        const Ray& ray = *rays[(active >> lane) & 1u ? lane : first];
        set_packet_ray(packet.ray, lane, ray.origin, ray.direction, ray.t_min, ray.t_max, ray.time);
        packet.ray.id[lane] = static_cast<unsigned>(lane);  // for the recording filter
        packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
    // Lanes Embree would refuse are left out (misses) and counted.
    const auto drop = [this](uint64_t count) { drop_ray(count); };
    if (!keep_accepted_lanes(packet.ray, active, drop)) return 0;
    const EmbreeValid valid = embree_valid(active);
    init_context(context, coherent);
    rtcIntersect8(valid.lanes, m_world, &context.embree, &packet);

    uint32_t hit_lanes = 0;
    for (int lane = 0; lane < kPacketWidth; ++lane)
        hit_lanes |= static_cast<uint32_t>(packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID)
                     << lane;
    hit_lanes &= active;
    for_each_lane(hit_lanes, [&](int lane) {
        HitRecord& hit = hits[lane];
        hit.t = packet.ray.tfar[lane];
        hit.primitive = packet.hit.primID[lane];
        hit.barycentric = Vec2(packet.hit.u[lane], packet.hit.v[lane]);
        hit.normal = Vec3(packet.hit.Ng_x[lane], packet.hit.Ng_y[lane], packet.hit.Ng_z[lane]);
        const unsigned instance = packet.hit.instID[0][lane];
        const bool instanced = instance != RTC_INVALID_GEOMETRY_ID;
        hit.top_geometry = instanced ? instance : packet.hit.geomID[lane];
        hit.local_geometry = instanced ? packet.hit.geomID[lane] : RTC_INVALID_GEOMETRY_ID;
    });
    return hit_lanes;
}

uint32_t Accel::occluded_packet(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                                const PerLane<float>& times, float t_max, uint32_t active,
                                bool coherent) const {
    if (is_single_lane(active)) {
        const int lane = std::countr_zero(active);
        return occluded(origins[lane], directions[lane], 0.0f, t_max, times[lane]) ? active : 0;
    }
    QueryContext context;
    return packet_blocked(origins, directions, times, t_max, active, context, coherent);
}

uint32_t Accel::occluded_packet_passing(const PerLane<Vec3>& origins,
                                        const PerLane<Vec3>& directions,
                                        const PerLane<float>& times, float t_max, uint32_t active,
                                        PerLane<PassedSurfaces>& passed, uint32_t& overflowed,
                                        bool coherent) const {
    overflowed = 0;
    if (is_single_lane(active)) {
        const int lane = std::countr_zero(active);
        const Ray ray{origins[lane], directions[lane], 0.0f, t_max, times[lane]};
        const std::optional<bool> blocked = occluded_passing(ray, passed[lane]);
        if (!blocked) overflowed = active;
        return blocked.value_or(false) ? active : 0;
    }
    for_each_lane(active, [&](int lane) { passed[lane].count = 0; });
    QueryContext context;
    context.lanes = passed.data();
    const uint32_t blocked =
        packet_blocked(origins, directions, times, t_max, active, context, coherent);
    // A lane Embree refused left `active`: not blocked and nothing crossed, as
    // occluded_passing() answers it.
    overflowed = context.overflowed_lanes & active;
    for_each_lane(active & ~overflowed, [&](int lane) {
        if ((blocked >> lane) & 1u)
            passed[lane].count = 0;
        else
            order_crossings(passed[lane], t_max);
    });
    return blocked & ~overflowed;
}

uint32_t Accel::packet_blocked(const PerLane<Vec3>& origins, const PerLane<Vec3>& directions,
                               const PerLane<float>& times, float t_max, uint32_t& active,
                               QueryContext& context, bool coherent) const {
    alignas(32) RTCRay8 packet;
    const int first = std::countr_zero(active);
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        const int source = (active >> lane) & 1u ? lane : first;
        set_packet_ray(packet, lane, origins[source], directions[source], 0.0f, t_max,
                       times[source]);
        packet.id[lane] = static_cast<unsigned>(lane);  // for the recording filter
    }
    // Lanes Embree would refuse are left out (not blocked) and counted.
    const auto drop = [this](uint64_t count) { drop_ray(count); };
    if (!keep_accepted_lanes(packet, active, drop)) return 0;
    const EmbreeValid valid = embree_valid(active);
    init_context(context, coherent);
    rtcOccluded8(valid.lanes, m_world, &context.embree, &packet);

    // Embree sets tfar to -inf where something blocks the segment.
    uint32_t blocked = 0;
    for (int lane = 0; lane < kPacketWidth; ++lane)
        blocked |= static_cast<uint32_t>(packet.tfar[lane] < 0.0f) << lane;
    return blocked & active;
}

const char* Accel::embree_version() {
    return RTC_VERSION_STRING;
}

}  // namespace glint
