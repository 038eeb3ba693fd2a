-- expect-exit: 1
-- expect-message: scene_add_material_as_settings.lua:7:
-- expect-message: the settings must be a table such as {material = m}, got a material
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(glint.solid.sphere{}, glint.diffuse{})
