-- expect-exit: 1
-- expect-message: scene_rotate_zero_axis.lua:7:
-- expect-message: axis must not be zero
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local r = glint.rotate(30, {0, 0, 0})
