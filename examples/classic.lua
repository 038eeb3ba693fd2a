-- Classic ray tracing (integrator "whitted"): Phong spheres, a mirror sphere and a
-- standing mirror, a ball of tinted glass, on a checkered floor. A square area light gives
-- soft shadows, a point light hard ones, and an ambient term lifts what neither reaches.
-- The thin-lens camera focuses on the glass ball in the middle: the red ball in front and
-- the spheres at the back are blurred. Units are metres; +x is on the image's left.
--   build/glint render examples/classic.lua
--   build/glint render examples/classic.lua --adaptive sobel --debug edges
local light_tile = glint.diffuse{ reflectance = 0.7 }
local dark_tile  = glint.diffuse{ reflectance = {0.08, 0.09, 0.12} }
local red        = glint.phong{ diffuse = {0.65, 0.07, 0.05}, specular = 0.3, exponent = 60 }
local blue       = glint.phong{ diffuse = {0.06, 0.16, 0.55}, specular = 0.4, exponent = 250 }
local green      = glint.phong{ diffuse = {0.12, 0.45, 0.1}, specular = 0.15, exponent = 20 }
local chrome     = glint.mirror{ tint = 0.9 }
-- Amber glass: through the 1.2 m ball, exp(-1.2 * sigma) keeps 89 % of red, 34 % of green
-- and 12 % of blue; thinner near the rim, so paler there.
local amber      = glint.dielectric{ ior = 1.5, absorption = {0.1, 0.9, 1.8} }
local lamp       = glint.emissive{ radiance = 16 }

-- Focus on the glass ball: the focus distance is measured along the view direction, and
-- the camera looks straight at the ball's centre.
local eye, ball = {0, 1.8, -6.5}, {0, 0.6, 0}
local to_ball = math.sqrt((ball[1] - eye[1]) ^ 2 + (ball[2] - eye[2]) ^ 2 + (ball[3] - eye[3]) ^ 2)
glint.camera{ eye = eye, look_at = ball, fov = 36, aperture = 0.08, focus_distance = to_ball }
glint.render{ width = 640, height = 400, spp = 16, integrator = "whitted", max_depth = 8,
              ambient = 0.04, shadow_samples = 3,
              output = {"classic.exr", "classic.png"} }
glint.background{ radiance = {0.12, 0.16, 0.24} }

-- A 14 x 22 checkerboard of 1 m tiles, each a quad facing up; it reaches behind the camera
-- so that the standing mirror shows floor, not sky.
for i = -7, 6 do
    for j = -12, 9 do
        local x, z = i, j
        glint.quad{ vertices = {{x, 0, z}, {x, 0, z + 1}, {x + 1, 0, z + 1}, {x + 1, 0, z}},
                    material = (i + j) % 2 == 0 and light_tile or dark_tile }
    end
end

-- The area light, 1.5 m square, 4.5 m up and to the left, facing down.
glint.quad{ vertices = {{1.75, 4.5, -2.25}, {3.25, 4.5, -2.25}, {3.25, 4.5, -0.75}, {1.75, 4.5, -0.75}},
            material = lamp }
-- A warm point light from the right, behind the camera's line.
glint.point_light{ position = {-4, 3, -3}, intensity = {16, 13, 10} }

glint.sphere{ center = ball, radius = 0.6, material = amber }
glint.sphere{ center = {1.3, 0.45, -1.6}, radius = 0.45, material = red }        -- in front, blurred
glint.sphere{ center = {-1.5, 0.7, 1.2}, radius = 0.7, material = chrome }
glint.sphere{ center = {1.9, 0.55, 2.2}, radius = 0.55, material = blue }
glint.sphere{ center = {-3.4, 0.35, 4.4}, radius = 0.35, material = green }       -- far, blurred

-- A standing mirror at the back left, turned so that the camera sees the spheres in it.
glint.box{ min = {-1.2, 0, -0.04}, max = {1.2, 2.2, 0.04}, material = chrome,
           transform = glint.translate(2.6, 0, 4.2) * glint.rotate(22, {0, 1, 0}) }
