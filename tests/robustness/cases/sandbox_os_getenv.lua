-- expect-exit: 1
-- expect-message: sandbox_os_getenv.lua:4:
-- expect-message: os.getenv is not available
print(os.getenv('HOME'))
