-- expect-exit: 1
-- expect-message: scene_table_deep.lua:10:
-- expect-message: nested more than 64 deep
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local t = {}
local c = t
for i = 1, 150 do c[1] = {}; c = c[1] end
glint.sphere{ center = t, material = m }
