-- expect-exit: 1
-- expect-message: scene_groups_exponential.lua:9:
-- expect-message: more than 1000000 times
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local g = glint.group()
g:sphere{ radius = 1, material = m }
for i = 1, 40 do local h = glint.group(); h:place(g); h:place(g, glint.translate(1, 0, 0)); g = h end
glint.place(g)
