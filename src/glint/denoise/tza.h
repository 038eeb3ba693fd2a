#pragma once
// Reader of the tensor archives (.tza) in which Open Image Denoise publishes its trained
// networks. An archive is little-endian: a header (magic 0x41D7 as uint16, major version 2
// and a minor version as uint8, the offset of the tensor table as uint64), the tensors' data,
// then the table: a uint32 count and for each tensor its name (uint16 length and the bytes),
// the number of dimensions (uint8), each dimension (uint32), the layout (one letter per
// dimension: "oihw" for convolution weights, "x" for biases), the element type ('f' for
// float32, 'h' for float16) and the offset of its data (uint64).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace glint {

/// One tensor of an archive, widened to float.
struct Tensor {
    std::vector<int> dims;      ///< e.g. {out, in, 3, 3} for "oihw", {out} for "x"
    std::string layout;         ///< "oihw" or "x"
    std::vector<float> values;  ///< row-major in the order of `dims`
    std::size_t size() const { return values.size(); }
};

/// The tensors of an archive by name ("enc_conv0.weight", "enc_conv0.bias", ...).
using TensorArchive = std::map<std::string, Tensor>;

/// Parses an archive held in memory. `origin` names it in messages (a file path). Throws
/// glint::Error naming the origin and what is wrong when the bytes are not an archive of
/// version 2 (bad magic, another version), are truncated, or hold a table entry that points
/// outside them or has an unknown layout or element type.
TensorArchive parse_tza(const std::vector<std::uint8_t>& bytes, const std::string& origin);

/// Reads and parses the archive at `path`; throws glint::Error when it cannot be read or
/// parsed.
TensorArchive read_tza(const std::string& path);

/// IEEE 754 binary16 to float (subnormals, infinities and NaNs included).
float half_to_float(std::uint16_t half);

}  // namespace glint
