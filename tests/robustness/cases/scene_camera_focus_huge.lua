-- expect-exit: 1
-- expect-message: scene_camera_focus_huge.lua:7:
-- expect-message: 'focus_distance' must be at most 1e+12
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.camera{ focus_distance = 1e30 }
