-- expect-exit: 1
-- expect-message: sandbox_os_execute.lua:5:
-- expect-message: os.execute is not available
-- expect-message: --trusted-scene
os.execute('touch pwned')
