-- expect-exit: 1
-- expect-message: sandbox_setmetatable_handle.lua:4:
-- expect-message: bad argument
setmetatable(glint.diffuse{}, {})
