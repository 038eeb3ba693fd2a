-- expect-exit: 1
-- expect-message: the film (8x8) needs
-- expect-absent: --exposure
-- args: --exposure 80
-- env: GLINT_MEMORY_LIMIT=1K
-- Issue 28: --exposure accepts -100 to 100 stops as documented (80 was refused).
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
