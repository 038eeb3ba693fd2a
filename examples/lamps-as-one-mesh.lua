-- The streets of many-lights.lua, with their 1,024 lamps made as one would export them from
-- a modelling tool: one emissive mesh per lamp colour (four meshes of 512 triangles),
-- not 1,024 separate quads. The light tree (light_sampler = "tree", the default) still
-- chooses among single triangles, so each shadow ray goes to a lamp near the point. With
-- light_sampler = "power" a mesh is chosen by its power and a triangle on it by area:
-- as good as choosing among all lamps by power alone, which is poor here.
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
              output = {"lamps-as-one-mesh.exr", "lamps-as-one-mesh.png"} }

glint.quad{ vertices = {{-40, 0, -40}, {-40, 0, 40}, {40, 0, 40}, {40, 0, -40}}, material = ground }

for i = -3, 3 do
    for j = -3, 3 do
        local h = 1.5 + ((i * 7 + j * 13) % 5) * 0.6
        local x, z = i * 5.0, j * 5.0
        glint.box{ min = {x - 1.6, 0, z - 1.6}, max = {x + 1.6, h, z + 1.6}, material = walls }
    end
end

-- The lamps: a 32 x 32 grid of 0.25 m panels facing down, 2.2 to 3.4 m up, gathered by
-- colour into four meshes.
local meshes = {}
for c = 1, 4 do meshes[c] = { vertices = {}, indices = {} } end
for i = 0, 31 do
    for j = 0, 31 do
        local x = -17.5 + i * (35 / 31)
        local z = -17.5 + j * (35 / 31)
        local y = 2.2 + ((i * 5 + j * 3) % 7) * 0.2
        local s = 0.125
        local m = meshes[(i + j) % 4 + 1]
        local first = #m.vertices
        for _, v in ipairs({{x - s, y, z - s}, {x + s, y, z - s}, {x + s, y, z + s}, {x - s, y, z + s}}) do
            m.vertices[#m.vertices + 1] = v
        end
        -- Two triangles wound so that the panel faces down (as the quads of many-lights.lua).
        for _, k in ipairs({1, 2, 3, 1, 3, 4}) do m.indices[#m.indices + 1] = first + k end
    end
end
for c = 1, 4 do
    assert(#meshes[c].indices == 3 * 512)
    glint.mesh{ vertices = meshes[c].vertices, indices = meshes[c].indices, material = colours[c] }
end
