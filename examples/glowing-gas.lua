-- A glowing gas: a ball of medium that absorbs, scatters and emits (a warm glow, denser in
-- blue, so its edge reddens), over a floor, beside a small lamp. The gas lights nothing
-- but itself and its own scattering; the lamp's light scatters in it. volpath (the default
-- here), bdpt, vcm, mlt and the light tracer agree on it: volpath collects the glow along its
-- paths, bdpt, vcm and mlt along their camera subpaths, the light tracer starts paths in the
-- gas (`glint render examples/glowing-gas.lua --integrator light`). The viewer's preview
-- shows the glow seen from the camera and single scattering only, so its gas is darker
-- (`glint view examples/glowing-gas.lua --integrator preview`).
-- docs/integrators.md (`volpath`: emitting media).
local gas = glint.medium{ sigma_a = {1, 1.5, 2}, sigma_s = 0.6, g = 0.2, emission = {2, 1, 0.4} }

glint.camera{ eye = {0, 1, 4}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 40 }
glint.render{ width = 256, height = 256, spp = 64, integrator = "volpath", max_depth = 6,
              output = {"glowing-gas.exr", "glowing-gas.png"} }

glint.quad{ vertices = { {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3} },
            material = glint.diffuse{ reflectance = 0.6 } }
glint.sphere{ center = {0, 0.9, 0}, radius = 0.7, material = glint.interface{ interior = gas } }
glint.sphere{ center = {1.4, 1.8, 0.5}, radius = 0.15, material = glint.emissive{ radiance = 10 } }
