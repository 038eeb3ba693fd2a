glint.sphere{ radius = 1, material = glint.diffuse{} }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ output = "out.jpg" }
