-- expect-exit: 1
-- expect-message: scene_rotate_inf.lua:7:
-- expect-message: glint.rotate: 'angle' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local r = glint.rotate(1e39, {0, 1, 0})
