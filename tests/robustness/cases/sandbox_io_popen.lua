-- expect-exit: 1
-- expect-message: sandbox_io_popen.lua:4:
-- expect-message: io.popen is not available
io.popen('ls')
