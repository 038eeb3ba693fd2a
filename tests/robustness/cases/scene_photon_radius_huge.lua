-- expect-exit: 1
-- expect-message: scene_photon_radius_huge.lua:7:
-- expect-message: 'photon_radius' must be in [0, 1e12]
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.render{ integrator = 'sppm', photon_radius = 1e30 }
