-- expect-exit: 1
-- expect-message: sandbox_os_tmpname.lua:4:
-- expect-message: os.tmpname is not available
os.tmpname()
