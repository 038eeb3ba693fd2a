-- expect-exit: 1
-- expect-message: scene_denoise_splatting.lua:7:
-- expect-message: the denoiser needs an integrator that renders pixel by pixel
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ width = 8, height = 8, spp = 4, integrator = "light", denoise = true }
