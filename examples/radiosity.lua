-- Radiosity: a diffuse room solved once, independently of the view (integrator
-- "radiosity"), then looked at through the camera with the vertex radiosities interpolated
-- (Gouraud). A ceiling panel and a spot light on the back wall light it; the colour bleeding
-- from the red and blue walls onto the white ones is the interreflection the solve finds.
-- Try radiosity_cache = "room.rad" to solve once and move the camera between renders, and
-- hybrid = true for the two-pass method (exact direct light and soft shadows).
local white = glint.diffuse{ reflectance = 0.75 }
local red   = glint.diffuse{ reflectance = {0.7, 0.12, 0.1} }
local blue  = glint.diffuse{ reflectance = {0.12, 0.2, 0.65} }
local wood  = glint.diffuse{ reflectance = {0.55, 0.38, 0.22} }
local panel = glint.emissive{ radiance = 6 }

glint.camera{ eye = {0.3, 1.5, 4.6}, look_at = {0, 1.0, 0}, up = {0, 1, 0}, fov = 62 }
glint.render{ width = 320, height = 240, spp = 4, integrator = "radiosity",
              radiosity_patch_size = 1.5, radiosity_unshot = 0.05, radiosity_samples = 4,
              output = {"radiosity.exr", "radiosity.png"} }

local function quad(material, a, b, c, d)
    glint.quad{ vertices = {a, b, c, d}, material = material }
end

-- A room 4 m wide, 3 m high and 5 m deep, every wall facing in.
quad(white, {-2, 0, 0}, {2, 0, 0}, {2, 0, 5}, {-2, 0, 5})          -- floor
quad(white, {-2, 3, 0}, {-2, 3, 5}, {2, 3, 5}, {2, 3, 0})          -- ceiling
quad(white, {-2, 0, 0}, {-2, 3, 0}, {2, 3, 0}, {2, 0, 0})          -- back wall
quad(red,   {-2, 0, 5}, {-2, 3, 5}, {-2, 3, 0}, {-2, 0, 0})        -- left wall
quad(blue,  {2, 0, 0}, {2, 3, 0}, {2, 3, 5}, {2, 0, 5})            -- right wall
quad(white, {2, 0, 5}, {2, 3, 5}, {-2, 3, 5}, {-2, 0, 5})          -- front wall (behind the camera)

-- The ceiling panel, 1 cm below the ceiling, facing down.
quad(panel, {-0.5, 2.99, 1.5}, {0.5, 2.99, 1.5}, {0.5, 2.99, 2.5}, {-0.5, 2.99, 2.5})

-- A spot light high on the back wall, aimed at the floor.
glint.spot_light{ position = {1.2, 2.6, 0.3}, look_at = {0.8, 0, 1.5}, intensity = 8,
                  cone_angle = 35, falloff_start = 25 }

-- A table and two blocks.
glint.box{ min = {-1.2, 0.7, 1.2}, max = {0.2, 0.75, 2.2}, material = wood }
glint.box{ min = {-1.15, 0, 1.25}, max = {-1.05, 0.7, 1.35}, material = wood }
glint.box{ min = {0.05, 0, 1.25}, max = {0.15, 0.7, 1.35}, material = wood }
glint.box{ min = {-1.15, 0, 2.05}, max = {-1.05, 0.7, 2.15}, material = wood }
glint.box{ min = {0.05, 0, 2.05}, max = {0.15, 0.7, 2.15}, material = wood }
glint.box{ min = {0.8, 0, 0.6}, max = {1.5, 1.2, 1.3}, material = white }
glint.box{ min = {-1.7, 0, 3.4}, max = {-1.1, 0.5, 4.0}, material = red }
