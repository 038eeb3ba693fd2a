-- expect-exit: 2
-- expect-message: --denoise: the denoiser needs an integrator that renders pixel by pixel
-- args: --integrator light --denoise --spp 4
-- Issue 28: a refused --denoise combination is a usage error, exit 2.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
