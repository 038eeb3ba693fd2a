-- expect-exit: 1
-- expect-message: sandbox_dofile.lua:4:
-- expect-message: dofile is not available
dofile('other.lua')
