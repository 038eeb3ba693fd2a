-- Appearance (issue 4): image textures on a sphere, a cube and an OBJ torus (its uvs from
-- the file); a tiled checkerboard floor whose left half is looked up without mipmaps (it
-- shimmers into moire towards the horizon) and whose right half is mipmapped; wood and
-- marble; two bump-mapped planets; a normal-mapped tiled wall; rough gold, copper and
-- aluminium and rough glass; all lit by a lat-long sky (image-based lighting), which is
-- also what you see behind the scene. The camera looks along -z: +x is on the right.
-- The images come from scripts/make-example-textures.sh (nothing is downloaded).
--   build/glint render examples/textures.lua
--   build/glint render examples/textures.lua --no-mipmap     (both floor halves alias)
glint.render{ width = 640, height = 360, spp = 64, max_depth = 8,
              output = {"textures.exr", "textures.png"} }
glint.camera{ eye = {0, 3.4, 8.5}, look_at = {0, 0.4, -0.2}, fov = 38 }
glint.environment{ file = "textures/sky.exr", rotation = 0, intensity = 0.3 }

-- Floor: 8 x 8 checker image, repeated every 2 m. Left half not mipmapped, right half
-- mipmapped (anisotropic filtering over each pixel's footprint).
local function checker_floor(mipmap)
    return glint.texture.image{ file = "textures/checker.png", scale = 100, mipmap = mipmap }
end
local far = 200
glint.quad{ vertices = {{-far, 0, far}, {0, 0, far}, {0, 0, -far}, {-far, 0, -far}},
            material = glint.diffuse{ reflectance = checker_floor(false) } }
glint.quad{ vertices = {{0, 0, far}, {far, 0, far}, {far, 0, -far}, {0, 0, -far}},
            material = glint.diffuse{ reflectance = checker_floor(true) } }

-- A wall of bevelled tiles: flat geometry, relief from a tangent-space normal map.
local tiles = glint.texture.image{ file = "textures/tiles-normal.png", encoding = "linear",
                                   scale = {4, 1.5} }
glint.quad{ vertices = {{-4, 0, -2.4}, {4, 0, -2.4}, {4, 3, -2.4}, {-4, 3, -2.4}},
            material = glint.diffuse{ reflectance = {0.75, 0.72, 0.66}, normal_map = tiles } }

-- Front row: the uv test grid on a sphere, a cube and a torus, under a glossy coat.
local grid = glint.texture.image{ file = "textures/uv-grid.png" }
local coated_grid = glint.plastic{ diffuse = grid, roughness = 0.15 }
glint.sphere{ center = {-2.4, 0.45, 1.6}, radius = 0.45, material = coated_grid }
glint.box{ min = {-0.4, 0, -0.4}, max = {0.4, 0.8, 0.4}, material = coated_grid,
           transform = glint.translate(-1.2, 0, 1.6) * glint.rotate(30, 0, 1, 0) }
glint.mesh{ file = "textures/torus.obj", material = coated_grid,
            transform = glint.translate(0, 0.55, 1.6) * glint.rotate(60, 1, 0, 0) * glint.scale(0.7) }

-- Wood (rings about the object's y axis) and marble (veins from turbulence), evaluated in
-- object space: move the objects and the grain moves with them.
local wood = glint.texture.wood{ rings = 9, scale = 1 }
glint.box{ min = {-0.35, 0, -0.35}, max = {0.35, 0.7, 0.35},
           material = glint.plastic{ diffuse = wood, roughness = 0.3 },
           transform = glint.translate(1.2, 0, 1.6) * glint.rotate(-20, 0, 1, 0) }
glint.sphere{ center = {2.4, 0.45, 1.6}, radius = 0.45,
              material = glint.plastic{ diffuse = glint.texture.marble{ scale = 2.5 }, roughness = 0.05 } }

-- Back row: two bump-mapped planets, rough metals and rough glass.
local relief = glint.texture.fbm{ scale = 4, octaves = 6 }
local planet_colour = glint.texture.fbm{ scale = 4, octaves = 6,
                                         low = {0.05, 0.15, 0.45}, high = {0.55, 0.45, 0.3} }
glint.sphere{ center = {-3.0, 0.5, -1.0}, radius = 0.5,
              material = glint.diffuse{ reflectance = planet_colour, bump = relief, bump_scale = 0.06 } }
glint.sphere{ center = {-1.8, 0.5, -1.0}, radius = 0.5,
              material = glint.diffuse{ reflectance = {0.6, 0.35, 0.25},
                                        bump = glint.texture.turbulence{ scale = 6, octaves = 5 },
                                        bump_scale = 0.02 } }
glint.sphere{ center = {-0.6, 0.5, -1.0}, radius = 0.5, material = glint.conductor{ preset = "gold", roughness = 0.25 } }
glint.sphere{ center = {0.6, 0.5, -1.0}, radius = 0.5, material = glint.conductor{ preset = "copper", roughness = 0.1 } }
glint.sphere{ center = {1.8, 0.5, -1.0}, radius = 0.5, material = glint.conductor{ preset = "aluminium", roughness = 0.4 } }
glint.sphere{ center = {3.0, 0.5, -1.0}, radius = 0.5,
              material = glint.dielectric{ ior = 1.5, roughness = 0.15, absorption = {0.6, 0.25, 0.1} } }
