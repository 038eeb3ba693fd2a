// Reprojection over synthetic geometry buffers: a translated camera reuses the history of every
// pixel that stays visible and rejects exactly the disoccluded ones; a rotated camera (no
// parallax) reuses every pixel still in the previous frame and fetches its value.
#include <glint/camera/camera.h>
#include <glint/view/reprojection.h>

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

constexpr int kWidth = 64, kHeight = 48;
// tan(fov / 2) = 1/2: a pixel is depth / 48 wide on a plane facing the camera.
const float kFov = glm::degrees(2.0f * std::atan(0.5f));
constexpr float kWallZ = -12.0f;   // pixels 1/4 wide
constexpr float kSquareZ = -6.0f;  // pixels 1/8 wide
constexpr float kSquareHalf = 1.0f;

PerspectiveCamera camera_at(const Vec3& eye, const Vec3& forward) {
    return PerspectiveCamera(eye, eye + forward, Vec3(0, 1, 0), kFov, Vec2i(kWidth, kHeight), 0.0f,
                             1.0f);
}

enum Surface : uint32_t { kWall = 0, kSquare = 1 };

// A wall facing the camera and, with `with_square`, a square in front of it, seen from
// `camera`: depth along each pixel-centre ray, the normal, and which surface.
GeometryBuffer synthetic_buffer(const Camera& camera, bool with_square, bool with_ids) {
    GeometryBuffer g;
    g.width = kWidth;
    g.height = kHeight;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const Ray ray = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            float t = (kSquareZ - ray.origin.z) / ray.direction.z;
            const Vec3 p = ray.origin + t * ray.direction;
            Surface surface = kSquare;
            if (!with_square || std::abs(p.x) > kSquareHalf || std::abs(p.y) > kSquareHalf) {
                t = (kWallZ - ray.origin.z) / ray.direction.z;
                surface = kWall;
            }
            g.depth.push_back(t);
            g.normal.push_back(Vec3(0, 0, 1));
            g.albedo.push_back(Rgb(1.0f));
            g.object_id.push_back(with_ids ? surface : 0u);
        }
    }
    return g;
}

Surface surface_at(const GeometryBuffer& g, int x, int y) {
    // Depths tell the surfaces apart even without ids: the square is twice as near.
    return g.depth[y * kWidth + x] < 0.75f * -kWallZ ? kSquare : kWall;
}

void check_translation(bool with_ids) {
    // The camera moves 1/2 to the right: the wall's points appear 2 pixels further right in
    // the previous frame, the square's 4 (both exactly on pixel centres); the square's edges
    // lie on pixel boundaries in both frames.
    const PerspectiveCamera previous_camera = camera_at(Vec3(0), Vec3(0, 0, -1));
    const PerspectiveCamera current_camera = camera_at(Vec3(0.5f, 0, 0), Vec3(0, 0, -1));
    const GeometryBuffer previous = synthetic_buffer(previous_camera, true, with_ids);
    const GeometryBuffer current = synthetic_buffer(current_camera, true, with_ids);
    const std::vector<HistoryTaps> taps =
        reproject(current, current_camera, previous, previous_camera);

    std::vector<float> history(previous.size());
    for (std::size_t i = 0; i < history.size(); ++i) history[i] = static_cast<float>(i);
    const std::vector<float> fetched = fetch_history<float>(taps, history, -1.0f);

    int reused = 0, rejected = 0, disoccluded = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const Surface surface = surface_at(current, x, y);
            const int px = x + (surface == kSquare ? 4 : 2);
            const bool visible_before = px < kWidth && surface_at(previous, px, y) == surface;
            const std::size_t i = y * kWidth + x;
            EXPECT_EQ(taps[i].valid(), visible_before) << "pixel " << x << ", " << y;
            if (visible_before) {
                ++reused;
                EXPECT_EQ(taps[i].index[1], HistoryTaps::kNone) << "one tap on a pixel centre";
                EXPECT_FLOAT_EQ(fetched[i], static_cast<float>(y * kWidth + px));
            } else {
                ++rejected;
                EXPECT_EQ(fetched[i], -1.0f);
                disoccluded += px < kWidth;
            }
        }
    }
    // 16 rows of the wall beside the square's left edge were hidden by it before (the square
    // moves 4 pixels, the wall 2), and two columns entered at the right edge.
    EXPECT_EQ(disoccluded, 16 * 2);
    EXPECT_EQ(rejected - disoccluded, 2 * kHeight);
    EXPECT_EQ(reused + rejected, kWidth * kHeight);
}

TEST(Reprojection, TranslationReusesVisiblePixelsAndRejectsDisoccludedOnes) {
    check_translation(true);
}

