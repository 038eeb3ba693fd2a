-- expect-exit: 1
-- expect-message: sandbox_error_number.lua:4:
-- expect-message: error(42): the script raised a number
error(42)
