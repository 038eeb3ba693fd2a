-- The Cornell box (the geometry of cornell-box.lua, without its two blocks) with a glass
-- sphere and a mirror sphere standing on the floor. The glass focuses the light into a
-- caustic on the floor; the mirror shows the room, light and glass sphere included.
-- Units are millimetres; the camera looks along +z, so +x (the red wall) is on the left.
local white = glint.diffuse{ reflectance = {0.725, 0.71, 0.68} }
local red   = glint.diffuse{ reflectance = {0.63, 0.065, 0.05} }
local green = glint.diffuse{ reflectance = {0.14, 0.45, 0.091} }
local light = glint.emissive{ radiance = {17, 12, 4}, two_sided = false }
local glass = glint.dielectric{ ior = 1.5 }
local mirror = glint.mirror{ tint = 0.95 }

glint.camera{ eye = {278, 273, -800}, look_at = {278, 273, 0}, up = {0, 1, 0}, fov = 39.3077 }
glint.render{ width = 512, height = 512, spp = 64, integrator = "path",
              output = {"cornell-spheres.exr", "cornell-spheres.png"} }

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
