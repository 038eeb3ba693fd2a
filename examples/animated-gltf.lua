-- A glTF animation as motion blur: examples/gltf/mover.glb, written by Blender 3.4's glTF
-- exporter from scripts/blender_animation.py (a cube that moves from the origin to (2, 1, 0)
-- and turns 90 degrees between frames 1 and 25 at 24 fps, eased in and out). The import
-- plays frames 10 to 16 over the shutter: Blender writes frame f at time f / 24, so the
-- window is {10 / 24, 16 / 24} seconds, the fastest part of the move.
glint.camera{ eye = {1, 2.5, 6}, look_at = {1, 0.5, 0}, fov = 40, shutter = {0, 1} }
glint.render{ width = 320, height = 200, spp = 32,
              output = {"animated-gltf.exr", "animated-gltf.png"} }
glint.background{ radiance = {0.1, 0.12, 0.16} }
glint.point_light{ position = {2, 5, 4}, intensity = 60 }

glint.quad{ vertices = {{-5, -0.5, -5}, {-5, -0.5, 5}, {5, -0.5, 5}, {5, -0.5, -5}},
            material = glint.diffuse{ reflectance = 0.6 } }
-- The exported cube has the default grey material of Blender's glTF export; a red one here.
glint.import{ file = "gltf/mover.glb", animation = {10 / 24, 16 / 24},
              material = glint.diffuse{ reflectance = {0.8, 0.2, 0.15} } }
