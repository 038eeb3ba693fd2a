#pragma once
// What every analytic shape (sphere, CSG solid) needs to live in Embree as user geometry:
// one primitive whose bounds, intersection and occlusion are callbacks on the shape, and
// the reading of Embree's ray packets (RTCRayN) inside those callbacks.
#include <glint/core/ray.h>
#include <glint/math/bounds.h>

#include <embree3/rtcore.h>

#include <bit>
#include <cstdint>

namespace glint {

// Origin and direction of ray i of an n-wide Embree packet.
inline Vec3 packet_origin(RTCRayN* rays, unsigned n, unsigned i) {
    return Vec3(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
}
inline Vec3 packet_direction(RTCRayN* rays, unsigned n, unsigned i) {
    return Vec3(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
}

// Ray i of an n-wide Embree packet, with its current [tnear, tfar].
inline Ray ray_from_packet(RTCRayN* rays, unsigned n, unsigned i) {
    Ray ray;
    ray.origin = packet_origin(rays, n, i);
    ray.direction = packet_direction(rays, n, i);
    ray.t_min = RTCRayN_tnear(rays, n, i);
    ray.t_max = RTCRayN_tfar(rays, n, i);
    return ray;
}

// Calls f(i) for each ray i that Embree's `valid` marks active (-1) among the n of a packet.
// The mask is built without branches and then walked bit by bit: which lanes of a packet
// reach a shape has no pattern a branch predictor could learn.
template <typename Function>
void for_each_valid_ray(const int* valid, unsigned n, Function&& f) {
    uint32_t lanes = 0;
    for (unsigned i = 0; i < n; ++i) lanes |= static_cast<uint32_t>(valid[i] == -1) << i;
    for (; lanes != 0; lanes &= lanes - 1) f(static_cast<unsigned>(std::countr_zero(lanes)));
}

inline RTCBounds to_embree_bounds(const Bounds3& b) {
    return RTCBounds{b.min.x, b.min.y, b.min.z, 0.0f, b.max.x, b.max.y, b.max.z, 0.0f};
}

// A committed user geometry of one primitive, whose callbacks get `shape` as user data.
template <typename ShapeType>
RTCGeometry make_user_geometry(RTCDevice device, const ShapeType& shape, RTCBoundsFunction bounds,
                               RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, 1);
    rtcSetGeometryUserData(geometry, const_cast<ShapeType*>(&shape));
    rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, intersect);
    rtcSetGeometryOccludedFunction(geometry, occluded);
    rtcCommitGeometry(geometry);
    return geometry;
}

}  // namespace glint
