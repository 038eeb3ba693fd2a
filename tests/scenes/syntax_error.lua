-- A syntax error on line 3.
local white = glint.diffuse{ reflectance = 0.5 }
glint.sphere{ center = {0, 0, 0} radius = 1, material = white }
