-- The nine quadric forms, each an infinite solid made finite by a 'bounds' box (whose
-- faces become flat caps), in a 3x3 grid. Every form has its axis along y and is inside
-- where x^T Q x <= 0; see docs/scene-language.md for the equations.
--   back row:   ellipsoid              hyperboloid of one sheet   hyperboloid of two sheets
--   middle row: elliptic cone          elliptic paraboloid        hyperbolic paraboloid
--   front row:  elliptic cylinder      hyperbolic cylinder        parabolic cylinder
-- The paraboloids and the parabolic cylinder are turned upside down (their curved side
-- up, towards the light). Lit by a square area light above.
local function colour(r, g, b) return glint.diffuse{ reflectance = {r, g, b} } end
local floor = glint.diffuse{ reflectance = 0.55 }

glint.camera{ eye = {0, 11, 12.5}, look_at = {0, 0.3, 0.4}, fov = 42 }
glint.render{ width = 640, height = 480, spp = 32, output = {"quadrics.exr", "quadrics.png"} }
glint.background{ radiance = 0.1 }

glint.quad{ vertices = {{-30, 0, -30}, {-30, 0, 30}, {30, 0, 30}, {30, 0, -30}}, material = floor }
glint.quad{ vertices = {{-2.5, 10, -2.5}, {2.5, 10, -2.5}, {2.5, 10, 2.5}, {-2.5, 10, 2.5}},
            material = glint.emissive{ radiance = 10 } }

-- Grid cell (column, row) from the back left, lifted by `lift` so the solid stands on the
-- floor; `turn` is applied first, in the solid's own space.
local spacing = 4
local function cell(column, row, lift, turn)
    local xf = glint.translate(spacing * (column - 2), lift, spacing * (row - 2))
    if turn then xf = xf * turn end
    return xf
end
local upside_down = glint.rotate(180, {1, 0, 0})

-- Back row.
glint.add(glint.solid.ellipsoid{ a = 1.4, b = 0.9, c = 1.0, material = colour(0.8, 0.15, 0.12),
                                 transform = cell(1, 1, 0.9) })
glint.add(glint.solid.hyperboloid_one_sheet{
    a = 0.5, b = 0.7, c = 0.5, bounds = {{-2, -1, -2}, {2, 1, 2}},
    material = colour(0.85, 0.45, 0.1), transform = cell(2, 1, 1) })
glint.add(glint.solid.hyperboloid_two_sheets{
    a = 0.45, b = 0.45, c = 0.45, bounds = {{-2, -1.2, -2}, {2, 1.2, 2}},
    material = colour(0.8, 0.7, 0.1), transform = cell(3, 1, 1.2) })

-- Middle row.
glint.add(glint.solid.elliptic_cone{
    a = 0.8, b = 1, c = 0.8, bounds = {{-2, -1, -2}, {2, 1, 2}},
    material = colour(0.3, 0.65, 0.15), transform = cell(1, 2, 1) })
glint.add(glint.solid.elliptic_paraboloid{
    a = 0.7, c = 0.7, bounds = {{-2, 0, -2}, {2, 1.8, 2}},
    material = colour(0.1, 0.6, 0.5), transform = cell(2, 2, 1.8, upside_down) })
glint.add(glint.solid.hyperbolic_paraboloid{
    a = 1.4, c = 1.4, bounds = {{-1.2, -1, -1.2}, {1.2, 1, 1.2}},
    material = colour(0.15, 0.45, 0.8),
    transform = cell(3, 2, 1, glint.rotate(45, {0, 1, 0}) * upside_down) })

-- Front row.
glint.add(glint.solid.elliptic_cylinder{
    a = 1.2, c = 0.7, bounds = {{-2, -0.8, -2}, {2, 0.8, 2}},
    material = colour(0.35, 0.25, 0.75), transform = cell(1, 3, 0.8) })
glint.add(glint.solid.hyperbolic_cylinder{
    a = 0.4, c = 0.5, bounds = {{-1.3, -0.8, -1.3}, {1.3, 0.8, 1.3}},
    material = colour(0.65, 0.2, 0.6), transform = cell(2, 3, 0.8) })
glint.add(glint.solid.parabolic_cylinder{
    a = 0.8, bounds = {{-1.3, 0, -1}, {1.3, 1.6, 1}},
    material = colour(0.75, 0.3, 0.4), transform = cell(3, 3, 1.6, upside_down) })
