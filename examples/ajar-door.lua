-- A room lit through a door left ajar (after Veach's classic test scene for Metropolis light
-- transport): the only lamp is in a small room next door and faces away from the door, so
-- all the light in the big room has bounced at least twice and entered through a slit a
-- hand wide. Path tracing finds the slit by chance and is noisy everywhere; `mlt` finds it
-- once and explores around it. Units are metres; y is up.
--   glint render examples/ajar-door.lua                      (mlt, a few seconds)
--   glint render examples/ajar-door.lua --integrator path    (the same image, noisier)
local wall  = glint.diffuse{ reflectance = {0.78, 0.76, 0.72} }
local floor = glint.diffuse{ reflectance = {0.45, 0.33, 0.22} }
local door  = glint.diffuse{ reflectance = {0.65, 0.62, 0.55} }
local blue  = glint.diffuse{ reflectance = {0.2, 0.3, 0.6} }
local lamp  = glint.emissive{ radiance = {150, 130, 100}, two_sided = false }

glint.camera{ eye = {-1.5, 1.5, 1.8}, look_at = {0.5, 0.9, -2}, up = {0, 1, 0}, fov = 62 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "mlt", max_depth = 12,
              output = {"ajar-door.exr", "ajar-door.png"} }

local function quad(material, a, b, c, d)
    glint.quad{ vertices = {a, b, c, d}, material = material }
end

-- The big room: x in [-2, 2], z in [-2, 2], 2.6 high.
quad(floor, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2})
quad(wall, {-2, 2.6, -2}, {2, 2.6, -2}, {2, 2.6, 2}, {-2, 2.6, 2})
quad(wall, {-2, 0, -2}, {-2, 2.6, -2}, {-2, 2.6, 2}, {-2, 0, 2})   -- left
quad(wall, {2, 0, -2}, {2, 0, 2}, {2, 2.6, 2}, {2, 2.6, -2})       -- right
quad(wall, {-2, 0, 2}, {-2, 2.6, 2}, {2, 2.6, 2}, {2, 0, 2})       -- behind the camera

-- The wall between the rooms (z = -2) with a doorway for x in [0.2, 1.1], 2.1 high.
quad(wall, {-2, 0, -2}, {0.2, 0, -2}, {0.2, 2.6, -2}, {-2, 2.6, -2})
quad(wall, {1.1, 0, -2}, {2, 0, -2}, {2, 2.6, -2}, {1.1, 2.6, -2})
quad(wall, {0.2, 2.1, -2}, {1.1, 2.1, -2}, {1.1, 2.6, -2}, {0.2, 2.6, -2})

-- The small room behind: x in [-0.6, 1.8], z in [-3.6, -2].
quad(floor, {-0.6, 0, -3.6}, {-0.6, 0, -2}, {1.8, 0, -2}, {1.8, 0, -3.6})
quad(wall, {-0.6, 2.6, -3.6}, {1.8, 2.6, -3.6}, {1.8, 2.6, -2}, {-0.6, 2.6, -2})
quad(wall, {-0.6, 0, -3.6}, {1.8, 0, -3.6}, {1.8, 2.6, -3.6}, {-0.6, 2.6, -3.6})
quad(wall, {-0.6, 0, -3.6}, {-0.6, 0, -2}, {-0.6, 2.6, -2}, {-0.6, 2.6, -3.6})
quad(wall, {1.8, 0, -3.6}, {1.8, 2.6, -3.6}, {1.8, 2.6, -2}, {1.8, 0, -2})

-- The door, hinged at x = 1.1 and opened 10 degrees into the small room: its free edge
-- leaves a slit of about 0.15 m at the frame (x = 0.2).
glint.box{ min = {-0.9, 0, -0.04}, max = {0, 2.1, 0}, material = door,
           transform = glint.translate(1.1, 0, -2) * glint.rotate(-10, {0, 1, 0}) }

-- The lamp: a panel in the small room that shines only towards the far wall.
quad(lamp, {1.3, 0.8, -3.2}, {0.1, 0.8, -3.2}, {0.1, 2.0, -3.2}, {1.3, 2.0, -3.2})

-- Something to look at in the big room.
glint.box{ min = {-0.4, 0, -0.4}, max = {0.4, 0.75, 0.4}, material = wall,
           transform = glint.translate(-0.6, 0, -0.6) * glint.rotate(25, {0, 1, 0}) }
glint.sphere{ center = {0.9, 0.45, -0.3}, radius = 0.45, material = blue }
