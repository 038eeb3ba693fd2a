-- expect-exit: 1
-- expect-message: scene_shape_given_handle.lua:8:
-- expect-message: sphere expects a table of named parameters
-- expect-message: got a material
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.sphere(glint.diffuse{})
