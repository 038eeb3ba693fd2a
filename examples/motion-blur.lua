-- Motion blur: a ball rolls across, another bounces (three keys), a pinwheel of boxes
-- spins a quarter turn and a flag waves (a mesh with vertex keys: deformation blur), all
-- while the shutter is open. Each camera sample draws a
-- time in the shutter; the keys of a moving object are spread evenly over the times
-- [0, 1] (translation and scale interpolated linearly, rotation by slerp). The floor and
-- the lights stand still; the shadows blur with the objects. Units are metres.
local floor_white = glint.diffuse{ reflectance = 0.6 }
local red         = glint.diffuse{ reflectance = {0.8, 0.15, 0.1} }
local blue        = glint.plastic{ diffuse = {0.1, 0.25, 0.8}, ior = 1.5 }
local yellow      = glint.diffuse{ reflectance = {0.9, 0.7, 0.15} }

glint.camera{ eye = {0, 2.2, -6.5}, look_at = {0, 0.6, 0}, fov = 40, shutter = {0, 1} }
glint.render{ width = 320, height = 200, spp = 32, output = {"motion-blur.exr", "motion-blur.png"} }
glint.background{ radiance = {0.08, 0.1, 0.14} }
glint.point_light{ position = {2, 6, -3}, intensity = 60 }

glint.quad{ vertices = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}},
            material = floor_white }

-- Rolling from left to right (a turn about z as it goes, which the blur of a plain ball
-- cannot show, but the keys carry it).
glint.sphere{ center = {0, 0.4, 0}, radius = 0.4, material = red,
              motion = { glint.translate(-2.2, 0, -1),
                         glint.translate(-0.6, 0, -1) * glint.rotate(-230, {0, 0, 1}) } }

-- Bouncing: down, then up again.
glint.sphere{ center = {0, 0, 0}, radius = 0.3, material = blue,
              motion = { glint.translate(1.4, 1.6, -1.2), glint.translate(1.6, 0.3, -1.2),
                         glint.translate(1.8, 1.2, -1.2) } }

-- A pinwheel of four boxes, a group turning about its hub by a quarter turn.
local pinwheel = glint.group()
for i = 0, 3 do
    pinwheel:box{ min = {0.1, -0.08, -0.06}, max = {0.9, 0.08, 0.06}, material = yellow,
                  transform = glint.rotate(90 * i, {0, 0, 1}) }
end
glint.place(pinwheel, { glint.translate(0.3, 1.3, 1.2),
                        glint.translate(0.3, 1.3, 1.2) * glint.rotate(45, {0, 0, 1}),
                        glint.translate(0.3, 1.3, 1.2) * glint.rotate(90, {0, 0, 1}) })

-- A flag on a pole, waving: a 12 x 6 grid whose vertices move with a travelling wave,
-- given at five times (vertex_keys: the flag at times 1/4, 1/2, 3/4 and 1; `vertices` is
-- the flag at time 0).
local cloth = glint.diffuse{ reflectance = {0.2, 0.6, 0.3} }
local columns, rows = 12, 6
local function flag_at(time)
    local points = {}
    for j = 0, rows do
        for i = 0, columns do
            local u = i / columns
            local x = -2.6 + 1.2 * u
            local z = 1.6 + 0.35 * u * math.sin(2 * math.pi * (1.5 * u - time))
            points[#points + 1] = {x, 1.2 + 0.6 * j / rows, z}
        end
    end
    return points
end
local indices = {}
for j = 0, rows - 1 do
    for i = 0, columns - 1 do
        local a = j * (columns + 1) + i + 1
        local b, c, d = a + 1, a + columns + 2, a + columns + 1
        for _, k in ipairs({a, b, c, a, c, d}) do indices[#indices + 1] = k end
    end
end
local keys = {}
for k = 1, 4 do
    local flat = {}
    for _, p in ipairs(flag_at(0.25 * k)) do
        flat[#flat + 1] = p[1]; flat[#flat + 1] = p[2]; flat[#flat + 1] = p[3]
    end
    keys[k] = flat
end
glint.mesh{ vertices = flag_at(0), indices = indices, vertex_keys = keys, material = cloth }
glint.box{ min = {-2.66, 0, 1.54}, max = {-2.58, 1.85, 1.62}, material = floor_white }
