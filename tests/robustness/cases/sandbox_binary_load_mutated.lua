-- expect-exit: 1
-- expect-message: sandbox_binary_load_mutated.lua:5:
-- expect-message: text chunks only
local b = string.dump(function() return 1 end)
local f = load(b:sub(1, 20) .. string.rep('\255', 40))
