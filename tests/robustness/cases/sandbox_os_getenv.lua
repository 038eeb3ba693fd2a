-- expect-exit: 1
-- expect-message: sandbox_os_getenv.lua:4:
-- expect-message: may read only variables whose names start with GLINT_
print(os.getenv('HOME'))
