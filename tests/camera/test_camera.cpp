// Camera importance for light paths: sample_wi agrees with generate_ray (the film point it
// returns, with the same lens point, gives a ray through the reference point), the thin
// lens's lens points against their density (chi-square on the lens disc), We's value and
// normalisation, and pdf_we's.
#include <glint/camera/camera.h>
#include <glint/core/rng.h>
#include <glint/math/frame.h>
#include <glint/math/warp.h>

#include <gtest/gtest.h>
#include <support/chi_square_plane.h>

#include <cmath>

using namespace glint;

namespace {

const Vec3 kEye(1.0f, 2.0f, 3.0f);
const Vec3 kLookAt(0.0f, 1.5f, -2.0f);
const Vec3 kUp(0.0f, 1.0f, 0.0f);
constexpr float kFov = 50.0f;
const Vec2i kResolution(64, 48);
constexpr float kAperture = 0.25f;
constexpr float kFocus = 4.0f;

PerspectiveCamera pinhole() {
    return PerspectiveCamera(kEye, kLookAt, kUp, kFov, kResolution, 0.0f, kFocus);
}
PerspectiveCamera thin_lens() {
    return PerspectiveCamera(kEye, kLookAt, kUp, kFov, kResolution, kAperture, kFocus);
}

// The camera's axes, computed here: forward, right, up.
struct Axes {
    Vec3 forward = glm::normalize(kLookAt - kEye);
    Vec3 right = glm::normalize(glm::cross(forward, kUp));
    Vec3 up = glm::cross(right, forward);
};

// Area of the frame at distance 1 from the lens.
double image_area() {
    const double t = std::tan(0.5 * kFov * M_PI / 180.0);
    return 4.0 * t * t * kResolution.x / kResolution.y;
}

// A point seen through film position `film` (pixels) at distance `depth` along forward,
// from the pinhole at the eye.
Vec3 point_through(const Vec2& film, float depth) {
    const Axes a;
    const float t = std::tan(0.5f * glm::radians(kFov));
    const float sx = 2.0f * film.x / kResolution.x - 1.0f,
                sy = 1.0f - 2.0f * film.y / kResolution.y;
    return kEye + depth * (a.forward +
                           sx * t * (static_cast<float>(kResolution.x) / kResolution.y) * a.right +
                           sy * t * a.up);
}

// sample_wi's film point fed back to generate_ray with the same lens point gives a ray
// from p_lens through `ref`, and the sample's own fields agree with that ray.
void expect_round_trip(const PerspectiveCamera& camera, const Vec3& ref, const Vec2& u_lens) {
    const std::optional<CameraWiSample> s = camera.sample_wi(ref, u_lens);
    ASSERT_TRUE(s) << "ref " << ref.x << "," << ref.y << "," << ref.z;
    const Ray ray = camera.generate_ray(s->film, u_lens);
    EXPECT_LT(glm::length(ray.origin - s->p_lens), 1e-5f);
    const Vec3 towards_ref = glm::normalize(ref - ray.origin);
    EXPECT_GT(glm::dot(ray.direction, towards_ref), 1.0f - 1e-6f);
    EXPECT_GT(glm::dot(s->wi, -towards_ref), 1.0f - 1e-6f);
    Vec2 film(-1.0f);
    EXPECT_NEAR(to_rgb(camera.we(ray, &film))[0], to_rgb(s->We)[0], 1e-4f * to_rgb(s->We)[0]);
    EXPECT_NEAR(film.x, s->film.x, 1e-3f);
    EXPECT_NEAR(film.y, s->film.y, 1e-3f);
}

}  // namespace

