local lib = require("lib")
lib.ball(glint.diffuse{})
