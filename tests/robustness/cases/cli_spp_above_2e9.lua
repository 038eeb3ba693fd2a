-- expect-exit: 1
-- expect-message: the film (8x8) needs
-- expect-absent: not an integer
-- expect-absent: must be an integer
-- args: --spp 2100000000
-- env: GLINT_MEMORY_LIMIT=1K
-- Issue 28: --spp 2100000000 is within 1 to 2^31 - 1; a memory budget of 1 KiB ends the
-- run right after the settings are read.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
