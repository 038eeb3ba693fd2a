-- expect-exit: 1
-- expect-message: scene_scale_zero.lua:7:
-- expect-message: factors must not be zero
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local s = glint.scale(0)
