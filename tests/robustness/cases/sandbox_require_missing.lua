-- expect-exit: 1
-- expect-message: sandbox_require_missing.lua:4:
-- expect-message: require('no_such_module'): no module file
require('no_such_module')
