-- ReSTIR in the viewer's preview: a square among houses at night, lit by 256 small lamps
-- (downward-facing panels) in four colours. Direct light comes from ReSTIR DI (two light-tree
-- candidates per pixel, the previous pass's reservoir reprojected, two neighbours'), the
-- light between the houses from one path-traced bounce. Compare:
--   build/glint render examples/restir-many-lights.lua
--   build/glint view examples/restir-many-lights.lua              (move the camera)
-- and the same with preview_restir = "off" (light-tree sampling alone) or "biased" (darker
-- at contact shadows; see docs/integrators.md).
local ground = glint.diffuse{ reflectance = {0.45, 0.45, 0.42} }
local walls = glint.diffuse{ reflectance = {0.6, 0.55, 0.5} }
local colours = {
    glint.emissive{ radiance = {60, 42, 18}, two_sided = false },  -- sodium
    glint.emissive{ radiance = {40, 45, 55}, two_sided = false },  -- cold white
    glint.emissive{ radiance = {55, 30, 35}, two_sided = false },  -- pink
    glint.emissive{ radiance = {30, 50, 35}, two_sided = false },  -- green
}

glint.camera{ eye = {-1.5, 6, -15}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "preview",
              preview_restir = "unbiased", preview_restir_candidates = 2,
              preview_restir_spatial = 2, preview_bounces = 1, preview_photons = 0,
              output = {"restir-many-lights.exr", "restir-many-lights.png"} }

glint.quad{ vertices = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}}, material = ground }

-- Blocks of houses between the streets, of heights that vary from block to block.
for i = -2, 2 do
    for j = -2, 2 do
        local h = 1.5 + ((i * 7 + j * 13) % 5) * 0.6
        local x, z = i * 4.0, j * 4.0
        glint.box{ min = {x - 1.2, 0, z - 1.2}, max = {x + 1.2, h, z + 1.2}, material = walls }
    end
end

-- Lamps: a 16 x 16 grid of 0.25 m panels facing down, 2.2 to 3.4 m up.
local count = 0
for i = 0, 15 do
    for j = 0, 15 do
        local x = -10 + i * (20 / 15)
        local z = -10 + j * (20 / 15)
        local y = 2.2 + ((i * 5 + j * 3) % 7) * 0.2
        local s = 0.125
        glint.quad{ vertices = {{x - s, y, z - s}, {x + s, y, z - s}, {x + s, y, z + s}, {x - s, y, z + s}},
                    material = colours[(i + j) % 4 + 1] }
        count = count + 1
    end
end

assert(count == 256)
