-- Emissive meshes: a hexagonal ceiling lamp (six triangles: each sampled uniformly in the
-- solid angle it subtends, Arvo's spherical triangles) and a neon ring on the back wall
-- (a flat band of 96 triangles: sampled by area), over a table with a sphere on it.
local white = glint.diffuse{ reflectance = {0.7, 0.7, 0.68} }
local wood = glint.diffuse{ reflectance = {0.45, 0.3, 0.18} }
local blue = glint.diffuse{ reflectance = {0.15, 0.25, 0.6} }
local lamp = glint.emissive{ radiance = {14, 12, 9}, two_sided = false }
local neon = glint.emissive{ radiance = {2, 6, 12}, two_sided = false }

glint.camera{ eye = {0, 1.6, 4.2}, look_at = {0, 1.1, 0}, up = {0, 1, 0}, fov = 55 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "path",
              output = {"emissive-mesh.exr", "emissive-mesh.png"} }

-- The room: floor, ceiling, back and side walls.
glint.quad{ vertices = {{-3, 0, -2}, {-3, 0, 5}, {3, 0, 5}, {3, 0, -2}}, material = white }
glint.quad{ vertices = {{-3, 3, -2}, {3, 3, -2}, {3, 3, 5}, {-3, 3, 5}}, material = white }
glint.quad{ vertices = {{-3, 0, -2}, {3, 0, -2}, {3, 3, -2}, {-3, 3, -2}}, material = white }
glint.quad{ vertices = {{-3, 0, 5}, {-3, 0, -2}, {-3, 3, -2}, {-3, 3, 5}}, material = white }
glint.quad{ vertices = {{3, 0, -2}, {3, 0, 5}, {3, 3, 5}, {3, 3, -2}}, material = white }

glint.box{ min = {-0.8, 0, -0.2}, max = {0.8, 0.75, 0.8}, material = wood }
glint.sphere{ center = {0.2, 1.0, 0.3}, radius = 0.25, material = blue }

-- The lamp: a hexagon of six triangles round its centre, 2.9 m up, facing down.
local vertices, indices = {{0, 2.9, 0.6}}, {}
for k = 0, 5 do
    local a = k * math.pi / 3
    vertices[#vertices + 1] = {0.4 * math.cos(a), 2.9, 0.6 + 0.4 * math.sin(a)}
end
for k = 0, 5 do
    indices[#indices + 1] = 1
    indices[#indices + 1] = 2 + k
    indices[#indices + 1] = 2 + (k + 1) % 6
end
glint.mesh{ vertices = vertices, indices = indices, material = lamp }

-- The neon ring: a flat band 2 cm wide, radius 0.6 m, 1 cm in front of the back wall.
vertices, indices = {}, {}
local segments = 48
for k = 0, segments - 1 do
    local a = 2 * math.pi * k / segments
    local c, s = math.cos(a), math.sin(a)
    vertices[#vertices + 1] = {0.59 * c, 1.9 + 0.59 * s, -1.99}
    vertices[#vertices + 1] = {0.61 * c, 1.9 + 0.61 * s, -1.99}
end
for k = 0, segments - 1 do
    local i0, o0 = 2 * k + 1, 2 * k + 2
    local i1, o1 = 2 * ((k + 1) % segments) + 1, 2 * ((k + 1) % segments) + 2
    for _, v in ipairs({i0, o0, o1, i0, o1, i1}) do indices[#indices + 1] = v end
end
glint.mesh{ vertices = vertices, indices = indices, material = neon }
