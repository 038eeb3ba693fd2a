-- expect-exit: 1
-- expect-message: scene_background_negative.lua:7:
-- expect-message: 'radiance' must not be negative
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.background{ radiance = -1 }
