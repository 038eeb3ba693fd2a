-- expect-exit: 1
-- expect-message: scene_denoise_not_boolean.lua:7:
-- expect-message: 'denoise' must be a boolean
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ width = 8, height = 8, denoise = "yes" }
