-- expect-exit: 1
-- expect-message: scene_preview_window_zero.lua:7:
-- expect-message: 'preview_window' must be in [1, 1024]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ integrator = 'preview', preview_window = 0 }
