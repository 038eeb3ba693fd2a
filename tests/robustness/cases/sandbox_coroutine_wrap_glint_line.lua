-- expect-exit: 1
-- expect-message: sandbox_coroutine_wrap_glint_line.lua:7: sphere: parameter 'radius' must be a number
-- Issue 28: a glint function run as a coroutine names the line that resumed it.
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local m = glint.diffuse{}
local make = coroutine.wrap(glint.sphere)
make({ radius = "x", material = m })
