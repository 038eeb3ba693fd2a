-- expect-exit: 1
-- expect-message: sandbox_error_table.lua:4:
-- expect-message: the script raised an error whose value is a table
error({})
