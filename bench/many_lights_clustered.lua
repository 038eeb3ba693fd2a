-- Many lights, clustered (bench, issue 31): the streets of examples/many-lights.lua, lit
-- instead by 24 clusters of 40 small panels each (960), of brightness varying 1:50, facing
-- down or sideways, the clusters of different sizes. Unlike the example's regular grid, the
-- light tree's split choice matters here: bench/README.md, "Tree build".
local ground = glint.diffuse{ reflectance = {0.45, 0.45, 0.42} }
local walls = glint.diffuse{ reflectance = {0.6, 0.55, 0.5} }

glint.camera{ eye = {-2, 9, -26}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "path", max_depth = 4,
              output = {"many-lights-clustered.exr"} }

glint.quad{ vertices = {{-40, 0, -40}, {-40, 0, 40}, {40, 0, 40}, {40, 0, -40}}, material = ground }

-- Blocks of houses between the streets, of heights that vary from block to block.
for i = -3, 3 do
    for j = -3, 3 do
        local h = 1.5 + ((i * 7 + j * 13) % 5) * 0.6
        local x, z = i * 5.0, j * 5.0
        glint.box{ min = {x - 1.6, 0, z - 1.6}, max = {x + 1.6, h, z + 1.6}, material = walls }
    end
end

-- Lamps: clusters of panels of brightness varying 1:50, facing down or sideways, placed
-- by a small linear congruential generator so that every run builds the same scene.
local rng_state = 12345
local function rnd()
    rng_state = (rng_state * 1103515245 + 12345) % 2147483648
    return rng_state / 2147483648
end
local mats = {}
for k = 1, 8 do
    local b = 0.5 * 50 ^ ((k - 1) / 7)
    mats[k] = glint.emissive{ radiance = {b * 30, b * 25, b * 20}, two_sided = false }
end
for c = 1, 24 do
    local cx, cz = rnd() * 36 - 18, rnd() * 36 - 18
    local spread = 0.5 + 4 * rnd() ^ 2
    for k = 1, 40 do
        local x = cx + (rnd() - 0.5) * spread
        local z = cz + (rnd() - 0.5) * spread
        local y = 1.0 + rnd() * 4.0
        local s = 0.06 + 0.12 * rnd()
        local m = mats[math.floor(rnd() * 8) + 1]
        if rnd() < 0.7 then
            glint.quad{ vertices = {{x - s, y, z - s}, {x + s, y, z - s}, {x + s, y, z + s}, {x - s, y, z + s}}, material = m }
        else
            glint.quad{ vertices = {{x, y - s, z - s}, {x, y - s, z + s}, {x, y + s, z + s}, {x, y + s, z - s}}, material = m }
        end
    end
end
