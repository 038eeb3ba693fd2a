-- expect-exit: 1
-- expect-message: sandbox_binary_load_mode.lua:4:
-- expect-message: text chunks only
local f = load(string.dump(function() end), 'x', 'b')
