-- expect-exit: 1
-- expect-message: sandbox_metatable_hidden.lua:7:
-- expect-message: attempt to index a string value
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
getmetatable(m).__index = nil
