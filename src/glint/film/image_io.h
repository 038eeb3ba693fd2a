#pragma once
// Reading and writing images, and the relative-MSE comparison the tests and `glint compare`
// use. The formats themselves are in image_codecs.h (OpenEXR, stb, PFM).
#include <glint/film/image.h>
#include <glint/film/tonemap.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {

struct WriteOptions {
    float exposure = 0.0f;            ///< stops; scales linear values by 2^exposure, PNG only
    Tonemap tonemap = Tonemap::clip;  ///< the display curve after the exposure, PNG only
    /// PNG only: false stores the values, clamped to [0, 1], as they are (no exposure, tone
    /// curve or sRGB encoding), as data maps such as normal maps are stored.
    bool srgb = true;
    bool half = false;  ///< EXR only: 16-bit half floats instead of 32-bit floats
};

/// Writes by extension (case-insensitive): ".exr" stores every channel as 32-bit float;
/// ".png" stores 8-bit sRGB-encoded R, G, B (or one channel as grey): linear values
/// scaled by 2^exposure, mapped by the tone curve to [0, 1] (tonemap.h; "clip" clamps) and
/// correctly rounded. Anything else throws.
/// The image goes to a temporary file beside `path` that is renamed over it, so `path`
/// is never left half-written; on failure the temporary is removed and glint::Error
/// names the path and the reason. (An OutputBatch of one image; see output_batch.h.)
void write_image(const std::string& path, const Image& image, const WriteOptions& options = {});

/// Writes `image` to exactly `file` (format by its extension, as write_image), checking
/// every result of the writer, then flushes the file to the disk (fsync) and decodes it
/// again, so that a full disk or a file-size limit the encoder does not report is still
/// caught. Throws glint::Error with the reason; may leave a partial `file` behind, which
/// is why only OutputBatch calls it, on a temporary.
void write_image_file(const std::string& file, const Image& image, const WriteOptions& options);

/// An image as its file stores it.
struct StoredImage {
    Image image;
    /// The file holds integer code values (PNG, JPEG, ...), here scaled to [0, 1] and not
    /// yet decoded from sRGB; false for float files (EXR, HDR, PFM).
    bool integer = false;
    int bits_per_value = 32;  ///< 8 or 16 for integer files
    int alpha = -1;           ///< the alpha channel's position, or -1
    /// 8-bit files read with `eight_bit_codes`: the code values themselves, laid out as
    /// image.pixels would be, which is then left empty (a quarter of the memory).
    std::vector<uint8_t> codes;
};

/// Reads OpenEXR, PNG, JPEG, Radiance HDR, TGA, BMP, PNM, PSD, GIF and PFM files, the
/// format found from the file's first bytes, not its name. The header is checked before
/// any pixel is allocated (core/memory.h, check_image_header: sizes within limits and
/// plausible for the file's size, the decoded image within the memory budget). Throws
/// glint::Error naming the path if the file cannot be read, its header lies, or its data
/// ends early.
StoredImage read_stored_image(const std::string& path, bool eight_bit_codes = false);

/// read_stored_image with integer files decoded from sRGB to linear, alpha excepted, so
/// read_image(write_image(x)) gives x back up to 8-bit quantisation. EXR channel order is
/// the file's (OpenEXR sorts layers by name): look channels up by name.
Image read_image(const std::string& path);

/// The sRGB transfer curve (IEC 61966-2-1): an encoded value in [0, 1] to linear, and back.
float srgb_to_linear(float encoded);
double linear_to_srgb(double linear);

struct CompareResult {
    double rel_mse;                   ///< mean of (t - r)^2 / (r^2 + 1e-2)
    double rmse;                      ///< sqrt of the mean of (t - r)^2
    std::array<double, 3> test_mean;  ///< per-channel means of R, G, B
    std::array<double, 3> ref_mean;
    uint64_t non_finite = 0;  ///< R, G, B values (of either image) that are NaN or infinite
};

/// Compares the R, G, B channels (found by name) of two images of the same size, over
/// all pixels and the three channels. A non-finite value in either image makes rel_mse and
/// rmse NaN (and is counted in non_finite), so that no threshold test can pass. Throws glint::Error
/// on a size mismatch or a missing channel.
CompareResult compare_images(const Image& test, const Image& reference);

}  // namespace glint
