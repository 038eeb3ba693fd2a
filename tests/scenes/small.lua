-- A small valid scene used by the CLI tests: instancing, a mesh from OBJ, lights.
local white = glint.diffuse{ reflectance = 0.7 }
local lamp = glint.emissive{ radiance = {4, 4, 4}, two_sided = true }
glint.camera{ eye = {0, 2, 8}, look_at = {0, 0.5, 0}, fov = 40 }
glint.render{ width = 32, height = 24, spp = 4, output = "small.exr" }
glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}}, material = white }
local post = glint.group()
post:box{ min = {-0.2, 0, -0.2}, max = {0.2, 1, 0.2}, material = white }
post:sphere{ center = {0, 1.2, 0}, radius = 0.2, material = lamp }
for i = 0, 2 do
    glint.place(post, glint.translate(i * 1.5 - 1.5, 0, 0) * glint.rotate(30 * i, {0, 1, 0}))
end
glint.mesh{ file = "triangle.obj", material = white, transform = glint.translate(0, 0, -1) }
glint.point_light{ position = {0, 5, 0}, intensity = 10 }
