-- expect-exit: 1
-- expect-message: scene_light_adaptive_sobel.lua:7: integrator 'light' has no adaptive sampling
-- Issue 28: the same, set by the scene: an error at its line, exit 1.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
glint.render{ integrator = "light", adaptive = "sobel" }
