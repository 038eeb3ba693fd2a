-- expect-exit: 1
-- expect-message: scene_add_material.lua:8:
-- expect-message: glint.add expects a solid
-- expect-message: got a material
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(glint.diffuse{})