TEST(CameraImportance, PinholeSampleWiRoundTripsThroughGenerateRay) {
    const PerspectiveCamera camera = pinhole();
    Rng rng(1);
    for (int i = 0; i < 200; ++i) {
        const Vec2 film(rng.next_float() * kResolution.x, rng.next_float() * kResolution.y);
        const Vec3 ref = point_through(film, 0.5f + 10.0f * rng.next_float());
        expect_round_trip(camera, ref, Vec2(rng.next_float(), rng.next_float()));
        const std::optional<CameraWiSample> s = camera.sample_wi(ref, Vec2(0.5f));
        ASSERT_TRUE(s);
        EXPECT_NEAR(s->film.x, film.x, 2e-3f);
        EXPECT_NEAR(s->film.y, film.y, 2e-3f);
        EXPECT_EQ(s->p_lens, kEye);
        const float dist2 = glm::dot(ref - kEye, ref - kEye);
        const float cos_lens = glm::dot(Axes().forward, -s->wi);
        EXPECT_NEAR(s->pdf, dist2 / cos_lens, 1e-4f * s->pdf);
    }
    // Behind the camera and outside the frame: nothing.
    EXPECT_FALSE(camera.sample_wi(kEye - Axes().forward, Vec2(0.5f)));
    EXPECT_FALSE(camera.sample_wi(point_through(Vec2(-3.0f, 10.0f), 2.0f), Vec2(0.5f)));
    EXPECT_FALSE(
        camera.sample_wi(point_through(Vec2(10.0f, kResolution.y + 2.0f), 2.0f), Vec2(0.5f)));
}

TEST(CameraImportance, ThinLensSampleWiRoundTripsOnAndOffTheFocusPlane) {
    const PerspectiveCamera camera = thin_lens();
    Rng rng(2);
    for (const float depth : {kFocus, 1.5f, 9.0f}) {
        for (int i = 0; i < 100; ++i) {
            // Inside the middle of the frame, so every lens point sees it.
            const Vec2 film((0.25f + 0.5f * rng.next_float()) * kResolution.x,
                            (0.25f + 0.5f * rng.next_float()) * kResolution.y);
            expect_round_trip(camera, point_through(film, depth),
                              Vec2(rng.next_float(), rng.next_float()));
        }
    }
}

// Lens points as sample_wi draws them, on the lens disc: uniform (chi-square), and each
// sample's solid-angle pdf is the area density 1 / A_lens converted: dist^2 / (cos A_lens).
TEST(CameraImportance, ThinLensPointsAreUniformOnTheDiscWithTheirPdf) {
    const PerspectiveCamera camera = thin_lens();
    const Axes a;
    const Vec3 ref = point_through(Vec2(40.0f, 20.0f), 2.5f);
    const double lens_area = M_PI * kAperture * kAperture;
    int wrong_pdf = 0;
    const auto result = test::chi_square_points(
        [&](const Vec2& u, float) -> std::optional<Vec2> {
            const std::optional<CameraWiSample> s = camera.sample_wi(ref, u);
            if (!s) return std::nullopt;
            const Vec3 d = s->p_lens - ref;
            const double expected =
                glm::dot(d, d) / (std::abs(glm::dot(a.forward, s->wi)) * lens_area);
            if (std::abs(s->pdf - expected) > 1e-4 * expected) ++wrong_pdf;
            const Vec3 q = s->p_lens - kEye;
            if (std::abs(glm::dot(q, a.forward)) > 1e-5f) ++wrong_pdf;
            return Vec2(glm::dot(q, a.right), glm::dot(q, a.up));
        },
        [&](const Vec2& p) {
            return glm::dot(p, p) <= kAperture * kAperture ? 1.0 / lens_area : 0.0;
        },
        Vec2(-1.1f * kAperture), Vec2(1.1f * kAperture), 100000, 9, 0.001);
    EXPECT_TRUE(result.passed) << result.details;
    EXPECT_NEAR(result.integrated_pdf, 1.0, 3e-3) << result.details;
    EXPECT_EQ(wrong_pdf, 0);
}

