-- The motion blur benchmark's scene (bench/motion_blur.sh): 144 groups of a box and a
-- sphere over a floor, each placed moving (two keys: a slide and a quarter turn) when
-- MOVING is true, or still at its first key when false; a point light and a sky. The
-- script substitutes MOVING and SHUTTER.
local moving = MOVING
local floor_white = glint.diffuse{ reflectance = 0.6 }
local red = glint.diffuse{ reflectance = {0.8, 0.2, 0.1} }
local blue = glint.plastic{ diffuse = {0.1, 0.2, 0.8} }

glint.camera{ eye = {0, 9, -14}, look_at = {0, 0, 0}, fov = 45, shutter = SHUTTER }
glint.render{ width = 256, height = 256, spp = 32 }
glint.background{ radiance = {0.1, 0.12, 0.15} }
glint.point_light{ position = {4, 12, -6}, intensity = 300 }
glint.quad{ vertices = {{-30, 0, -30}, {-30, 0, 30}, {30, 0, 30}, {30, 0, -30}},
            material = floor_white }

local piece = glint.group()
piece:box{ min = {-0.3, 0, -0.3}, max = {0.3, 0.6, 0.3}, material = red }
piece:sphere{ center = {0, 0.9, 0}, radius = 0.3, material = blue }
for i = 0, 11 do
    for j = 0, 11 do
        local at = glint.translate(1.2 * (i - 5.5), 0, 1.2 * (j - 5.5))
        local later = at * glint.translate(0.5, 0, 0) * glint.rotate(90, {0, 1, 0})
        if moving then
            glint.place(piece, { at, later })
        else
            glint.place(piece, at)
        end
    end
end
