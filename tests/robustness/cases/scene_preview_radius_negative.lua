-- expect-exit: 1
-- expect-message: scene_preview_radius_negative.lua:7:
-- expect-message: 'preview_radius' must be in [0, 1e12]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ integrator = 'preview', preview_radius = -1 }
