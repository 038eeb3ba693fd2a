-- expect-exit: 1
-- expect-message: sandbox_io_write.lua:4:
-- expect-message: io.write is not available
io.write('x')
