-- expect-exit: 1
-- expect-message: scene_sphere_center_inf.lua:7:
-- expect-message: 'center' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.sphere{ center = {0, 1/0, 0}, material = m }
