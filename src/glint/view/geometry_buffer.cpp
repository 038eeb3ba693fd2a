#include <glint/camera/camera.h>
#include <glint/core/interaction.h>
#include <glint/geometry/accel.h>
#include <glint/material/material.h>
#include <glint/scene/scene.h>
#include <glint/view/geometry_buffer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint {

namespace {

// The pixels of a packet: a block kBlockWidth x kBlockHeight, neighbours whose rays Embree
// traverses together (coherent), as the preview's camera pass does.
constexpr int kBlockWidth = 4;
constexpr int kBlockHeight = kPacketWidth / kBlockWidth;

void record_hit(GeometryBuffer& buffer, std::size_t i, const Ray& ray, const SurfaceInteraction& si,
                const HitRecord& hit) {
    buffer.depth[i] = si.t;
    const Vec3 n = si.shading.n();
    buffer.normal[i] = glm::dot(n, ray.direction) > 0.0f ? -n : n;
    if (si.material) {
        buffer.albedo[i] = to_rgb(si.material->albedo(si));
        buffer.emitter[i] = si.material->is_emissive() ? 1 : 0;
    }
    // Geometry ids are small: the instance's goes to the high half.
    const uint32_t local = hit.instanced() ? hit.local_geometry + 1 : 0;
    buffer.object_id[i] = hit.top_geometry ^ (local << 16);
}

// What a packet of one block traces with: the lanes' rays, interactions and hit records.
struct BlockLanes {
    PerLane<Ray> rays;
    PerLane<SurfaceInteraction> si;
    PerLane<HitRecord> hits;
    PerLane<const Ray*> ray_of;
    PerLane<SurfaceInteraction*> si_of;
    PerLane<std::size_t> index;  // each lane's pixel
    BlockLanes() {
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            ray_of[lane] = &rays[lane];
            si_of[lane] = &si[lane];
        }
    }
};

// The block whose top-left pixel is `corner`, as one packet of pixel-centre rays. Pixels
// beyond the film's edge are inactive lanes; a lane that misses keeps the miss values.
void trace_block(const Scene& scene, const Camera& camera, Vec2i corner, GeometryBuffer& buffer,
                 BlockLanes& lanes) {
    uint32_t active = 0;
    for (int lane = 0; lane < kPacketWidth; ++lane) {
        const int x = corner.x + lane % kBlockWidth, y = corner.y + lane / kBlockWidth;
        if (x >= buffer.width || y >= buffer.height) continue;
        const std::size_t i = static_cast<std::size_t>(y) * buffer.width + x;
        lanes.index[lane] = i;
        lanes.rays[lane] = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
        buffer.depth[i] = 0.0f;
        buffer.normal[i] = Vec3(0.0f);
        buffer.albedo[i] = Rgb(1.0f);
        buffer.object_id[i] = GeometryBuffer::kMiss;
        buffer.emitter[i] = 0;
        active |= 1u << lane;
    }
    const uint32_t hit =
        scene.intersect_packet(lanes.ray_of, active, lanes.si_of, true, &lanes.hits);
    for_each_lane(hit, [&](int lane) {
        record_hit(buffer, lanes.index[lane], lanes.rays[lane], lanes.si[lane], lanes.hits[lane]);
    });
}

}  // namespace

GeometryBuffer trace_geometry_buffer(const Scene& scene, const Camera& camera, int width,
                                     int height) {
    GeometryBuffer buffer;
    buffer.width = width;
    buffer.height = height;
    const std::size_t count = buffer.size();
    buffer.depth.resize(count);
    buffer.normal.resize(count);
    buffer.albedo.resize(count);
    buffer.object_id.resize(count);
    buffer.emitter.resize(count);
    const int block_rows = (height + kBlockHeight - 1) / kBlockHeight;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, block_rows), [&](const tbb::blocked_range<int>& rows) {
            BlockLanes lanes;
            for (int row = rows.begin(); row < rows.end(); ++row)
                for (int x = 0; x < width; x += kBlockWidth)
                    trace_block(scene, camera, Vec2i(x, row * kBlockHeight), buffer, lanes);
        });
    return buffer;
}

}  // namespace glint
