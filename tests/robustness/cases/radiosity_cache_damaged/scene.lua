-- A radiosity cache that is no cache: refused with the file named, before any output.
glint.render{ integrator = "radiosity", radiosity_cache = "junk.rad" }
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.quad{ vertices = { {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0} },
            material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 0, 2}, intensity = 5 }
