-- expect-exit: 1
-- expect-message: scene_quadric_matrix_nan.lua:7:
-- expect-message: 'matrix' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(glint.solid.quadric{ matrix = {1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,0/0} }, { material = m })
