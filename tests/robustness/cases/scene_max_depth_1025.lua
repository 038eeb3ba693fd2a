-- expect-exit: 1
-- expect-message: scene_max_depth_1025.lua:7:
-- expect-message: 'max_depth' must be -1
glint.sphere{ radius = 5, material = glint.mirror{} }
glint.camera{ eye = {0, 0, 0}, look_at = {0, 0, -1} }
glint.point_light{ position = {0, 1, 0}, intensity = 1 }
glint.render{ max_depth = 1025 }
