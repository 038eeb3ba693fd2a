-- Spectral inputs in RGB mode (docs/materials.md "Measured metals", "Dispersive glass";
-- docs/scene-language.md "Emission by temperature or spectrum"): four spheres of measured
-- metals (gold, silver, copper, aluminium: η and k from Johnson & Christy 1972 and Rakić
-- 1995, integrated to RGB), a BK7 and a diamond sphere (Sellmeier presets, rendered at their
-- index n_d), lit by a warm 2700 K blackbody spot light from the left and a panel emitting
-- the CIE illuminant D65 above. The camera looks along -z.
--   build/glint render examples/spectral-materials.lua
glint.render{ width = 480, height = 270, spp = 16, max_depth = 8,
              output = {"spectral-materials.exr", "spectral-materials.png"} }
glint.camera{ eye = {0, 2.4, 5.6}, look_at = {0, 0.45, 0}, fov = 38 }
glint.background{ radiance = 0.05 }

glint.quad{ vertices = {{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}},
            material = glint.diffuse{ reflectance = 0.5 } }
-- A back wall, so that the metals have something to reflect.
glint.quad{ vertices = {{-10, 0, -2.5}, {10, 0, -2.5}, {10, 6, -2.5}, {-10, 6, -2.5}},
            material = glint.diffuse{ reflectance = {0.2, 0.3, 0.45} } }

glint.quad{ vertices = {{-2, 4, -1}, {2, 4, -1}, {2, 4, 1.5}, {-2, 4, 1.5}},
            material = glint.emissive{ radiance = 3, spectrum = "D65" } }
glint.spot_light{ position = {-4, 3, 2.5}, look_at = {0, 0.5, 0}, intensity = 40,
                  blackbody = 2700, cone_angle = 35 }

local metals = {"Au", "Ag", "Cu", "Al"}
for i, metal in ipairs(metals) do
    glint.sphere{ center = {(i - 2.5) * 1.1, 0.5, -0.6}, radius = 0.5,
                  material = glint.conductor{ metal = metal, roughness = 0.15 } }
end
glint.sphere{ center = {-0.6, 0.4, 0.7}, radius = 0.4,
              material = glint.dielectric{ ior = "BK7" } }
glint.sphere{ center = {0.6, 0.4, 0.7}, radius = 0.4,
              material = glint.dielectric{ ior = "diamond" } }
