-- expect-exit: 2
-- expect-message: --adaptive
-- expect-message: integrator 'preview' has no adaptive sampling
-- args: --integrator preview --adaptive sobel
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
