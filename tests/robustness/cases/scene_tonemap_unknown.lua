-- expect-exit: 1
-- expect-message: scene_tonemap_unknown.lua:7:
-- expect-message: unknown tonemap 'agx' (expected: clip, reinhard, filmic)
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ width = 8, height = 8, tonemap = "agx" }
