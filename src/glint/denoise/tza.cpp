#include <glint/core/error.h>
#include <glint/denoise/tza.h>

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

namespace glint {

namespace {

// A bounds-checked little-endian cursor over the archive's bytes: every read names the
// archive and says that it ended early, instead of reading past the end.
class Cursor {
public:
    Cursor(const std::vector<std::uint8_t>& bytes, const std::string& origin)
        : m_bytes(bytes), m_origin(origin) {}

    template <typename T>
    T read(const char* what) {
        need(sizeof(T), what);
        T value;
        std::memcpy(&value, m_bytes.data() + m_pos, sizeof(T));
        m_pos += sizeof(T);
        return value;
    }
    std::string read_string(std::size_t length, const char* what) {
        need(length, what);
        std::string text(reinterpret_cast<const char*>(m_bytes.data() + m_pos), length);
        m_pos += length;
        return text;
    }
    void seek(std::uint64_t position, const char* what) {
        if (position > m_bytes.size()) fail(fmt::format("{} points past its end", what));
        m_pos = static_cast<std::size_t>(position);
    }
    [[noreturn]] void fail(const std::string& message) const {
        throw Error(
            fmt::format("{}: not a valid denoiser weights archive (.tza): {}", m_origin, message));
    }

private:
    void need(std::size_t count, const char* what) const {
        if (m_bytes.size() - m_pos < count)
            fail(fmt::format("truncated: it ends inside {} (byte {} of {})", what, m_pos,
                             m_bytes.size()));
    }
    const std::vector<std::uint8_t>& m_bytes;
    const std::string& m_origin;
    std::size_t m_pos = 0;
};

static_assert(std::endian::native == std::endian::little,
              "the .tza reader copies little-endian values as they are");

Tensor read_tensor_entry(Cursor& cursor, const std::vector<std::uint8_t>& bytes,
                         std::string& name) {
    const auto name_length = cursor.read<std::uint16_t>("a tensor name's length");
    name = cursor.read_string(name_length, "a tensor name");
    Tensor tensor;
    const auto rank = cursor.read<std::uint8_t>("a tensor's rank");
    std::uint64_t count = 1;
    for (int i = 0; i < rank; ++i) {
        const auto dim = cursor.read<std::uint32_t>("a tensor's shape");
        if (dim == 0 || dim > (1u << 24))
            cursor.fail(fmt::format("tensor '{}' has a dimension of {}", name, dim));
        tensor.dims.push_back(static_cast<int>(dim));
        count *= dim;
    }
    tensor.layout = cursor.read_string(rank, "a tensor's layout");
    if (tensor.layout != "oihw" && tensor.layout != "x")
        cursor.fail(
            fmt::format("tensor '{}' has layout '{}' (expected oihw or x)", name, tensor.layout));
    const char type = cursor.read<char>("a tensor's element type");
    if (type != 'f' && type != 'h')
        cursor.fail(fmt::format("tensor '{}' has element type '{}' (expected f or h)", name, type));
    const std::uint64_t offset = cursor.read<std::uint64_t>("a tensor's data offset");
    const std::uint64_t element = type == 'f' ? 4 : 2;
    if (count > (std::uint64_t{1} << 32) || offset > bytes.size() ||
        (bytes.size() - offset) / element < count)
        cursor.fail(fmt::format("the data of tensor '{}' lies outside the file", name));
    tensor.values.resize(static_cast<std::size_t>(count));
    const std::uint8_t* data = bytes.data() + offset;
    for (std::size_t i = 0; i < tensor.values.size(); ++i) {
        if (type == 'f') {
            std::memcpy(&tensor.values[i], data + 4 * i, 4);
        } else {
            std::uint16_t half;
            std::memcpy(&half, data + 2 * i, 2);
            tensor.values[i] = half_to_float(half);
        }
    }
    return tensor;
}

}  // namespace

float half_to_float(std::uint16_t half) {
    const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000u) << 16;
    const int exponent = (half >> 10) & 0x1f;
    const std::uint32_t mantissa = half & 0x3ffu;
    if (exponent == 0) {
        // Zero or subnormal: mantissa * 2^-24, exact in float.
        const float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
        return sign ? -magnitude : magnitude;
    }
    std::uint32_t bits;
    if (exponent == 31)
        bits = sign | 0x7f800000u | (mantissa << 13);  // infinity or NaN
    else
        bits = sign | (static_cast<std::uint32_t>(exponent - 15 + 127) << 23) | (mantissa << 13);
    return std::bit_cast<float>(bits);
}

TensorArchive parse_tza(const std::vector<std::uint8_t>& bytes, const std::string& origin) {
    Cursor cursor(bytes, origin);
    if (cursor.read<std::uint16_t>("the header") != 0x41D7)
        cursor.fail("it does not start with the magic number 0x41D7");
    const int major = cursor.read<std::uint8_t>("the header");
    cursor.read<std::uint8_t>("the header");  // the minor version changes nothing we read
    if (major != 2) cursor.fail(fmt::format("format version {} (glint reads version 2)", major));
    cursor.seek(cursor.read<std::uint64_t>("the header"), "the table offset");
    const auto count = cursor.read<std::uint32_t>("the tensor table");
    TensorArchive archive;
    for (std::uint32_t i = 0; i < count; ++i) {
        std::string name;
        Tensor tensor = read_tensor_entry(cursor, bytes, name);
        if (!archive.emplace(name, std::move(tensor)).second)
            cursor.fail(fmt::format("tensor '{}' appears twice", name));
    }
    return archive;
}

TensorArchive read_tza(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(fmt::format("{}: cannot open the denoiser weights", path));
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                    std::istreambuf_iterator<char>());
    if (file.bad()) throw Error(fmt::format("{}: cannot read the denoiser weights", path));
    return parse_tza(bytes, path);
}

}  // namespace glint
