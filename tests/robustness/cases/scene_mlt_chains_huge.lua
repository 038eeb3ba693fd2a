-- expect-exit: 1
-- expect-message: scene_mlt_chains_huge.lua:9: render: 'mlt_bootstrap' must be at least 1
-- expect-absent: must be an integer
-- Issue 28: an integer above 2e9 but within an int's range is an integer ('mlt_chains' was
-- called "not an integer"); the bootstrap's error, read after it, ends the run at once.
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.sphere{ center = {0, 0, 0}, radius = 0.5, material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
glint.render{ integrator = "mlt", mlt_chains = 2100000000, mlt_bootstrap = 0 }
