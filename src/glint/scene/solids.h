#pragma once
// Builds the CSG trees described in a SceneDesc into Solids, assigning every primitive a
// part index and its material (its own, or the nearest enclosing node's).
#include <glint/geometry/csg/solid_shape.h>
#include <glint/material/material.h>
#include <glint/scene/scene_desc.h>

#include <memory>
#include <vector>

namespace glint {

struct BuiltSolid {
    std::unique_ptr<SolidShape> shape;
    std::vector<const Material*> part_materials;
};

std::vector<std::string> solid_types();

// `placement` is the shape entry that placed the solid (for error locations).
BuiltSolid build_solid(const SceneDesc& desc, int root, const Params& placement,
                       const std::vector<std::unique_ptr<Material>>& materials, bool shortcuts);

}  // namespace glint
