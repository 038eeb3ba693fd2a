-- expect-exit: 1
-- expect-message: sandbox_finaliser_loops.lua:10: script ran past its time limit of 1 s
-- expect-message: or a __gc finaliser
-- args: --script-time-limit 1
-- Issue 28: a finaliser that loops runs with Lua's hooks off, so only the watchdog ends it;
-- the message names the line that ran it and says a finaliser may be the cause.
glint.sphere{ radius = 1, material = glint.diffuse{} }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
setmetatable({}, { __gc = function() while true do end end })
collectgarbage()
