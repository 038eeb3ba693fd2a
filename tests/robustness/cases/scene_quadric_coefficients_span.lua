-- expect-exit: 1
-- expect-message: scene_quadric_coefficients_span.lua:6: quadric: 'matrix' entry (1, 1) is 1e-30 times its largest
-- Issue 28: coefficients 30 orders of magnitude apart (a semi-axis of 1e15) are refused.
glint.camera{ eye = {0, 0, 4}, look_at = {0, 0, 0}, fov = 40 }
glint.point_light{ position = {0, 2, 3}, intensity = 10 }
glint.add(glint.solid.quadric{ matrix = { 1e-30, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, -1 } },
          { material = glint.diffuse{ reflectance = 0.5 } })
