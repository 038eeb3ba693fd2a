-- expect-exit: 1
-- expect-message: scene_environment_rotation.lua:7:
-- expect-message: 'rotation' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.environment{ file = 'sky.exr', rotation = 1e39 }
