-- expect-exit: 1
-- expect-message: scene_group_contains_itself.lua:9:
-- expect-message: a group cannot contain itself
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local g = glint.group()
g:sphere{ radius = 1, material = m }
g:place(g)
glint.place(g)
