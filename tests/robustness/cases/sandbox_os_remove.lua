-- expect-exit: 1
-- expect-message: sandbox_os_remove.lua:4:
-- expect-message: os.remove is not available
os.remove('x')
