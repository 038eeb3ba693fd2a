-- expect-exit: 1
-- expect-message: scene_csg_deep_unions.lua:8:
-- expect-message: this CSG tree would be 1001 nodes deep
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local s = glint.solid.sphere{}
for i = 1, 100000 do s = glint.union{ s } end
