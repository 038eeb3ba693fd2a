-- A puff of smoke from a density grid file (smoke.nvdb, written by
-- scripts/make-example-grid.sh) over a floor, lit by a warm spot light from above and a
-- dim blue sky, rendered by null-scattering path tracing (volpath). The grid is sparse: a
-- 16^3 majorant grid lets the walks skip its empty corners (docs/heterogeneous-media.md).
-- The file's 32^3 voxels of 1/16 span [-1/32, 2 - 1/32] on each axis; the transform centres
-- them on the origin.
local smoke = glint.medium{ type = "grid", file = "smoke.nvdb", density = 12, albedo = 0.9,
                            g = 0.2, transform = glint.translate(-0.96875, -0.96875, -0.96875) }
local floor = glint.diffuse{ reflectance = {0.6, 0.6, 0.6} }

glint.camera{ eye = {0, 1.2, -4.2}, look_at = {0, 0.1, 0}, up = {0, 1, 0}, fov = 40 }
glint.render{ width = 160, height = 120, spp = 16, integrator = "volpath",
              output = {"smoke.exr", "smoke.png"} }
glint.background{ radiance = {0.05, 0.08, 0.15} }

-- An interface box (a surface that only bounds a medium) around the grid's box [-1, 1]^3.
glint.box{ min = {-1, -1, -1}, max = {1, 1, 1}, material = glint.interface{ interior = smoke } }
glint.quad{ vertices = {{-6, -1.05, -6}, {-6, -1.05, 6}, {6, -1.05, 6}, {6, -1.05, -6}}, material = floor }
glint.spot_light{ position = {1.5, 4, -1}, look_at = {0, 0, 0}, intensity = {40, 34, 26},
                  cone_angle = 30, falloff_start = 26 }
