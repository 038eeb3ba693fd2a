-- expect-exit: 1
-- expect-message: scene_camera_fov_nan.lua:8:
-- expect-message: 'fov' must be a finite number
-- expect-message: got NaN
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.camera{ fov = 0/0 }
