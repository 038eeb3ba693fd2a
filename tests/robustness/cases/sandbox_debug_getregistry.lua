-- expect-exit: 1
-- expect-message: sandbox_debug_getregistry.lua:4:
-- expect-message: debug.getregistry is not available
local r = debug.getregistry()
