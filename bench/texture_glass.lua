-- Issue 17's "an image texture seen through glass renders about 5x slower than a plain
-- colour there": a textured quad behind a glass ball. Compare, one thread, alternating:
--   build/glint render bench/texture_glass.lua --threads 1 -o /tmp/tex.exr
--   GLINT_PLAIN=1 build/glint render bench/texture_glass.lua --threads 1 -o /tmp/plain.exr
-- (GLINT_ROUGH=1 makes the glass rough). Measured 2026-11-24: about 1.4x, not 5x (see
-- bench/README.md, "Textures seen through glass").
local plain = os.getenv("GLINT_PLAIN") ~= nil
local rough = os.getenv("GLINT_ROUGH") ~= nil and 0.2 or 0
glint.camera{ eye = {0, 0, 4}, look_at = {0, 0, 0}, fov = 40 }
glint.render{ width = 160, height = 160, spp = 16, integrator = "path" }
glint.point_light{ position = {0, 3, 4}, intensity = 30 }
local wall = plain and 0.5
    or glint.texture.image{ file = "../examples/textures/uv-grid.png", scale = 1 }
glint.quad{ vertices = {{-3, -3, -2}, {3, -3, -2}, {3, 3, -2}, {-3, 3, -2}},
            material = glint.diffuse{ reflectance = wall } }
glint.sphere{ radius = 1.2, material = glint.dielectric{ ior = 1.5, roughness = rough } }
