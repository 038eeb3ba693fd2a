glint.sphere{ radius = 1, material = glint.diffuse{} }
local shapes = require("shapes")
