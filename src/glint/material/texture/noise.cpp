#include <glint/material/texture/noise.h>

#include <array>
#include <cstdint>

namespace glint {
namespace {

// Perlin's fixed permutation of 0..255 (Improving Noise, 2002).
constexpr std::array<uint8_t, 256> kPermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

constexpr bool is_permutation_of_bytes(const std::array<uint8_t, 256>& table) {
    std::array<bool, 256> seen{};
    for (uint8_t v : table) {
        if (seen[v]) return false;
        seen[v] = true;
    }
    return true;
}
static_assert(is_permutation_of_bytes(kPermutation));

// The permutation written twice, so that hashing a cell corner, P[P[P[x] + y] + z] with
// x, y, z in 0..256, never needs a wrap-around.
constexpr std::array<uint8_t, 512> kRepeated = [] {
    std::array<uint8_t, 512> table{};
    for (int i = 0; i < 512; ++i) table[i] = kPermutation[i & 255];
    return table;
}();

// The 12 directions from a cube's centre to its edge midpoints, padded to 16 (four
// repeated) so that the low 4 bits of a hash choose one without a division. The order is
// that of Perlin's reference grad(), so values match his implementation.
struct Gradient {
    int8_t x, y, z;
};
constexpr std::array<Gradient, 16> kGradients = {{
    {1, 1, 0},
    {-1, 1, 0},
    {1, -1, 0},
    {-1, -1, 0},
    {1, 0, 1},
    {-1, 0, 1},
    {1, 0, -1},
    {-1, 0, -1},
    {0, 1, 1},
    {0, -1, 1},
    {0, 1, -1},
    {0, -1, -1},
    {1, 1, 0},
    {-1, 1, 0},
    {0, -1, 1},
    {0, -1, -1},
}};

// The value at offset (x, y, z) from a corner of the linear function that the corner's
// gradient defines; zero at the corner itself.
float corner_value(int hash, float x, float y, float z) {
    const Gradient& g = kGradients[hash & 15];
    return g.x * x + g.y * y + g.z * z;
}

// 6t^5 - 15t^4 + 10t^3: its first and second derivatives vanish at 0 and 1, so the noise
// is C2 across cell faces (the 1985 cubic fade left visible creases in bump maps).
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float t, float a, float b) {
    return a + t * (b - a);
}

// The cell coordinate modulo 256, for any finite (integral) float. Beyond int range a cast
// would overflow; fmod is exact there (and slower, so only used there).
int lattice_index(float cell) {
    const float reduced = std::abs(cell) < 1e9f ? cell : std::fmod(cell, 256.0f);
    return static_cast<int>(reduced) & 255;
}

}  // namespace

// The bounds in noise.h. Inside a cell, with f in [0,1)^3 the position in it and c its 8
// corners,
//     n(f) = sum_c W_c(f) g_c.(f - c),   W_c = product over the axes of fade(f) or 1 - fade(f),
// a weighted mean (the W_c are >= 0 and sum to 1) of the corners' linear functions. The
// hash picks each g_c from the 12 directions (two components +-1, one 0), and the bounds
// hold for every such choice, so for any permutation table:
//   value: max over g of |g.v| is the sum of the two largest |v_i|, so
//          |n(f)| <= sum_c W_c(f) top2(|f - c|). Maximising over the cell (grid, then local
//          search) gives 1.03635 at f = (0.355, 0.482, 0.5) and its mirror images.
//   slope: along a unit direction e, dn/de = sum_c g_c.v_c with
//          v_c = (grad W_c . e)(f - c) + W_c e, so |dn/de| <= sum_c top2(|v_c|). The maximum
//          over f and e is 3.75 at the cell centre along an axis: there fade' = 15/8 and
//          every v_c has components of size 15/64 across e (and 7/64 along it), so the
//          bound is 8 * 2 * 15/64 = 3.75.
// At a lattice point f = 0 only the corner c = 0 has weight, and its linear function is
// zero there: the noise vanishes at every integer point.
float perlin_noise(const Vec3& p) {
    if (!is_finite(p)) return 0.0f;
    const Vec3 cell = glm::floor(p);
    const int x = lattice_index(cell.x), y = lattice_index(cell.y), z = lattice_index(cell.z);
    const Vec3 f = p - cell;  // position inside the cell, in [0, 1)

    const auto& P = kRepeated;
    const int a = P[x] + y, aa = P[a] + z, ab = P[a + 1] + z;
    const int b = P[x + 1] + y, ba = P[b] + z, bb = P[b + 1] + z;

    const float u = fade(f.x), v = fade(f.y), w = fade(f.z);
    const float x0 = f.x, x1 = f.x - 1.0f, y0 = f.y, y1 = f.y - 1.0f;
    const float z0 = f.z, z1 = f.z - 1.0f;
    return lerp(
        w,
        lerp(v, lerp(u, corner_value(P[aa], x0, y0, z0), corner_value(P[ba], x1, y0, z0)),
             lerp(u, corner_value(P[ab], x0, y1, z0), corner_value(P[bb], x1, y1, z0))),
        lerp(v, lerp(u, corner_value(P[aa + 1], x0, y0, z1), corner_value(P[ba + 1], x1, y0, z1)),
             lerp(u, corner_value(P[ab + 1], x0, y1, z1), corner_value(P[bb + 1], x1, y1, z1))));
}

namespace {

// Weighted mean of shape(noise) over the octaves; shape is the identity for fbm and abs
// for turbulence. Dividing by the total weight keeps the result in noise's own range.
template <typename Shape>
float fractal_sum(const Vec3& p, int octaves, float lacunarity, float gain, Shape shape) {
    float sum = 0.0f, total_weight = 0.0f;
    float frequency = 1.0f, weight = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        sum += weight * shape(perlin_noise(p * frequency));
        total_weight += weight;
        frequency *= lacunarity;
        weight *= gain;
    }
    return total_weight > 0.0f ? sum / total_weight : 0.0f;
}

}  // namespace

float fbm(const Vec3& p, int octaves, float lacunarity, float gain) {
    return fractal_sum(p, octaves, lacunarity, gain, [](float n) { return n; });
}

float turbulence(const Vec3& p, int octaves, float lacunarity, float gain) {
    return fractal_sum(p, octaves, lacunarity, gain, [](float n) { return std::abs(n); });
}

}  // namespace glint
