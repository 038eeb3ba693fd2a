-- expect-exit: 1
-- expect-message: sandbox_binary_load.lua:4:
-- expect-message: text chunks only
local f = load(string.dump(function() return 1 end))
