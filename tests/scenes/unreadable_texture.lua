glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0} }
glint.render{ width = 8, height = 8, spp = 1 }

-- A file that exists but is no image.
local bad = glint.texture.image{ file = "triangle.obj" }
glint.sphere{ material = glint.diffuse{ reflectance = bad } }
