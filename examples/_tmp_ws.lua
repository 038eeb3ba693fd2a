-- The Cornell box, exactly as measured (shared/scenes/cornell-box.md): Lambertian walls
-- and blocks, one quad light facing down. Units are millimetres.
local white = glint.diffuse{ reflectance = {0.725, 0.71, 0.68} }
local red   = glint.diffuse{ reflectance = {0.63, 0.065, 0.05} }
local green = glint.diffuse{ reflectance = {0.14, 0.45, 0.091} }
local light = glint.emissive{ radiance = {17, 12, 4}, two_sided = false }

glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 }
glint.render{ wavelength_sets = 4, hybrid = true, caustic_photons = 0,  width = 512, height = 512, spp = 64, integrator = "path",
              output = {"cornell-box.exr", "cornell-box.png"} }

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

-- Short block.
quad(white, {130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114})
quad(white, {290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272})
quad(white, {130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114})
quad(white, {82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65})
quad(white, {240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225})

-- Tall block.
quad(white, {423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406})
quad(white, {423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406})
quad(white, {472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456})
quad(white, {314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296})
quad(white, {265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247})
