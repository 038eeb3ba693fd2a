-- A light probe as a photographer makes it: the example sky photographed in a mirrored
-- ball (textures/sky-mirror-ball.exr, 128 x 128, written from textures/sky.exr by
-- scripts/make-example-textures.sh), given with mapping = "mirror_ball". glint turns it
-- into a lat-long map once, at load. The ball's centre reflects the camera's side (+z),
-- its rim what lay behind the ball (-z), where a single ball sees least: the probe is
-- turned half a turn so that this blind spot lies behind our camera, which looks along -z.
-- The same scene with mapping = "latlong" and textures/sky.exr (rotation 180) renders the
-- same light (tests/light/test_environment_mapping.cpp checks this for every mapping).
--   build/glint render examples/light-probe.lua
glint.render{ width = 320, height = 180, spp = 32, max_depth = 6,
              output = {"light-probe.exr", "light-probe.png"} }
glint.camera{ eye = {0, 1.6, 5.5}, look_at = {0, 0.6, 0}, fov = 35 }
glint.environment{ file = "textures/sky-mirror-ball.exr", mapping = "mirror_ball",
                   rotation = 180, intensity = 0.3 }

glint.quad{ vertices = {{-20, 0, 20}, {20, 0, 20}, {20, 0, -20}, {-20, 0, -20}},
            material = glint.diffuse{ reflectance = 0.5 } }
glint.sphere{ center = {-1.4, 0.6, 0}, radius = 0.6, material = glint.mirror{} }
glint.sphere{ center = {0, 0.6, 0}, radius = 0.6,
              material = glint.principled{ base_color = {0.8, 0.2, 0.1}, roughness = 0.3 } }
glint.sphere{ center = {1.4, 0.6, 0}, radius = 0.6,
              material = glint.principled{ base_color = {1.0, 0.77, 0.34}, metallic = 1,
                                           roughness = 0.25 } }
