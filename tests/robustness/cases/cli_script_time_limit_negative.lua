-- expect-exit: 2
-- expect-message: --script-time-limit: '-1' is not a number of seconds from 0 (no limit) to 1e+06
-- args: --script-time-limit -1
glint.sphere{ radius = 1, material = glint.diffuse{} }
