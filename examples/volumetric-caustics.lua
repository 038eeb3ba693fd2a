-- Volumetric caustics: a small, bright light above a glass sphere in a box of thin fog.
-- The sphere focuses the light into a beam that the fog makes visible below it, and a
-- caustic on the floor. The fog is bounded by an interface box (a surface that only bounds
-- a medium); the camera stands outside it, in clear air. volpath finds the beam only by
-- BSDF and phase sampling hitting the small light through the glass, so it converges
-- slowly; the light tracer follows the light through the glass into the fog and sees the
-- beam at once (`glint render examples/volumetric-caustics.lua --integrator light`), but
-- cannot see the glass itself; bdpt does both (`--integrator bdpt`: the beam, the glass
-- and the caustic seen through it). bench/volumetric_caustics.sh compares the three.
-- In the viewer, `glint view examples/volumetric-caustics.lua --integrator preview` shows the
-- fog and the beam in real time: move the light and the beam follows (single scattering and
-- the volume photons' beam estimate, docs/integrators.md).
local fog = glint.medium{ density = 0.1, albedo = 0.9, g = 0.4 }
local glass = glint.dielectric{ ior = 1.5 }
local floor = glint.diffuse{ reflectance = 0.6 }
local walls = glint.diffuse{ reflectance = {0.5, 0.45, 0.4} }
local lamp = glint.emissive{ radiance = 400 }

glint.camera{ eye = {0, 1.2, 4.2}, look_at = {0, 0.9, 0}, up = {0, 1, 0}, fov = 45 }
glint.render{ width = 192, height = 192, spp = 32, integrator = "volpath", max_depth = 12,
              output = {"volumetric-caustics.exr", "volumetric-caustics.png"} }

-- The fog fills the room; its boundary lies just inside the walls.
glint.box{ min = {-1.99, 0.01, -1.99}, max = {1.99, 2.99, 1.99},
           material = glint.interface{ interior = fog } }
glint.quad{ vertices = { {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2} }, material = floor }
glint.quad{ vertices = { {-2, 0, -2}, {2, 0, -2}, {2, 3, -2}, {-2, 3, -2} }, material = walls }
glint.quad{ vertices = { {-2, 3, -2}, {2, 3, -2}, {2, 3, 2}, {-2, 3, 2} }, material = walls }

glint.sphere{ center = {0, 1.1, 0}, radius = 0.45, material = glass }
glint.sphere{ center = {0, 2.4, 0}, radius = 0.06, material = lamp }
