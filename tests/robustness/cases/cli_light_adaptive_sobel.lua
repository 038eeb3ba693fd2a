-- expect-exit: 2
-- expect-message: --adaptive: integrator 'light' has no adaptive sampling (adaptive 'sobel')
-- args: --integrator light --adaptive sobel
-- Issue 28: 'light' accepted adaptive = "sobel" silently (its paths splat anywhere).
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
