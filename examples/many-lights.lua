-- Many lights: a square of streets at night, lit by 1,024 small lamps (downward-facing
-- panels) in four colours, among blocks of houses.
-- Most lamps are far from any given point or face away from it: the light tree
-- (light_sampler = "tree", the default) sends each shadow ray to a lamp that matters there.
-- Render with light_sampler = "power" to see what choosing lamps by power alone costs.
local ground = glint.diffuse{ reflectance = {0.45, 0.45, 0.42} }
local walls = glint.diffuse{ reflectance = {0.6, 0.55, 0.5} }
local colours = {
    glint.emissive{ radiance = {60, 42, 18}, two_sided = false },  -- sodium
    glint.emissive{ radiance = {40, 45, 55}, two_sided = false },  -- cold white
    glint.emissive{ radiance = {55, 30, 35}, two_sided = false },  -- pink
    glint.emissive{ radiance = {30, 50, 35}, two_sided = false },  -- green
}

glint.camera{ eye = {-2, 9, -26}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "path", max_depth = 4,
              output = {"many-lights.exr", "many-lights.png"} }

glint.quad{ vertices = {{-40, 0, -40}, {-40, 0, 40}, {40, 0, 40}, {40, 0, -40}}, material = ground }

-- Blocks of houses between the streets, of heights that vary from block to block.
for i = -3, 3 do
    for j = -3, 3 do
        local h = 1.5 + ((i * 7 + j * 13) % 5) * 0.6
        local x, z = i * 5.0, j * 5.0
        glint.box{ min = {x - 1.6, 0, z - 1.6}, max = {x + 1.6, h, z + 1.6}, material = walls }
    end
end

-- Lamps: a 32 x 32 grid of 0.25 m panels facing down, 2.2 to 3.4 m up.
local count = 0
for i = 0, 31 do
    for j = 0, 31 do
        local x = -17.5 + i * (35 / 31)
        local z = -17.5 + j * (35 / 31)
        local y = 2.2 + ((i * 5 + j * 3) % 7) * 0.2
        local s = 0.125
        glint.quad{ vertices = {{x - s, y, z - s}, {x + s, y, z - s}, {x + s, y, z + s}, {x - s, y, z + s}},
                    material = colours[(i + j) % 4 + 1] }
        count = count + 1
    end
end

assert(count == 1024)
