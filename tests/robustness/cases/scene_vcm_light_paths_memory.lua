-- expect-exit: 1
-- expect-message: vcm's 16777216 light subpaths per iteration (vcm_light_paths) need
-- expect-message: available
-- env: GLINT_MEMORY_LIMIT=64M
-- Issue 28: vcm_light_paths at its maximum is estimated before anything is allocated, so a
-- machine without the memory says so instead of failing with a generic message.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
glint.render{ integrator = "vcm", vcm_light_paths = 16777216 }
