-- Caustics: a glass sphere focuses a small spot light onto the floor, and a polished
-- metal ring throws its cardioid. Render with photon mapping or SPPM:
--   build/glint render examples/caustics.lua                       (photon, default)
--   build/glint render examples/caustics.lua --integrator sppm --spp 64
--   build/glint render examples/caustics.lua --integrator photon --debug photons
--   build/glint render examples/caustics.lua --integrator preview --spp 30   (the viewer's
--       real-time caustics: the passes of 30 frames, a few seconds)
local floor = glint.diffuse{ reflectance = {0.75, 0.73, 0.7} }
local glass = glint.dielectric{ ior = 1.5 }
local metal = glint.mirror{ tint = {0.95, 0.85, 0.6} }

glint.camera{ eye = {0, 5.5, 6.5}, look_at = {0, 0.3, 0}, fov = 38 }
glint.render{ width = 480, height = 360, spp = 8, integrator = "photon",
              photons = 200000, caustic_photons = 1000000, photon_neighbours = 80, gather_rays = 8,
              output = {"caustics.exr", "caustics.png"} }
glint.background{ radiance = 0.02 }

glint.quad{ vertices = {{-8, 0, 8}, {8, 0, 8}, {8, 0, -8}, {-8, 0, -8}}, material = floor }

-- The glass sphere, lit from above and to the side, so its caustic falls beside it.
glint.sphere{ center = {-1.4, 0.8, 0.3}, radius = 0.8, material = glass }

-- A ring: a thin cylinder minus a slightly smaller one; light hitting its inside wall
-- gathers into the cardioid on the floor inside the ring.
local outer = glint.solid.cylinder{ radius = 1.0, height = 0.5 }
local inner = glint.solid.cylinder{ radius = 0.95, height = 0.6 }
glint.add(glint.difference{ outer, inner, material = metal, transform = glint.translate(1.3, 0.25, 0) })

glint.spot_light{ position = {-4.5, 5, 0}, look_at = {0.4, 0, 0}, intensity = 260, cone_angle = 28, falloff_start = 24 }
