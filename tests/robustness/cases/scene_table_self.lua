-- expect-exit: 1
-- expect-message: scene_table_self.lua:9:
-- expect-message: 'center' contains itself
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local t = {}
t[1] = t
glint.sphere{ center = t, material = m }
