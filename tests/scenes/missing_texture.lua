glint.camera{ eye = {0, 0, 5}, look_at = {0, 0, 0} }
glint.render{ width = 8, height = 8, spp = 1 }

local wood = glint.texture.image{ file = "textures/does-not-exist.png", scale = 4 }
glint.sphere{ material = glint.diffuse{ reflectance = wood } }
