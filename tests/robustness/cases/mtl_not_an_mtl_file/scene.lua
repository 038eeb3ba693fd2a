glint.import{ file = "mesh.obj" }
glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