TEST(Reprojection, DepthAloneRejectsDisocclusionsWithoutObjectIds) {
    check_translation(false);
}

TEST(Reprojection, ObjectIdsRejectAnotherObjectAtTheSameDepth) {
    const PerspectiveCamera camera = camera_at(Vec3(0), Vec3(0, 0, -1));
    const GeometryBuffer previous = synthetic_buffer(camera, false, true);
    GeometryBuffer current = previous;
    for (uint32_t& id : current.object_id) id = 7;  // another object in the same place
    const std::vector<HistoryTaps> taps = reproject(current, camera, previous, camera);
    for (const HistoryTaps& t : taps) EXPECT_FALSE(t.valid());
    current.object_id = previous.object_id;
    for (Vec3& n : current.normal) n = Vec3(1, 0, 0);  // same place, turned away
    for (const HistoryTaps& t : reproject(current, camera, previous, camera))
        EXPECT_FALSE(t.valid());
}

TEST(Reprojection, RotationReusesEveryPixelStillInTheFrame) {
    // Turning about the eye moves nothing relative to anything else: a pixel keeps its
    // history exactly when its point was inside the previous frame.
    const PerspectiveCamera previous_camera = camera_at(Vec3(0), Vec3(0, 0, -1));
    const float angle = glm::radians(5.0f);
    const PerspectiveCamera current_camera =
        camera_at(Vec3(0), Vec3(std::sin(angle), 0.2f, -std::cos(angle)));
    const GeometryBuffer previous = synthetic_buffer(previous_camera, false, true);
    const GeometryBuffer current = synthetic_buffer(current_camera, false, true);
    const std::vector<HistoryTaps> taps =
        reproject(current, current_camera, previous, previous_camera);

    // The previous frame showed a smooth function of the wall point: its x.
    std::vector<float> wall_x(previous.size());
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const Ray ray = previous_camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            wall_x[y * kWidth + x] =
                (ray.origin + previous.depth[y * kWidth + x] * ray.direction).x;
        }
    }
    const std::vector<float> fetched = fetch_history<float>(taps, wall_x, NAN);
    const float tan_half = 0.5f, aspect = static_cast<float>(kWidth) / kHeight;
    int reused = 0, checked = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = y * kWidth + x;
            const Ray ray = current_camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            const Vec3 p = ray.origin + current.depth[i] * ray.direction;
            // The previous film position, worked out by hand.
            const float fx = 0.5f * (p.x / -p.z / (tan_half * aspect) + 1.0f) * kWidth;
            const float fy = 0.5f * (1.0f - p.y / -p.z / tan_half) * kHeight;
            const float margin = std::min({fx, kWidth - fx, fy, kHeight - fy});
            if (std::abs(margin) < 1e-3f) continue;  // on the frame's edge: either is right
            ++checked;
            EXPECT_EQ(taps[i].valid(), margin > 0.0f) << "pixel " << x << ", " << y;
            if (taps[i].valid()) {
                ++reused;
                // Wall x is linear across the previous film: bilinear taps give it back
                // (within half a pixel of the edge the outer taps are missing: clamped).
                if (margin >= 0.5f) {
                    EXPECT_NEAR(fetched[i], p.x, 1e-3f);
                }
            }
        }
    }
    EXPECT_GT(checked, kWidth * kHeight - 10);
    EXPECT_GT(reused, kWidth * kHeight / 2);
    EXPECT_LT(reused, checked);  // the turn brought new pixels in
}

TEST(Reprojection, EscapedRaysReprojectByDirection) {
    // Nothing hit anywhere: a translation keeps every pixel (the sky is infinitely far),
    // and a hit never takes a miss's history.
    const PerspectiveCamera previous_camera = camera_at(Vec3(0), Vec3(0, 0, -1));
    const PerspectiveCamera current_camera = camera_at(Vec3(3, 1, 0), Vec3(0, 0, -1));
    GeometryBuffer sky = synthetic_buffer(previous_camera, false, true);
    std::fill(sky.depth.begin(), sky.depth.end(), 0.0f);
    std::fill(sky.object_id.begin(), sky.object_id.end(), GeometryBuffer::kMiss);
    for (const HistoryTaps& t : reproject(sky, current_camera, sky, previous_camera))
        EXPECT_TRUE(t.valid());
    const GeometryBuffer wall = synthetic_buffer(current_camera, false, true);
    for (const HistoryTaps& t : reproject(wall, current_camera, sky, previous_camera))
        EXPECT_FALSE(t.valid());
}

}  // namespace
}  // namespace glint
