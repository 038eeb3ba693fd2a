-- Surfaces that only bound a medium (glint.interface): a ball of dark, tinted smoke with no
-- glass around it, beside a glass ball holding the same medium. Light crosses the
-- interface unbent; inside, the medium absorbs red least, so both look red, and the glass
-- one also refracts and reflects. Render with volpath, the integrator that carries the
-- medium a path is in.
local smoke = glint.medium{ sigma_a = {0.4, 2.5, 3.0}, sigma_s = 0.5, g = 0.3 }
local white = glint.diffuse{ reflectance = 0.7 }
local lamp = glint.emissive{ radiance = 6, two_sided = true }

glint.camera{ eye = {0, 1.0, 4.0}, look_at = {0, 0.5, 0}, up = {0, 1, 0}, fov = 40 }
glint.render{ width = 192, height = 128, spp = 32, integrator = "volpath",
              output = {"interface.exr", "interface.png"} }

glint.quad{ vertices = { {-4, 0, -3}, {-4, 0, 3}, {4, 0, 3}, {4, 0, -3} }, material = white }
glint.quad{ vertices = { {-4, 0, -3}, {4, 0, -3}, {4, 4, -3}, {-4, 4, -3} }, material = white }
glint.quad{ vertices = { {-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1} }, material = lamp }

glint.sphere{ center = {-0.7, 0.6, 0}, radius = 0.6, material = glint.interface{ interior = smoke } }
glint.sphere{ center = {0.7, 0.6, 0}, radius = 0.6,
              material = glint.dielectric{ ior = 1.5, interior = smoke } }
