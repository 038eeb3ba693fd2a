-- Constructive solid geometry. Back row: two overlapping spheres combined as a union, an
-- intersection (a lens) and a difference (the red sphere with a bite taken by the blue
-- one); each part keeps its own colour, so the cut faces show which solid made them.
-- Front row: a cube and a sphere as an intersection and a difference, and a die: a cube
-- rounded by intersecting it with a larger sphere, with spherical pips subtracted by a Lua
-- loop. Lit by a square area light above. Units are arbitrary.
local red    = glint.diffuse{ reflectance = {0.75, 0.12, 0.1} }
local blue   = glint.diffuse{ reflectance = {0.1, 0.25, 0.75} }
local gold   = glint.diffuse{ reflectance = {0.8, 0.55, 0.15} }
local green  = glint.diffuse{ reflectance = {0.15, 0.55, 0.2} }
local ivory  = glint.diffuse{ reflectance = {0.85, 0.82, 0.72} }
local ink    = glint.diffuse{ reflectance = 0.03 }
local floor  = glint.diffuse{ reflectance = 0.5 }

glint.camera{ eye = {0, 8.5, 12}, look_at = {0, 0.7, 0.2}, fov = 38 }
glint.render{ width = 640, height = 400, spp = 32, output = {"csg.exr", "csg.png"} }
glint.background{ radiance = 0.08 }

glint.quad{ vertices = {{-30, 0, -30}, {-30, 0, 30}, {30, 0, 30}, {30, 0, -30}}, material = floor }
glint.quad{ vertices = {{-2, 9, -2}, {2, 9, -2}, {2, 9, 2}, {-2, 9, 2}},
            material = glint.emissive{ radiance = 14 } }

-- Two unit spheres 1.1 apart, standing on the floor at (x, z).
local function two_spheres(x, z)
    return glint.solid.sphere{ center = {x - 0.55, 1, z}, radius = 1, material = red },
           glint.solid.sphere{ center = {x + 0.55, 1, z}, radius = 1, material = blue }
end
glint.add(glint.union{ two_spheres(-4.2, -2) })
glint.add(glint.intersection{ two_spheres(0, -2) })
-- Turned so that the bite faces the camera. (Settings go first: Lua passes on all the
-- values of a call like two_spheres() only when it comes last in a table.)
glint.add(glint.difference{
    transform = glint.translate(4.2, 0, -2) * glint.rotate(-70, {0, 1, 0}),
    two_spheres(0, 0) })

-- A cube of side 2 standing on the floor and a sphere of radius 1.3 around its centre.
local function cube_and_sphere()
    return glint.solid.box{ min = {-1, 0, -1}, max = {1, 2, 1}, material = gold },
           glint.solid.sphere{ center = {0, 1, 0}, radius = 1.3, material = green }
end
glint.add(glint.intersection{ transform = glint.translate(-4.2, 0, 2.2) *
                                          glint.rotate(-20, {0, 1, 0}),
                              cube_and_sphere() })
glint.add(glint.difference{ transform = glint.translate(0, 0, 2.2) * glint.rotate(30, {0, 1, 0}),
                            cube_and_sphere() })

-- The die: a cube of side 2 centred on the origin, rounded by a sphere of radius 1.5,
-- minus its pips. Each face's pips sit on a 3x3 grid in the face's own (u, v) axes;
-- opposite faces add up to seven.
local grid = {
    [1] = {{0, 0}},
    [2] = {{-1, -1}, {1, 1}},
    [3] = {{-1, -1}, {0, 0}, {1, 1}},
    [4] = {{-1, -1}, {-1, 1}, {1, -1}, {1, 1}},
    [5] = {{-1, -1}, {-1, 1}, {0, 0}, {1, -1}, {1, 1}},
    [6] = {{-1, -1}, {-1, 0}, {-1, 1}, {1, -1}, {1, 0}, {1, 1}},
}
-- For each face: the count, its outward normal and two axes in its plane.
local faces = {
    {1, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}},
    {6, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    {2, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    {5, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    {3, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
    {4, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
}
local die = {
    glint.intersection{ glint.solid.box{ min = {-1, -1, -1}, max = {1, 1, 1} },
                        glint.solid.sphere{ radius = 1.5 } },
    material = ivory,
}
-- Pip centres lie `depth` from the die's centre, `spacing` apart, just inside the faces.
local spacing, pip_radius, depth = 0.5, 0.2, 0.9
for _, face in ipairs(faces) do
    local count, n, u, v = face[1], face[2], face[3], face[4]
    for _, uv in ipairs(grid[count]) do
        local c = {}
        for k = 1, 3 do c[k] = depth * n[k] + spacing * (uv[1] * u[k] + uv[2] * v[k]) end
        die[#die + 1] = glint.solid.sphere{ center = c, radius = pip_radius, material = ink }
    end
end
die.transform = glint.translate(4.2, 1.0, 2.2) * glint.rotate(35, {0, 1, 0}) *
                glint.rotate(-12, {1, 0, 1})
glint.add(glint.difference(die))
