#pragma once
// Light subpaths as bytes, for the ranks of an MPI job to exchange (vcm shares each
// iteration's light subpaths among the ranks this way, docs/cluster.md): every vertex bit
// for bit, its pointers as indices into the scene's lists (lights, materials), and its BSDF
// made again on the receiving side from its surface, whose shading frame is already final,
// so that both sides hold the same vertex.
#include <glint/core/arena.h>
#include <glint/film/film.h>
#include <glint/integrator/bidirectional/subpath.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace glint {

class SubpathCodec {
public:
    explicit SubpathCodec(const Scene& scene);

    /// Appends `path` and its scene time to `out`.
    void write(const std::vector<PathVertex>& path, float time, std::vector<uint8_t>& out) const;
    /// Reads a path written by write() from `bytes` at `at` (moved past it) into `path` and
    /// `time`, its BSDFs made in `arena`. Throws glint::Error for bytes that end early.
    void read(const std::vector<uint8_t>& bytes, size_t& at, std::vector<PathVertex>& path,
              float& time, Arena& arena) const;

    /// Appends splats (film position and colour) to `out`; read_splats reads them back.
    static void write_splats(const std::vector<Splat>& splats, std::vector<uint8_t>& out);
    static void read_splats(const std::vector<uint8_t>& bytes, size_t& at,
                            std::vector<Splat>& splats);

private:
    int32_t index_of_material(const Material* material) const;
    int32_t index_of_medium(const Medium* medium) const;  // a media() search: media are few

    const Scene& m_scene;
    std::unordered_map<const Material*, int32_t> m_material_index;
};

}  // namespace glint
