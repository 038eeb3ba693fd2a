-- expect-exit: 1
-- expect-message: sandbox_pcall_glint_line.lua:7: sphere: parameter 'radius' must be a number
-- Issue 28: a glint function called through pcall names the script's line, not '?:' (the
-- value is checked when the scene is built, with the line the call recorded).
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local m = glint.diffuse{}
assert(pcall(glint.sphere, { radius = "x", material = m }))
