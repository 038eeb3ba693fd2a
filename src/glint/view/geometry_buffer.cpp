#include <glint/camera/camera.h>
#include <glint/core/interaction.h>
#include <glint/material/material.h>
#include <glint/scene/scene.h>
#include <glint/view/geometry_buffer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint {

GeometryBuffer trace_geometry_buffer(const Scene& scene, const Camera& camera, int width,
                                     int height) {
    GeometryBuffer buffer;
    buffer.width = width;
    buffer.height = height;
    const std::size_t count = buffer.size();
    buffer.depth.assign(count, 0.0f);
    buffer.normal.assign(count, Vec3(0.0f));
    buffer.albedo.assign(count, Rgb(1.0f));
    buffer.object_id.assign(count, GeometryBuffer::kMiss);
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        SurfaceInteraction si;
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                const Ray ray = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
                HitRecord hit{};
                if (!scene.intersect(ray, si, hit)) continue;
                buffer.depth[i] = si.t;
                const Vec3 n = si.shading.n();
                buffer.normal[i] = glm::dot(n, ray.direction) > 0.0f ? -n : n;
                if (si.material) buffer.albedo[i] = to_rgb(si.material->albedo(si));
                // Geometry ids are small: the instance's goes to the high half.
                const uint32_t local = hit.instanced() ? hit.local_geometry + 1 : 0;
                buffer.object_id[i] = hit.top_geometry ^ (local << 16);
            }
        }
    });
    return buffer;
}

}  // namespace glint