TEST(CameraImportance, WeIsZeroOutsideTheFrameAndMatchesTheFormula) {
    for (const PerspectiveCamera& camera : {pinhole(), thin_lens()}) {
        const bool lens = camera.needs_lens_sample();
        const double lens_area = lens ? M_PI * kAperture * kAperture : 1.0;
        const Axes a;
        Rng rng(4);
        for (int i = 0; i < 200; ++i) {
            const Vec2 film(rng.next_float() * kResolution.x, rng.next_float() * kResolution.y);
            const Ray ray = camera.generate_ray(film, Vec2(rng.next_float(), rng.next_float()));
            Vec2 back(-1.0f);
            const float we = to_rgb(camera.we(ray, &back))[0];
            const double c = glm::dot(ray.direction, a.forward);
            const double expected = 1.0 / (lens_area * image_area() * c * c * c * c);
            EXPECT_NEAR(we, expected, 1e-4 * expected);
            EXPECT_NEAR(back.x, film.x, 2e-3f);
            EXPECT_NEAR(back.y, film.y, 2e-3f);
            const CameraPdf pdf = camera.pdf_we(ray);
            EXPECT_NEAR(pdf.pos, 1.0 / lens_area, 1e-5 / lens_area);
            EXPECT_NEAR(pdf.dir, 1.0 / (image_area() * c * c * c), 1e-4 * pdf.dir);
        }
        // Just outside each edge of the frame, and backwards.
        const Vec2 outside[] = {{-0.01f, 20.0f},
                                {kResolution.x + 0.01f, 20.0f},
                                {30.0f, -0.01f},
                                {30.0f, kResolution.y + 0.01f}};
        for (const Vec2& film : outside) {
            // A pinhole ray through the film point, beyond the frame, from the lens centre.
            const Ray ray{kEye, glm::normalize(point_through(film, 1.0f) - kEye)};
            EXPECT_EQ(to_rgb(camera.we(ray))[0], 0.0f) << film.x << "," << film.y;
            EXPECT_EQ(camera.pdf_we(ray).dir, 0.0f);
        }
        EXPECT_EQ(to_rgb(camera.we(Ray{kEye, -a.forward}))[0], 0.0f);
    }
}

// The normalisation: for any lens point, the integral of We cos theta over the directions
// through the frame is 1 / A_lens (so over the lens too it is 1), and pdf_we's direction
// density integrates to 1. Monte Carlo over the hemisphere about forward, with a bound of
// four standard errors.
TEST(CameraImportance, WeAndPdfWeIntegrateToTheirNormalisation) {
    for (const PerspectiveCamera& camera : {pinhole(), thin_lens()}) {
        const bool lens = camera.needs_lens_sample();
        const double lens_area = lens ? M_PI * kAperture * kAperture : 1.0;
        const Axes a;
        const Frame frame(a.right, a.up, a.forward);
        for (const Vec2& u_lens : {Vec2(0.5f), Vec2(0.9f, 0.3f)}) {
            const Vec3 origin =
                kEye + (lens ? kAperture : 0.0f) *
                           (warp::square_to_uniform_disk_concentric(u_lens).x * a.right +
                            warp::square_to_uniform_disk_concentric(u_lens).y * a.up);
            Rng rng(5);
            constexpr int kN = 400000;
            double we_sum = 0.0, we_sum2 = 0.0, pdf_sum = 0.0, pdf_sum2 = 0.0;
            for (int i = 0; i < kN; ++i) {
                const Vec3 local =
                    warp::square_to_uniform_hemisphere(Vec2(rng.next_float(), rng.next_float()));
                const Ray ray{origin, frame.to_world(local)};
                const double inv_pdf = 2.0 * M_PI;
                const double we = to_rgb(camera.we(ray))[0] * local.z * inv_pdf;
                const double pdf = camera.pdf_we(ray).dir * inv_pdf;
                we_sum += we;
                we_sum2 += we * we;
                pdf_sum += pdf;
                pdf_sum2 += pdf * pdf;
            }
            auto check = [&](double sum, double sum2, double expected, const char* what) {
                const double mean = sum / kN;
                const double error = std::sqrt(std::max(0.0, sum2 / kN - mean * mean) / kN);
                EXPECT_NEAR(mean, expected, 4.0 * error + 1e-6 * expected)
                    << what << (lens ? " thin lens" : " pinhole");
            };
            check(we_sum, we_sum2, 1.0 / lens_area, "We cos");
            check(pdf_sum, pdf_sum2, 1.0, "pdf_we.dir");
        }
    }
}
