#include <glint/spectral/sigmoid_fit.h>

#include <glint/spectral/spectrum_to_rgb.h>

#include <algorithm>
#include <cmath>

namespace glint::spectral {
namespace {

constexpr double kFirstNm = 360.0;
constexpr double kRangeNm = 470.0;
constexpr int kMaxIterations = 200;

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

struct Evaluation {
    Vec3 residual{};  // colour − target
    Mat3 jacobian{};  // ∂colour_i / ∂c_j
};

Evaluation evaluate(const NormalisedCoefficients& c, const Vec3& target) {
    const ReflectanceWeights& w = reflectance_weights();
    Evaluation e;
    for (size_t i = 0; i < w.per_sample.size(); ++i) {
        const double t = (ReflectanceWeights::wavelength(i) - kFirstNm) / kRangeNm;
        const double x = (c[0] * t + c[1]) * t + c[2];
        const double root = std::sqrt(1.0 + x * x);
        const double s = 0.5 + x / (2.0 * root);
        const double ds_dx = 0.5 / (root * root * root);
        const Vec3 dx_dc = {t * t, t, 1.0};
        for (int ch = 0; ch < 3; ++ch) {
            e.residual[ch] += s * w.per_sample[i][ch];
            for (int j = 0; j < 3; ++j) e.jacobian[ch][j] += ds_dx * dx_dc[j] * w.per_sample[i][ch];
        }
    }
    for (int ch = 0; ch < 3; ++ch) e.residual[ch] -= target[ch];
    return e;
}

double norm2(const Vec3& v) {
    return v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
}

// Solves A x = b by Gaussian elimination with partial pivoting; false if A is singular.
bool solve3(Mat3 a, Vec3 b, Vec3& x) {
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 3; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (std::abs(a[pivot][col]) < 1e-300) return false;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (int r = col + 1; r < 3; ++r) {
            const double f = a[r][col] / a[col][col];
            for (int k = col; k < 3; ++k) a[r][k] -= f * a[col][k];
            b[r] -= f * b[col];
        }
    }
    for (int r = 2; r >= 0; --r) {
        double sum = b[r];
        for (int k = r + 1; k < 3; ++k) sum -= a[r][k] * x[k];
        x[r] = sum / a[r][r];
    }
    return true;
}

// The damped Gauss–Newton step: (JᵀJ + μ diag(JᵀJ)) δ = −Jᵀ r.
bool damped_step(const Evaluation& e, double mu, Vec3& step) {
    Mat3 normal{};
    Vec3 gradient{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            for (int ch = 0; ch < 3; ++ch) normal[i][j] += e.jacobian[ch][i] * e.jacobian[ch][j];
        for (int ch = 0; ch < 3; ++ch) gradient[i] -= e.jacobian[ch][i] * e.residual[ch];
    }
    for (int i = 0; i < 3; ++i) normal[i][i] *= 1.0 + mu;
    return solve3(normal, gradient, step);
}

}  // namespace

double sigmoid(double x) {
    if (std::isinf(x)) return x > 0.0 ? 1.0 : 0.0;
    return 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
}

SigmoidFit fit_sigmoid_polynomial(const Vec3& target, const NormalisedCoefficients& start,
                                  double tolerance, int max_steps) {
    NormalisedCoefficients c = start;
    Evaluation e = evaluate(c, target);
    double error = norm2(e.residual);
    double mu = 1e-3;
    int accepted = 0;
    for (int iteration = 0;
         iteration < kMaxIterations && accepted < max_steps && error > tolerance * tolerance;
         ++iteration) {
        Vec3 step{};
        if (!damped_step(e, mu, step)) break;
        const NormalisedCoefficients trial = {c[0] + step[0], c[1] + step[1], c[2] + step[2]};
        const Evaluation trial_e = evaluate(trial, target);
        const double trial_error = norm2(trial_e.residual);
        if (trial_error < error) {
            c = trial;
            e = trial_e;
            error = trial_error;
            ++accepted;
            mu = std::max(mu * 0.1, 1e-12);
        } else {
            mu *= 10.0;
            if (mu > 1e12) break;
        }
    }
    double worst = 0.0;
    for (double r : e.residual) worst = std::max(worst, std::abs(r));
    return {c, worst};
}

std::array<double, 3> to_nm_coefficients(const NormalisedCoefficients& c) {
    // t = (λ − a) / w  ⇒  c0 t² + c1 t + c2 = A λ² + B λ + C.
    const double a = kFirstNm, w = kRangeNm;
    return {c[0] / (w * w), c[1] / w - 2.0 * c[0] * a / (w * w),
            c[0] * a * a / (w * w) - c[1] * a / w + c[2]};
}

}  // namespace glint::spectral
