-- expect-exit: 1
-- expect-message: scene_camera_up_huge.lua:7:
-- expect-message: 'up' must lie within 1e+12
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.camera{ up = {0, 1e30, 0} }
