-- expect-exit: 1
-- expect-message: scene_hyperboloid_huge.lua:7:
-- expect-message: 'c' must be in [1e-06, 1e+06]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(glint.solid.hyperboloid_one_sheet{ c = 1e20 }, { material = m })
