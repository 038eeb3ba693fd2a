-- expect-exit: 1
-- expect-message: scene_translate_nan.lua:7:
-- expect-message: glint.translate: 'x' must be a finite number
local m = glint.diffuse{}
glint.sphere{ radius = 1, material = m }
glint.point_light{ position = {0, 5, 5}, intensity = 10 }
glint.place(glint.group(), glint.translate(0/0, 0, 0))
