glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
local checker = glint.texture.image{ file = "checker.png" }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = checker } }
