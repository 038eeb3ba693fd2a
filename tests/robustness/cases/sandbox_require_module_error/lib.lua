local M = {}
function M.ball(m)
  glint.sphere{ radius = -1, material = m }
end
return M
