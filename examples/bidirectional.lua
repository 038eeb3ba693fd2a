-- What bidirectional path tracing is for: a glass sphere seen directly (only camera paths
-- find it), the caustic a point light throws through it onto the floor (only light paths
-- find it), and the light that walls and floor pass on to each other (both). bdpt has a
-- strategy for each; path misses the caustic, light misses the glass:
--   build/glint render examples/bidirectional.lua                        (bdpt, default)
--   build/glint render examples/bidirectional.lua --integrator path      (no caustic)
--   build/glint render examples/bidirectional.lua --integrator light     (black glass)
--   build/glint render examples/bidirectional.lua --debug strategies     (each (s, t) alone)
local floor = glint.diffuse{ reflectance = {0.75, 0.73, 0.7} }
local wall = glint.diffuse{ reflectance = {0.45, 0.5, 0.6} }
local red = glint.diffuse{ reflectance = {0.6, 0.15, 0.1} }
local glass = glint.dielectric{ ior = 1.5 }

glint.camera{ eye = {0, 3.2, 5.5}, look_at = {0, 0.6, 0}, fov = 40 }
glint.render{ width = 256, height = 192, spp = 16, integrator = "bdpt", max_depth = 8,
              output = {"bidirectional.exr", "bidirectional.png"} }

glint.quad{ vertices = {{-6, 0, 6}, {6, 0, 6}, {6, 0, -4}, {-6, 0, -4}}, material = floor }
glint.quad{ vertices = {{-6, 0, -4}, {6, 0, -4}, {6, 6, -4}, {-6, 6, -4}}, material = wall }
glint.quad{ vertices = {{-4, 0, 6}, {-4, 0, -4}, {-4, 6, -4}, {-4, 6, 6}}, material = red }

-- The sphere focuses the point light above it into a bright spot on the floor beside it.
glint.sphere{ center = {0.3, 0.9, 0.2}, radius = 0.9, material = glass }
glint.point_light{ position = {-1.2, 4.0, -0.4}, intensity = 40 }
