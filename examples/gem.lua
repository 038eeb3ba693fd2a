-- Fire: a diamond crystal (an octahedron, as diamonds grow) under one small bright light.
-- Diamond's index falls from 2.46 in the violet to 2.41 in the red; light that enters, is
-- reflected inside and leaves splits into its colours, the flashes a cut stone is valued for.
-- Spectral mode is what shows them (in RGB mode the crystal stays colourless):
--   build/glint render examples/gem.lua                 (bdpt, a few seconds)
--   build/glint render examples/gem.lua --spp 64        (less colour noise)

-- Diamond: glint's preset (Sellmeier, Peter 1923; n_d = 2.4175).
local diamond = glint.dielectric{ ior = "diamond" }
local cloth = glint.diffuse{ reflectance = {0.05, 0.05, 0.06} }

glint.camera{ eye = {0, 2.2, 4.2}, look_at = {0, 0.9, 0}, fov = 32 }
glint.render{ width = 240, height = 180, spp = 16, integrator = "bdpt", spectral = true,
              output = {"gem.exr", "gem.png"} }
glint.background{ radiance = 0.01 }

glint.quad{ vertices = {{-6, 0, 6}, {6, 0, 6}, {6, 0, -6}, {-6, 0, -6}}, material = cloth }

-- The crystal, standing on a point, turned so that its faces catch the light at many angles.
glint.mesh{ vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1.3, 0}, {0, -1.3, 0}, {0, 0, 1}, {0, 0, -1}},
            indices = {1, 3, 5, 1, 6, 3, 1, 5, 4, 1, 4, 6, 2, 5, 3, 2, 3, 6, 2, 4, 5, 2, 6, 4},
            material = diamond,
            transform = glint.translate(0, 1.35, 0) * glint.rotate(25, {0, 1, 0})
                        * glint.rotate(12, {1, 0, 1}) * glint.scale(0.8) }

-- A small, bright light above and behind: the crystal's fire is its image, split.
glint.sphere{ center = {-1.5, 4, -2}, radius = 0.2,
              material = glint.emissive{ radiance = 300 } }
