glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0} }
local x = nil
local y = x.field
