-- A caustic from a point light, seen directly: the one kind of light a path tracer cannot
-- find (a camera path would have to hit the point light by BSDF sampling, through the
-- glass). Light tracing starts at the light and finds it at once:
--   build/glint render examples/point-caustic.lua                        (light, default)
--   build/glint render examples/point-caustic.lua --integrator path      (no caustic)
--   build/glint render examples/point-caustic.lua --integrator sppm --spp 64
local floor = glint.diffuse{ reflectance = {0.75, 0.73, 0.7} }
local wall = glint.diffuse{ reflectance = {0.45, 0.5, 0.6} }
local glass = glint.dielectric{ ior = 1.5 }

glint.camera{ eye = {0, 3.2, 5.5}, look_at = {0, 0.5, 0}, fov = 40 }
glint.render{ width = 320, height = 240, spp = 128, integrator = "light",
              output = {"point-caustic.exr", "point-caustic.png"} }

glint.quad{ vertices = {{-6, 0, 6}, {6, 0, 6}, {6, 0, -4}, {-6, 0, -4}}, material = floor }
glint.quad{ vertices = {{-6, 0, -4}, {6, 0, -4}, {6, 6, -4}, {-6, 6, -4}}, material = wall }

-- The sphere focuses the point light above it into a bright spot on the floor beside it.
glint.sphere{ center = {0.3, 0.9, 0.2}, radius = 0.9, material = glass }
glint.point_light{ position = {-1.2, 4.0, -0.4}, intensity = 40 }
