-- expect-exit: 2
-- expect-message: --debug: unknown debug view 'bogus'
-- args: --debug bogus
-- Issue 28: a flag's bad value is a usage error, exit 2.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
