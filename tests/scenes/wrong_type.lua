glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0} }
glint.render{ width = 8, height = 8, spp = 1 }
local white = glint.diffuse{ reflectance = 0.5 }
glint.sphere{ center = {0, 0, 0}, radius = "large", material = white }
