-- expect-exit: 1
-- expect-message: sandbox_c_stack_overflow_line.lua:6: C stack overflow
-- Issue 28: Lua's "C stack overflow" (gsub calling itself through its replacement function)
-- names the script's line.
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
local function f(s) return (s:gsub(".", f)) end
f("a")
