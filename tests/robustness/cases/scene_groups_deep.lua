-- expect-exit: 1
-- expect-message: scene_groups_deep.lua:9:
-- expect-message: placed inside each other more than 1000 deep
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local g = glint.group()
g:sphere{ radius = 1, material = m }
for i = 1, 100000 do local h = glint.group(); h:place(g); g = h end
glint.place(g)
