#include <glint/core/error.h>
#include <glint/geometry/accel.h>

#include <fmt/format.h>

namespace glint {

Accel::Accel() {
    m_device = rtcNewDevice(nullptr);
    if (!m_device) throw Error("could not create the Embree device");
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

void Accel::commit() {
    for (RTCScene scene : m_prototypes) rtcCommitScene(scene);
    rtcCommitScene(m_world);
    check_device("building the acceleration structure");
}

bool Accel::occluded(const Ray& ray) const {
    return occluded(ray.origin, ray.direction, ray.t_min, ray.t_max);
}

const char* Accel::embree_version() {
    return RTC_VERSION_STRING;
}

}  // namespace glint
