-- vcm with more light subpaths than pixels (vcm_light_paths, docs/integrators.md): the
-- caustic of mirror-caustic.lua, seen in the mirror, which only merging finds. Four light
-- subpaths per pixel per iteration make each iteration's photons four times as dense (and
-- its light tracing four times as frequent) for about three times an iteration's cost; the
-- camera's connections are unchanged. Compare with the default (one light subpath per pixel)
-- at about the same time:
--   build/glint render examples/vcm-light-paths.lua
--   build/glint render examples/mirror-caustic.lua --res 160x120 --spp 24
local floor = glint.diffuse{ reflectance = {0.7, 0.6, 0.5} }
local wall = glint.diffuse{ reflectance = {0.4, 0.45, 0.55} }

glint.camera{ eye = {1.4, 1.4, 3.0}, look_at = {0, 0.3, -1.2}, fov = 40 }
glint.render{ width = 160, height = 120, spp = 8, integrator = "vcm",
              vcm_light_paths = 4 * 160 * 120,
              output = {"vcm-light-paths.exr", "vcm-light-paths.png"} }

glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}}, material = floor }
glint.quad{ vertices = {{-4, 0, -4}, {4, 0, -4}, {4, 4, -4}, {-4, 4, -4}}, material = wall }

-- The mirror stands between the ball and the back wall, facing the camera.
glint.quad{ vertices = {{-1.6, 0.02, -1.2}, {1.6, 0.02, -1.2}, {1.6, 1.8, -1.2}, {-1.6, 1.8, -1.2}},
            material = glint.mirror{ tint = 0.95 } }
glint.sphere{ center = {0, 1.2, 0}, radius = 0.4, material = glint.dielectric{ ior = 1.5 } }
glint.point_light{ position = {0, 2, 0}, intensity = {4, 3, 2} }
