-- expect-exit: 1
-- expect-message: sandbox_forged_handle.lua:8:
-- expect-message: glint.add expects a solid
-- expect-message: got a table
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.add(setmetatable({}, { __name = 'glint.handle' }))
