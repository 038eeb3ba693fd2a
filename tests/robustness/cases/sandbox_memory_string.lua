-- expect-exit: 1
-- expect-message: sandbox_memory_string.lua:4:
-- expect-message: script ran past its memory limit of 1024 MiB
local s = string.rep('x', 1 << 30)
