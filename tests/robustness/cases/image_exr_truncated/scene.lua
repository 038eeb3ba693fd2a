glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
local tex = glint.texture.image{ file = "tex.exr" }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = tex } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
