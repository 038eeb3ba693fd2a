-- An isometric view with an orthographic camera (parallel rays: no perspective, so the
-- grid of boxes keeps its size into the distance), and, with GLINT_CAMERA=lens, the same
-- scene through a thin lens focused on the far box with focus_on:
--   build/glint render examples/orthographic.lua
--   GLINT_CAMERA=lens build/glint render examples/orthographic.lua
local mode = os.getenv("GLINT_CAMERA") or "orthographic"
assert(mode == "orthographic" or mode == "lens", "GLINT_CAMERA must be 'orthographic' or 'lens'")

if mode == "orthographic" then
    -- Isometric: looking down the diagonal (1, 1, 1); scale is the image's height in metres.
    glint.camera{ type = "orthographic", eye = {6, 6, 6}, look_at = {0, 0, 0}, scale = 5.5 }
else
    glint.camera{ eye = {5, 3, 6}, look_at = {0, 0.3, 0}, fov = 40, aperture = 0.12,
                  focus_on = {-1.5, 0.3, -1.5} }
end
glint.render{ width = 400, height = 300, spp = 16, integrator = "path",
              output = {"orthographic-" .. mode .. ".png"} }
glint.background{ radiance = 0.3 }

glint.quad{ vertices = {{-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}},
            material = glint.diffuse{ reflectance = 0.6 } }
local colours = { {0.7, 0.15, 0.1}, {0.2, 0.5, 0.15}, {0.15, 0.3, 0.6} }
for i = -1, 1 do
    for j = -1, 1 do
        local h = 0.3 + 0.2 * (i + j + 2)
        glint.box{ min = {1.5 * i - 0.4, 0, 1.5 * j - 0.4}, max = {1.5 * i + 0.4, h, 1.5 * j + 0.4},
                   material = glint.diffuse{ reflectance = colours[(i + j + 2) % 3 + 1] } }
    end
end
glint.directional_light{ direction = {-0.4, -1, -0.6}, irradiance = 3 }
