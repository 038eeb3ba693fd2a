-- Depth of field: a row of ten spheres receding from the camera over a checkered floor,
-- seen through a thin lens. By default the lens focuses on the nearest sphere and the row
-- blurs away behind it; GLINT_FOCUS=far focuses on the farthest one instead:
--   build/glint render examples/depth-of-field.lua                  -> depth-of-field-near.png
--   GLINT_FOCUS=far build/glint render examples/depth-of-field.lua  -> depth-of-field-far.png
-- (or change the default on the next line). Units are metres; +x is on the image's left.
local focus = os.getenv("GLINT_FOCUS") or "near"
assert(focus == "near" or focus == "far", "GLINT_FOCUS must be 'near' or 'far'")

local light_tile = glint.diffuse{ reflectance = 0.7 }
local dark_tile  = glint.diffuse{ reflectance = {0.1, 0.1, 0.13} }
local colours = { {0.7, 0.1, 0.06}, {0.75, 0.45, 0.05}, {0.2, 0.5, 0.1}, {0.06, 0.35, 0.55},
                  {0.3, 0.12, 0.6} }

-- The spheres: radius 0.35, 1.6 m apart along the z axis; the camera looks along the row
-- from the side, so it recedes from the lower right towards the horizon.
local centres = {}
for k = 0, 9 do
    centres[#centres + 1] = {0, 0.35, 1.6 * k}
end

-- The plane in focus lies across the view direction at `focus_distance` from the eye, so
-- it is the sphere centre's distance measured along that direction.
local eye, target = {2, 1.1, -4}, {-0.3, 0.35, 6}
local forward = {target[1] - eye[1], target[2] - eye[2], target[3] - eye[3]}
local length = math.sqrt(forward[1] ^ 2 + forward[2] ^ 2 + forward[3] ^ 2)
local function depth_of(p)
    return ((p[1] - eye[1]) * forward[1] + (p[2] - eye[2]) * forward[2] + (p[3] - eye[3]) * forward[3]) / length
end
local sharp = focus == "near" and centres[1] or centres[#centres]

glint.camera{ eye = eye, look_at = target, fov = 32, aperture = 0.06, focus_distance = depth_of(sharp) }
glint.render{ width = 640, height = 360, spp = 32, integrator = "whitted", ambient = 0.05,
              output = {"depth-of-field-" .. focus .. ".exr", "depth-of-field-" .. focus .. ".png"} }
glint.background{ radiance = {0.35, 0.45, 0.6} }
-- Low sun from the left, so each sphere casts a shadow across the row.
glint.directional_light{ direction = {-0.6, -0.5, 0.4}, irradiance = {3.2, 3, 2.7} }

-- Checkerboard of 1 m tiles, each a quad facing up.
for i = -6, 5 do
    for j = -3, 24 do
        glint.quad{ vertices = {{i, 0, j}, {i, 0, j + 1}, {i + 1, 0, j + 1}, {i + 1, 0, j}},
                    material = (i + j) % 2 == 0 and light_tile or dark_tile }
    end
end

for k, c in ipairs(centres) do
    local material = glint.phong{ diffuse = colours[(k - 1) % #colours + 1], specular = 0.25, exponent = 80 }
    glint.sphere{ center = c, radius = 0.35, material = material }
end
