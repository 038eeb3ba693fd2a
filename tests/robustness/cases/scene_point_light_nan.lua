-- expect-exit: 1
-- expect-message: scene_point_light_nan.lua:7:
-- expect-message: 'intensity' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.point_light{ position = {0, 1, 0}, intensity = 0/0 }
