-- expect-exit: 1
-- expect-message: radiosity_samples_zero.lua:4:
-- expect-message: 'radiosity_samples' must be in [1, 4096]
glint.render{ integrator = "radiosity", radiosity_samples = 0 }
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.quad{ vertices = { {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0} },
            material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 0, 2}, intensity = 5 }
