// A film's exact sums as image channels, for partial renders (`glint render --samples A:B`)
// and the MPI ranks, and adding them back into a film (`glint merge`).
//
// Every sum is a 128-bit fixed-point number (fixed_sum.h) stored as eight 16-bit words, each
// a float channel holding an integer 0 .. 65535 (exact in a float), least significant first:
//   sum.weight.0..7              the pixel's filter weights
//   sum.R.0..7, sum.G.*, sum.B.*  weight times radiance
//   sum.nonfinite.0..1           samples dropped as not finite (a 32-bit count)
// and with AOVs:
//   sum.aov_weight.*, sum.albedo.{R,G,B}.*, sum.normal.{X,Y,Z}.*, sum.depth.Z.*
// R, G, B hold the partial render's own mean, for looking at it; merging ignores them.
#include <glint/core/error.h>
#include <glint/film/film.h>

#include <fmt/format.h>

#include <array>

namespace glint {

namespace {

constexpr std::array<const char*, 4> kRadianceSums = {"weight", "R", "G", "B"};
constexpr std::array<const char*, 8> kAovSums = {"aov_weight", "albedo.R", "albedo.G", "albedo.B",
                                                 "normal.X",   "normal.Y", "normal.Z", "depth.Z"};
constexpr int kCountWords = 2;

void add_word_channels(std::vector<std::string>& channels, const std::string& name, int words) {
    for (int i = 0; i < words; ++i) channels.push_back(fmt::format("sum.{}.{}", name, i));
}

// The first of a sum's word channels in `image`; throws unless all are there, in order.
int word_channels(const Image& image, const std::string& name, int words) {
    const int first = image.channel_index(fmt::format("sum.{}.0", name));
    for (int i = 0; i < words; ++i) {
        if (first < 0 || image.channel_index(fmt::format("sum.{}.{}", name, i)) != first + i) {
            throw Error(fmt::format("not a partial render: channel sum.{}.{} is missing", name, i));
        }
    }
    return first;
}

void put_sum(Image& image, int x, int y, int channel, const FixedSum& sum) {
    for (int i = 0; i < FixedSum::kWords; ++i)
        image.at(x, y, channel + i) = static_cast<float>(sum.word(i));
}

FixedSum get_sum(const Image& image, int x, int y, int channel) {
    uint16_t words[FixedSum::kWords];
    for (int i = 0; i < FixedSum::kWords; ++i) {
        const float value = image.at(x, y, channel + i);
        if (!(value >= 0.0f && value <= 65535.0f) ||
            value != static_cast<float>(static_cast<int>(value)))
            throw Error(
                fmt::format("partial render: pixel ({}, {}) holds {} where a 16-bit word "
                            "was expected (a file not written by glint render --samples?)",
                            x, y, value));
        words[i] = static_cast<uint16_t>(value);
    }
    return FixedSum::from_words(words);
}

}  // namespace

Image Film::sums_image() const {
    if (!m_splats.empty() || m_with_halves)
        throw Error("film: a partial render cannot carry splats or the denoiser's halves");
    Image image = resolve();
    std::vector<std::string> channels = image.channels;
    const int radiance_first = static_cast<int>(channels.size());
    for (const char* name : kRadianceSums) add_word_channels(channels, name, FixedSum::kWords);
    const int count_first = static_cast<int>(channels.size());
    add_word_channels(channels, "nonfinite", kCountWords);
    const int aov_first = static_cast<int>(channels.size());
    if (m_with_aovs) {
        for (const char* name : kAovSums) add_word_channels(channels, name, FixedSum::kWords);
    }
    Image sums = make_image(m_width, m_height, channels);
    for (int y = 0; y < m_height; ++y) {
        for (int x = 0; x < m_width; ++x) {
            for (int c = 0; c < image.num_channels(); ++c) sums.at(x, y, c) = image.at(x, y, c);
            const std::size_t i = static_cast<std::size_t>(y) * m_width + x;
            const Pixel& p = m_pixels[i];
            put_sum(sums, x, y, radiance_first, p.weight_sum);
            for (int c = 0; c < 3; ++c)
                put_sum(sums, x, y, radiance_first + (1 + c) * FixedSum::kWords, p.rgb[c]);
            sums.at(x, y, count_first) = static_cast<float>(p.non_finite & 0xffff);
            sums.at(x, y, count_first + 1) = static_cast<float>(p.non_finite >> 16);
            if (!m_with_aovs) continue;
            const AovPixel& a = m_aovs[i];
            const FixedSum* aov_sums[8] = {&a.weight_sum, &a.albedo[0], &a.albedo[1], &a.albedo[2],
                                           &a.normal[0],  &a.normal[1], &a.normal[2], &a.depth};
            for (int k = 0; k < 8; ++k)
                put_sum(sums, x, y, aov_first + k * FixedSum::kWords, *aov_sums[k]);
        }
    }
    return sums;
}

void Film::add_sums_image(const Image& sums) {
    if (sums.width != m_width || sums.height != m_height) {
        throw Error(fmt::format("partial render of {}x{} pixels added to a film of {}x{}",
                                sums.width, sums.height, m_width, m_height));
    }
    if (m_with_halves) throw Error("film: partial renders cannot fill the denoiser's halves");
    int radiance[4];
    for (int k = 0; k < 4; ++k)
        radiance[k] = word_channels(sums, kRadianceSums[k], FixedSum::kWords);
    const int count = word_channels(sums, "nonfinite", kCountWords);
    const bool has_aovs = sums.channel_index("sum.aov_weight.0") >= 0;
    if (has_aovs != m_with_aovs) {
        throw Error(has_aovs ? "partial render has AOVs, the others not (render all with --aovs "
                               "or none)"
                             : "partial render lacks the AOVs the others have (render all with "
                               "--aovs or none)");
    }
    int aov[8] = {};
    for (int k = 0; k < 8 && has_aovs; ++k)
        aov[k] = word_channels(sums, kAovSums[k], FixedSum::kWords);
    for (int y = 0; y < m_height; ++y) {
        for (int x = 0; x < m_width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * m_width + x;
            Pixel& p = m_pixels[i];
            p.weight_sum += get_sum(sums, x, y, radiance[0]);
            for (int c = 0; c < 3; ++c) p.rgb[c] += get_sum(sums, x, y, radiance[1 + c]);
            p.non_finite += static_cast<uint32_t>(sums.at(x, y, count)) +
                            (static_cast<uint32_t>(sums.at(x, y, count + 1)) << 16);
            if (!m_with_aovs) continue;
            AovPixel& a = m_aovs[i];
            FixedSum* aov_sums[8] = {&a.weight_sum, &a.albedo[0], &a.albedo[1], &a.albedo[2],
                                     &a.normal[0],  &a.normal[1], &a.normal[2], &a.depth};
            for (int k = 0; k < 8; ++k) *aov_sums[k] += get_sum(sums, x, y, aov[k]);
        }
    }
}

}  // namespace glint
