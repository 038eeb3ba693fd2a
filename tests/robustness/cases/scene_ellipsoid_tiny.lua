-- expect-exit: 1
-- expect-message: scene_ellipsoid_tiny.lua:7:
-- expect-message: 'a' must be in [1e-06, 1e+06]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(glint.solid.ellipsoid{ a = 1e-30 }, { material = m })
