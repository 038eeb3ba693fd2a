-- expect-exit: 1
-- expect-message: sandbox_time_limit_loop.lua:7: script ran past its time limit of 1 s (an endless loop?)
-- args: --script-time-limit 1
-- Issue 17: a script that never ends stops at the time limit (here 1 s, by default 60 s)
-- even with no instruction budget in sight, and a pcall cannot catch it for good.
local x = 0
while true do pcall(function() while true do x = x + 1 end end) end
