glint.camera{ eye = {0, 0, 3}, look_at = {0, 0, 0}, fov = 40 }
glint.mesh{ file = "mesh.obj", material = glint.diffuse{ reflectance = 0.5 } }
glint.point_light{ position = {0, 2, 2}, intensity = 5 }
