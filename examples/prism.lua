-- A prism splits a narrow beam of white light into a rainbow on a wall. Spectral mode
-- (spectral = true) carries four wavelengths per path; at the dispersive glass each path
-- goes on with its hero wavelength alone, bent by that wavelength's index (Sellmeier). The
-- beam reaches the wall only through the glass, so a light-path method renders it: light
-- tracing, a few seconds:
--   build/glint render examples/prism.lua
--   build/glint render examples/prism.lua --integrator bdpt --spp 16   (slower)
-- In RGB mode (--spectral off: remove `spectral = true`) the same beam stays white.

-- Schott N-SF11, a dense flint glass (n_d = 1.785, Abbe number 25.7): its spread of about
-- four degrees between red and blue is easy to see. Sellmeier B1..B3, C1..C3 (µm²).
local flint = glint.dielectric{ sellmeier_b = { 1.73759695, 0.313747346, 1.89878101 },
                                sellmeier_c = { 0.013188707, 0.0623068142, 155.23629 } }
local wall = glint.diffuse{ reflectance = 0.8 }

glint.camera{ eye = {-0.6, 1.0, 1.6}, look_at = {2.7, 0.5, -1.45}, fov = 16 }
glint.render{ width = 320, height = 240, spp = 16, integrator = "light", spectral = true,
              output = {"prism.exr", "prism.png"} }

-- An equilateral prism standing on its base, 1 unit tall; the apex edge points along +z.
glint.mesh{ vertices = {{0, 0, 0.6}, {-0.52, 0, -0.3}, {0.52, 0, -0.3},
                        {0, 1, 0.6}, {-0.52, 1, -0.3}, {0.52, 1, -0.3}},
            indices = {1, 2, 3, 4, 6, 5, 1, 5, 2, 1, 4, 5, 2, 6, 3, 2, 5, 6, 3, 4, 1, 3, 6, 4},
            material = flint }

-- The beam: a spot light of 0.4° half-angle, rising 33° towards the prism's left face, which
-- (at n ≈ 1.78) is the angle of minimum deviation: inside, the light runs parallel to the
-- base, and it leaves falling 33°, red least and violet most.
glint.spot_light{ position = {-3.61, 0.5, -2.04}, look_at = {-0.26, 0.5, 0.15},
                  intensity = 600, cone_angle = 0.4, falloff_start = 0.3 }

-- The wall, 3 units from the prism across the beam's way out, facing it.
glint.quad{ vertices = {{1.95, -0.5, -2.75}, {3.59, -0.5, -0.24}, {3.59, 1.5, -0.24},
                        {1.95, 1.5, -2.75}},
            material = wall }
