-- expect-exit: 1
-- expect-message: scene_max_depth_fraction.lua:7:
-- expect-message: 'max_depth' must be an integer
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ max_depth = 2.5 }
