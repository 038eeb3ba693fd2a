-- expect-exit: 1
-- expect-message: sandbox_require_path.lua:4:
-- expect-message: a module name is made of
require('/etc/passwd')
