-- expect-exit: 1
-- expect-message: scene_union_with_number.lua:8:
-- expect-message: entry 2 is not a solid
-- expect-message: got a number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local u = glint.union{ glint.solid.sphere{}, 3 }
