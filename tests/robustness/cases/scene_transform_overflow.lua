-- expect-exit: 1
-- expect-message: scene_transform_overflow.lua:7:
-- expect-message: the transform is not finite
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local s = glint.scale(1e30) * glint.scale(1e30)
