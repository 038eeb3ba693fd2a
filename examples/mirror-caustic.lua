-- A caustic seen in a mirror: a point light above a glass ball focuses a bright disc on the
-- floor under the ball, and the camera looks at that disc in a standing mirror. The light
-- reaches the eye by point light -> glass -> floor -> mirror -> lens: a diffuse vertex between
-- two delta ones, which no strategy of a path tracer, a light tracer or bdpt can join (the
-- light is a point, the glass and the mirror are delta). Merging photons at the floor can:
--   build/glint render examples/mirror-caustic.lua                        (vcm, default)
--   build/glint render examples/mirror-caustic.lua --integrator bdpt      (no caustic in the mirror)
--   build/glint render examples/mirror-caustic.lua --integrator sppm --spp 64
local floor = glint.diffuse{ reflectance = {0.7, 0.6, 0.5} }
local wall = glint.diffuse{ reflectance = {0.4, 0.45, 0.55} }

glint.camera{ eye = {1.4, 1.4, 3.0}, look_at = {0, 0.3, -1.2}, fov = 40 }
glint.render{ width = 256, height = 192, spp = 16, integrator = "vcm",
              output = {"mirror-caustic.exr", "mirror-caustic.png"} }

glint.quad{ vertices = {{-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}}, material = floor }
glint.quad{ vertices = {{-4, 0, -4}, {4, 0, -4}, {4, 4, -4}, {-4, 4, -4}}, material = wall }

-- The mirror stands between the ball and the back wall, facing the camera.
glint.quad{ vertices = {{-1.6, 0.02, -1.2}, {1.6, 0.02, -1.2}, {1.6, 1.8, -1.2}, {-1.6, 1.8, -1.2}},
            material = glint.mirror{ tint = 0.95 } }
glint.sphere{ center = {0, 1.2, 0}, radius = 0.4, material = glint.dielectric{ ior = 1.5 } }
glint.point_light{ position = {0, 2, 0}, intensity = {4, 3, 2} }
