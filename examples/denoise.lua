-- The network denoiser (docs/denoiser.md): the Cornell box with a glass and a mirror sphere
-- (cornell-spheres.lua) at 8 samples per pixel, written noisy (denoise.exr, denoise.png) and
-- denoised by Open Image Denoise's trained network (denoise.denoised.exr, .png). Needs the
-- weights that scripts/install-deps.sh installs; `--denoise nlm` uses glint's own filter.
--   build/glint render examples/denoise.lua
local white = glint.diffuse{ reflectance = {0.725, 0.71, 0.68} }
local red   = glint.diffuse{ reflectance = {0.63, 0.065, 0.05} }
local green = glint.diffuse{ reflectance = {0.14, 0.45, 0.091} }
local light = glint.emissive{ radiance = {17, 12, 4}, two_sided = false }
local glass = glint.dielectric{ ior = 1.5 }
local mirror = glint.mirror{ tint = 0.95 }

glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 }
-- 8 samples per pixel, denoised by the network (denoise_quality: "fast", "balanced" or
-- "high"); the noisy image is written too, for comparison.
glint.render{ width = 512, height = 512, spp = 8, integrator = "path",
              denoise = true, denoise_quality = "balanced",
              output = {"denoise.exr", "denoise.png"} }

local function quad(material, a, b, c, d)
    glint.quad{ vertices = {a, b, c, d}, material = material }
end

-- The light, 0.1 mm under the ceiling, emitting towards -y.
quad(light, {343, 548.7, 227}, {343, 548.7, 332}, {213, 548.7, 332}, {213, 548.7, 227})

quad(white, {552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2})              -- floor
quad(white, {556, 548.8, 0}, {556, 548.8, 559.2}, {0, 548.8, 559.2}, {0, 548.8, 0})  -- ceiling
quad(white, {549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}) -- back wall
quad(green, {0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2})              -- right wall
quad(red, {552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0})    -- left wall

-- Mirror sphere at the back on the red side, glass sphere in front on the green side.
-- Each rests on the floor: centre height = radius.
glint.sphere{ center = {370, 100, 370}, radius = 100, material = mirror }
glint.sphere{ center = {185, 100, 170}, radius = 100, material = glass }
