-- expect-exit: 1
-- expect-message: sandbox_time_limit_pattern.lua:9: script ran past its time limit of 1 s inside a call that cannot be interrupted
-- expect-message: a string pattern that backtracks
-- args: --script-time-limit 1
-- Issue 17: the time is spent inside one call of string.find (the pattern backtracks in
-- time polynomial of degree 6 in the subject's length), where the instruction budget never
-- runs: the watchdog ends the process, naming the line.
local subject = string.rep("a", 100000)
local found = string.find(subject, ".-.-.-.-.-b")
