-- expect-exit: 1
-- expect-message: scene_render_debug_bogus.lua:7:
-- expect-message: unknown debug view 'bogus'
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ debug = 'bogus' }
