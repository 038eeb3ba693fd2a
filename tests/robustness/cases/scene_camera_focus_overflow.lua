-- expect-exit: 1
-- expect-message: scene_camera_focus_overflow.lua:7:
-- expect-message: 'focus_distance' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.camera{ focus_distance = 1e39 }
