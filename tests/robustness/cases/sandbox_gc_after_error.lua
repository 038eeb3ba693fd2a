-- expect-exit: 1
-- expect-message: sandbox_gc_after_error.lua:8:
-- expect-message: boom
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
setmetatable({}, { __gc = function() glint.sphere{ radius = 2, material = m } end })
error('boom')
