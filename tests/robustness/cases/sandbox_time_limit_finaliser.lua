-- expect-exit: 1
-- expect-message: sandbox_time_limit_finaliser.lua:8: script ran past its time limit of 1 s inside a call that cannot be interrupted
-- args: --script-time-limit 1
-- A finaliser runs when the VM closes, after the script has failed: it is script code, and
-- the time limit holds there too.
local subject = string.rep("a", 100000)
setmetatable({}, { __gc = function()
    subject:match(".-.-.-.-.-b")
end })
error("the scene stops here")
