-- Groups and instancing: one "post" (a box with a ball on top) is built once and placed
-- 24 times by a Lua loop, as two nested rings. In the middle, a tinted glass ball whose
-- colour comes from Beer-Lambert absorption: thicker glass, deeper colour.
-- Lit by a spot light from above and a point light from the side. Units are metres.
local floor_white = glint.diffuse{ reflectance = 0.6 }
local post_grey   = glint.diffuse{ reflectance = {0.55, 0.5, 0.45} }
local orange      = glint.diffuse{ reflectance = {0.8, 0.3, 0.05} }
local gold        = glint.mirror{ tint = {0.95, 0.75, 0.35} }
-- Absorption per metre inside the ball: red goes first, so the glass looks teal.
local teal_glass  = glint.dielectric{ ior = 1.5, absorption = {1.6, 0.25, 0.35} }

glint.camera{ eye = {0, 4.2, -8.5}, look_at = {0, 0.5, 0}, fov = 40 }
glint.render{ width = 640, height = 400, spp = 32, output = {"instancing.exr", "instancing.png"} }
glint.background{ radiance = {0.05, 0.07, 0.1} }

glint.spot_light{ position = {1, 7, -2}, look_at = {0, 0, 0}, intensity = 120,
                  cone_angle = 40, falloff_start = 25 }
glint.point_light{ position = {-5, 3, -4}, intensity = {12, 10, 8} }

glint.quad{ vertices = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}},
            material = floor_white }
glint.sphere{ center = {0, 0.9, 0}, radius = 0.9, material = teal_glass }

-- Two kinds of post, each a group: built once, then instanced. The shapes are given in
-- the group's own space, standing on y = 0 around the y axis.
local function make_post(ball_material)
    local post = glint.group()
    post:box{ min = {-0.12, 0, -0.12}, max = {0.12, 0.5, 0.12}, material = post_grey }
    post:sphere{ center = {0, 0.7, 0}, radius = 0.2, material = ball_material }
    return post
end
local matte_post = make_post(orange)
local mirror_post = make_post(gold)

-- A ring of 12 posts, alternating. Each placement turns the post about y, then pushes it
-- out to the radius: rotate * translate applies the translation first.
local ring = glint.group()
local count = 12
for i = 0, count - 1 do
    local post = (i % 2 == 0) and matte_post or mirror_post
    ring:place(post, glint.rotate(360 * i / count, {0, 1, 0}) * glint.translate(2.6, 0, 0))
end

-- The ring group placed twice: as it is, and scaled down, turned half a step, inside it.
glint.place(ring)
glint.place(ring, glint.scale(0.6) * glint.rotate(15, {0, 1, 0}))
