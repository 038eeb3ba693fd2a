-- expect-exit: 2
-- expect-message: --script-time-limit: 'nan' is not a number of seconds
-- args: --script-time-limit nan
glint.sphere{ radius = 1, material = glint.diffuse{} }
