-- Soft-shadow benchmark for the whitted integrator's penumbra shortcut: one large square
-- area light over a floor crowded with occluders of every kind the shortcut meets: big
-- spheres and boxes (wide umbrae and straight-edged penumbrae), small floating spheres
-- (shadows that never reach an umbra), and a grating of thin slats whose gaps are
-- narrower than the light (where the four extreme shadow rays can all be clear or all be
-- blocked while rays between them are not: the shortcut's error comes from places like
-- that). bench/classic.sh renders it with the shortcut off and on. Environment:
--   GLINT_PENUMBRA_SHORTCUT  "1" or "0" (default): the render setting penumbra_shortcut
--   GLINT_SHADOW_SAMPLES     N for N x N shadow rays per area light (default 8)
local shortcut = (os.getenv("GLINT_PENUMBRA_SHORTCUT") or "0") ~= "0"
local shadow_samples = math.tointeger(tonumber(os.getenv("GLINT_SHADOW_SAMPLES") or "8"))
assert(shadow_samples, "GLINT_SHADOW_SAMPLES must be an integer")

glint.camera{ eye = {0, 3.8, -8.5}, look_at = {0, 0, 0.5}, fov = 50 }
glint.render{ width = 320, height = 240, spp = 4, seed = 1, integrator = "whitted",
              shadow_samples = shadow_samples, penumbra_shortcut = shortcut, ambient = 0.02 }
glint.background{ radiance = 0.05 }

local floor = glint.diffuse{ reflectance = 0.7 }
local grey = glint.diffuse{ reflectance = 0.5 }
local warm = glint.phong{ diffuse = {0.6, 0.35, 0.2}, specular = 0.2, exponent = 40 }
local cool = glint.phong{ diffuse = {0.2, 0.3, 0.6}, specular = 0.3, exponent = 100 }

glint.quad{ vertices = {{-12, 0, -12}, {-12, 0, 12}, {12, 0, 12}, {12, 0, -12}}, material = floor }
-- The light: 2 m square, 4 m up, facing down.
glint.quad{ vertices = {{-1, 4, -1}, {1, 4, -1}, {1, 4, 1}, {-1, 4, 1}},
            material = glint.emissive{ radiance = 6 } }

-- A ring of large spheres resting on the floor and boxes between them.
for k = 0, 5 do
    local a = 2 * math.pi * k / 6 + math.pi / 12
    glint.sphere{ center = {3.2 * math.cos(a), 0.6, 3.2 * math.sin(a)}, radius = 0.6,
                  material = k % 2 == 0 and warm or cool }
    local b = a + math.pi / 6
    glint.box{ min = {-0.3, 0, -0.3}, max = {0.3, 1.2, 0.3}, material = grey,
               transform = glint.translate(4.2 * math.cos(b), 0, 4.2 * math.sin(b)) * glint.rotate(30 * k, {0, 1, 0}) }
end
-- Small spheres floating at different heights.
for k = 0, 7 do
    local a = 2 * math.pi * (k + 0.5) / 8
    glint.sphere{ center = {1.8 * math.cos(a), 0.6 + 0.25 * k, 1.8 * math.sin(a)}, radius = 0.12, material = warm }
end
-- A grating of thin slats, 1.5 m above the floor in front of the light.
for k = -4, 4 do
    glint.box{ min = {-1.6, 1.5, -0.03}, max = {1.6, 1.56, 0.03}, material = grey,
               transform = glint.translate(0, 0, -2.2 + 0.22 * k) }
end
