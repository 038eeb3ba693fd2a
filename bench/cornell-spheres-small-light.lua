-- examples/cornell-spheres.lua with a small light: a quarter of the side (32.5 x 26.25 mm
-- instead of 130 x 105) and 16 times the radiance, so the same power. Its caustic under
-- the glass sphere is sharper, and a camera path finds the light through the glass 16 times
-- less often: the case the bidirectional methods are for (bench/bidirectional.sh).
local white = glint.diffuse{ reflectance = {0.725, 0.71, 0.68} }
local red   = glint.diffuse{ reflectance = {0.63, 0.065, 0.05} }
local green = glint.diffuse{ reflectance = {0.14, 0.45, 0.091} }
local light = glint.emissive{ radiance = {272, 192, 64}, two_sided = false }
local glass = glint.dielectric{ ior = 1.5 }
local mirror = glint.mirror{ tint = 0.95 }

glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 }
glint.render{ width = 512, height = 512, spp = 64, integrator = "bdpt",
              output = {"cornell-spheres-small-light.exr"} }

local function quad(material, a, b, c, d)
    glint.quad{ vertices = {a, b, c, d}, material = material }
end

-- The light, centred where the example's is (x 278, z 279.5), 0.1 mm under the ceiling.
quad(light, {294.25, 548.7, 266.375}, {294.25, 548.7, 292.625},
     {261.75, 548.7, 292.625}, {261.75, 548.7, 266.375})

quad(white, {552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2})              -- floor
quad(white, {556, 548.8, 0}, {556, 548.8, 559.2}, {0, 548.8, 559.2}, {0, 548.8, 0})  -- ceiling
quad(white, {549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}) -- back wall
quad(green, {0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2})              -- right wall
quad(red, {552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0})    -- left wall

glint.sphere{ center = {370, 100, 370}, radius = 100, material = mirror }
glint.sphere{ center = {185, 100, 170}, radius = 100, material = glass }
