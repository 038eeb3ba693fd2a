-- expect-exit: 1
-- expect-message: sandbox_package_loadlib.lua:4:
-- expect-message: package.loadlib is not available
package.loadlib('libc.so.6', 'system')
