-- expect-exit: 1
-- expect-message: scene_matrix_singular.lua:7:
-- expect-message: glint.matrix: the transform is singular
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local x = glint.matrix{1,0,0,0, 0,1,0,0, 0,0,1e-30,0, 0,0,0,1}
