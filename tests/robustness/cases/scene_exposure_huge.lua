-- expect-exit: 1
-- expect-message: scene_exposure_huge.lua:7:
-- expect-message: 'exposure' must be in [-100, 100]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ exposure = 1e6 }
