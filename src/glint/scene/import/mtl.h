#pragma once
// Wavefront material libraries (.mtl) and their mapping onto glint's materials.
#include <glint/core/params.h>
#include <glint/math/vector.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

/// One texture map statement (`map_Kd -bm 0.5 wood.png`): the file and the options glint uses.
struct MtlMap {
    std::string file;                ///< as written, relative to the .mtl file's directory
    float bump_multiplier = 1;       ///< `-bm`
    Vec2 scale{1.0f}, offset{0.0f};  ///< `-s`, `-o` (u and v)
    bool clamp = false;              ///< `-clamp on`
};

/// One `newmtl` block. Unset values are those the file does not give.
struct MtlMaterial {
    std::string name;
    std::string where;  ///< "file.mtl:LINE" of its newmtl
    std::optional<Vec3> kd, ks, ke;
    std::optional<float> ns, ni, d;
    std::optional<int> illum;
    std::optional<MtlMap> map_kd, map_ks, map_ke, map_bump, norm, map_d;
    std::vector<std::string> ignored;  ///< statements read but not mapped (for a warning)
};

/// Parses MTL text. Understands newmtl, Ka (ignored), Kd, Ks, Ke, Ns, Ni, d, Tr (as 1 - d),
/// Tf (ignored), illum and the maps map_Kd, map_Ks, map_Ke, map_Bump / bump, norm, map_d
/// with their options (-bm, -s, -o, -clamp, and the others skipped). Throws glint::Error
/// naming the file and line for a number that does not parse or is out of range, a
/// statement before any newmtl, or a map with no file name.
std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name);
std::vector<MtlMaterial> load_mtl(const std::string& path);

/// The glint material for an MTL material, as a description: see docs/scene-language.md,
/// "OBJ materials". Texture maps are appended to `textures` as image textures whose file
/// names are made absolute against `directory` (the .mtl file's); the returned Params refer
/// to them by ObjectRef{"texture", index}. Notes on what could not be mapped are appended
/// to `warnings`.
Params mtl_to_params(const MtlMaterial& material, const std::string& directory,
                     std::vector<Params>& textures, std::vector<std::string>& warnings);

}  // namespace glint
