-- expect-exit: 1
-- expect-message: scene_mesh_index_wraps.lua:7:
-- expect-message: 'indices' must be integers from 1 to the 3 vertices
-- 2^32 + 1 would wrap to 1 in a 32-bit index (and converting it is undefined behaviour).
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0} }
glint.point_light{ position = {0, 2, 2}, intensity = 10 }
glint.mesh{ vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
            indices = {1, 2, 4294967297}, material = glint.diffuse{} }
