-- expect-exit: 1
-- expect-message: sandbox_debug_setmetatable.lua:4:
-- expect-message: debug.setmetatable is not available
debug.setmetatable(1, {})
