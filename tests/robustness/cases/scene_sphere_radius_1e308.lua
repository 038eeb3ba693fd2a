-- expect-exit: 1
-- expect-message: scene_sphere_radius_1e308.lua:7:
-- expect-message: 'radius' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.sphere{ radius = 1e308, material = m }
