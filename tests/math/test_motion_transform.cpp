// MotionTransform: its parts rebuild each key, interpolation passes through the keys and
// turns rotations about their axis at a constant rate (slerp), as Embree's quaternion
// motion does.
#include <glint/core/error.h>
#include <glint/math/motion_transform.h>

#include <gtest/gtest.h>

using namespace glint;

namespace {

void expect_same_matrix(const Transform& a, const Transform& b, float tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a.matrix()[c][r], b.matrix()[c][r], tolerance) << "entry " << c << "," << r;
}

}  // namespace

TEST(MotionTransform, PartsRebuildTheTransform) {
    const Transform sheared(Mat4(Vec4(1.0f, 0.2f, 0.0f, 0.0f), Vec4(0.3f, 2.0f, 0.1f, 0.0f),
                                 Vec4(0.0f, 0.4f, 0.5f, 0.0f), Vec4(1.0f, -2.0f, 3.0f, 1.0f)));
    const Transform mirrored = Transform::scale(Vec3(1.0f, -2.0f, 1.0f)) *
                               Transform::rotate(30.0f, Vec3(1.0f, 1.0f, 0.0f));
    for (const Transform& xf :
         {sheared, mirrored,
          Transform::translate(Vec3(1, 2, 3)) * Transform::rotate(120.0f, Vec3(0, 0, 1)) *
              Transform::scale(Vec3(2, 3, 4))}) {
        expect_same_matrix(compose(decompose(xf)), xf, 1e-5f);
    }
}

TEST(MotionTransform, PassesThroughItsKeysAndClampsTime) {
    const Transform a = Transform::translate(Vec3(-1, 0, 0));
    const Transform b = Transform::rotate(60.0f, Vec3(0, 1, 0)) * Transform::scale(Vec3(2.0f));
    const Transform c = Transform::translate(Vec3(0, 5, 0));
    const MotionTransform motion({a, b, c});
    expect_same_matrix(motion.at(0.0f), a, 0.0f);
    expect_same_matrix(motion.at(0.5f), b, 0.0f);
    expect_same_matrix(motion.at(1.0f), c, 0.0f);
    expect_same_matrix(motion.at(-3.0f), a, 0.0f);
    expect_same_matrix(motion.at(7.0f), c, 0.0f);
}

TEST(MotionTransform, RotatesAtAConstantRateAboutTheAxis) {
    // 0 to 150 degrees about z, scale 1 to 3, translation 0 to (4, 0, 0).
    const MotionTransform motion({Transform(), Transform::translate(Vec3(4, 0, 0)) *
                                                   Transform::rotate(150.0f, Vec3(0, 0, 1)) *
                                                   Transform::scale(Vec3(3.0f))});
    for (float t : {0.1f, 0.25f, 0.5f, 0.8f}) {
        const Transform expected = Transform::translate(Vec3(4.0f * t, 0, 0)) *
                                   Transform::rotate(150.0f * t, Vec3(0, 0, 1)) *
                                   Transform::scale(Vec3(1.0f + 2.0f * t));
        expect_same_matrix(motion.at(t), expected, 2e-5f);
    }
}

TEST(MotionTransform, TurnsTheShortWayRound) {
    // 0 to 270 degrees is the same key as -90: interpolation goes through -45, not 135.
    const MotionTransform motion({Transform(), Transform::rotate(270.0f, Vec3(0, 0, 1))});
    expect_same_matrix(motion.at(0.5f), Transform::rotate(-45.0f, Vec3(0, 0, 1)), 1e-5f);
}

TEST(MotionTransform, KeywiseProductNeedsMatchingKeyCounts) {
    const MotionTransform still(Transform::translate(Vec3(0, 1, 0)));
    const MotionTransform two({Transform(), Transform::translate(Vec3(1, 0, 0))});
    const MotionTransform three(
        {Transform(), Transform::translate(Vec3(1, 0, 0)), Transform::translate(Vec3(2, 0, 0))});
    const MotionTransform product = still * two;
    ASSERT_EQ(product.key_count(), 2u);
    expect_same_matrix(product.key(1), Transform::translate(Vec3(1, 1, 0)), 0.0f);
    EXPECT_FALSE((still * still).is_moving());
    EXPECT_THROW(two * three, Error);
}
