-- expect-exit: 1
-- expect-message: sandbox_package_path.lua:4:
-- expect-message: package.path is not available
package.path = '/tmp/?.lua'
