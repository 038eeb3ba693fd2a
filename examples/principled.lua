-- The principled material (glint.principled, docs/materials.md): the back row is metal
-- (metallic = 1, a gold base colour) from roughness 0 (left) to 1 (right); the middle row
-- the same roughnesses on a red dielectric (metallic = 0: a diffuse base under a specular
-- layer of ior 1.5); in front, rough glass (transmission = 1), a dark blue base under a
-- clear coat with sheen at its rim, a half-metallic textured sphere, and a small lamp
-- whose principled emission makes it an area light. The camera looks along -z.
--   build/glint render examples/principled.lua
glint.render{ width = 640, height = 360, spp = 24, max_depth = 8,
              output = {"principled.exr", "principled.png"} }
glint.camera{ eye = {0, 5.2, 7.0}, look_at = {0, 0.2, -0.2}, fov = 40 }
glint.background{ radiance = {0.25, 0.3, 0.4} }

-- A checker floor, to show refraction and blurred reflections.
local checker = glint.texture.checker{ mapping = "planar", scale = 1, even = 0.7, odd = 0.15 }
glint.quad{ vertices = {{-20, 0, 20}, {20, 0, 20}, {20, 0, -20}, {-20, 0, -20}},
            material = glint.principled{ base_color = checker, roughness = 0.6 } }
-- The key light: a large panel above and in front.
glint.quad{ vertices = {{-3, 6, 1}, {3, 6, 1}, {3, 6, 4}, {-3, 6, 4}},
            material = glint.emissive{ radiance = 6, two_sided = false } }

local roughnesses = {0, 0.25, 0.5, 0.75, 1}
for i, roughness in ipairs(roughnesses) do
    local x = (i - 3) * 1.1
    glint.sphere{ center = {x, 0.5, -1.9}, radius = 0.5,
                  material = glint.principled{ base_color = {1.0, 0.78, 0.34}, metallic = 1,
                                               roughness = roughness } }
    glint.sphere{ center = {x, 0.5, -0.5}, radius = 0.5,
                  material = glint.principled{ base_color = {0.7, 0.08, 0.06},
                                               roughness = roughness } }
end

glint.sphere{ center = {-2.0, 0.5, 1.2}, radius = 0.5,
              material = glint.principled{ base_color = {0.95, 0.98, 1.0}, transmission = 1,
                                           roughness = 0.1, ior = 1.5 } }
glint.sphere{ center = {-0.7, 0.5, 1.2}, radius = 0.5,
              material = glint.principled{ base_color = {0.05, 0.08, 0.3}, roughness = 0.7,
                                           clearcoat = 1, clearcoat_roughness = 0.05,
                                           sheen = 1, sheen_tint = 0.3 } }
glint.sphere{ center = {0.6, 0.5, 1.2}, radius = 0.5,
              material = glint.principled{ base_color = {0.9, 0.6, 0.4}, metallic = 0.5,
                                           roughness = 0.3,
                                           metallic_roughness = glint.texture.checker{
                                               even = {0, 1, 1}, odd = {0, 0.2, 0}, scale = 8 } } }
glint.sphere{ center = {1.9, 0.3, 1.2}, radius = 0.3,
              material = glint.principled{ base_color = 0.2, emission = {1.0, 0.7, 0.4},
                                           emission_strength = 4 } }
