glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0} }
glint.render{ width = 8, height = 8, spp = 1 }
-- 'iorr' is misspelt on line 4.
local glass = glint.dielectric{ iorr = 1.5 }
glint.sphere{ radius = 1, material = glass }
