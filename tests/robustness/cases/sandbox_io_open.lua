-- expect-exit: 1
-- expect-message: sandbox_io_open.lua:4:
-- expect-message: io.open is not available
local f = io.open('pwned', 'w')
