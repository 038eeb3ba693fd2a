-- expect-exit: 1
-- expect-message: sandbox_loadfile.lua:4:
-- expect-message: loadfile is not available
loadfile('other.lua')
