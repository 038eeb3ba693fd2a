-- expect-exit: 1
-- expect-message: sandbox_os_exit.lua:4:
-- expect-message: os.exit is not available
os.exit(0)
