-- CSG benchmark: an 8x8 grid of machined parts, each built from infinite quadrics
-- (cylinders, cones, paraboloids, hyperboloids) that only a finite bounding solid per part
-- makes finite, with holes drilled by further infinite quadrics. bench/run renders it with
-- the CSG bounding-box shortcuts on and off. Two environment variables choose, so that
-- every run is the same script:
--   GLINT_CSG_SHORTCUTS  "1" (default) or "0": the render setting csg_shortcuts
--   GLINT_CSG_LAYOUT     "rows" (default): each row of 8 parts is one CSG union, one object
--                        for Embree, as in a model built as a single CSG tree; "parts":
--                        every part is its own object, so Embree's hierarchy already skips
--                        the parts a ray does not come near
local shortcuts = (os.getenv("GLINT_CSG_SHORTCUTS") or "1") ~= "0"
local layout = os.getenv("GLINT_CSG_LAYOUT") or "rows"
assert(layout == "rows" or layout == "parts", "GLINT_CSG_LAYOUT must be 'rows' or 'parts'")

glint.camera{ eye = {0, 14, 17}, look_at = {0, 0, 0.5}, fov = 40 }
glint.render{ width = 320, height = 240, spp = 16, seed = 1, csg_shortcuts = shortcuts }
glint.background{ radiance = 0.15 }

glint.quad{ vertices = {{-30, 0, -30}, {-30, 0, 30}, {30, 0, 30}, {30, 0, -30}},
            material = glint.diffuse{ reflectance = 0.5 } }
glint.quad{ vertices = {{-3, 12, -3}, {3, 12, -3}, {3, 12, 3}, {-3, 12, 3}},
            material = glint.emissive{ radiance = 8 } }

local s = glint.solid
local upside_down = glint.rotate(180, {1, 0, 0})
local across = glint.rotate(90, {0, 0, 1})     -- a y-axis form turned to lie along x
local lengthwise = glint.rotate(90, {1, 0, 0}) -- ... or along z

-- Four kinds of part, each about 1.6 across, standing on the floor where `place` puts it.
local kinds = {
    -- A barrel: a cylinder meeting a hyperboloid waist, in a sphere, drilled across.
    function(m, place)
        return glint.difference{
            glint.intersection{ s.elliptic_cylinder{ a = 0.7, c = 0.7 },
                                s.hyperboloid_one_sheet{ a = 0.55, b = 0.8, c = 0.55 },
                                s.sphere{ center = {0, 0, 0}, radius = 0.8 } },
            s.elliptic_cylinder{ a = 0.2, c = 0.2, transform = across },
            material = m, transform = place * glint.translate(0, 0.8, 0) }
    end,
    -- A bullet: a paraboloid nose inside a cone, cut to a box.
    function(m, place)
        return glint.intersection{
            s.elliptic_paraboloid{ a = 0.6, c = 0.6, transform = upside_down },
            s.elliptic_cone{ a = 0.6, b = 1, c = 0.6, transform = glint.translate(0, 1.2, 0) *
                                                                  upside_down },
            s.box{ min = {-0.8, -1.6, -0.8}, max = {0.8, 0, 0.8} },
            material = m, transform = place * glint.translate(0, 1.6, 0) }
    end,
    -- A cross of two cylinders (a Steinmetz solid) in a sphere, minus a cone pocket.
    function(m, place)
        return glint.difference{
            glint.intersection{ s.elliptic_cylinder{ a = 0.75, c = 0.75, transform = across },
                                s.elliptic_cylinder{ a = 0.75, c = 0.75, transform = lengthwise },
                                s.sphere{ radius = 0.85 } },
            s.elliptic_cone{ a = 0.5, b = 1, c = 0.5, transform = glint.translate(0, 0.2, 0) },
            material = m, transform = place * glint.translate(0, 0.75, 0) }
    end,
    -- A saddle block with a hyperbolic slot and a drilled hole.
    function(m, place)
        return glint.difference{
            glint.intersection{ s.hyperbolic_paraboloid{ a = 1, c = 1, transform = upside_down },
                                s.hyperbolic_cylinder{ a = 0.5, c = 0.6 },
                                s.box{ min = {-0.8, -1.2, -0.8}, max = {0.8, 0.6, 0.8} } },
            s.elliptic_cylinder{ a = 0.15, c = 0.15, transform = lengthwise },
            material = m, transform = place * glint.translate(0, 1.2, 0) }
    end,
}

local n, spacing = 8, 2.2
for i = 0, n - 1 do
    local row = {}
    for j = 0, n - 1 do
        local hue = (i * n + j) / (n * n)
        local m = glint.diffuse{ reflectance = {0.25 + 0.6 * hue, 0.5, 0.85 - 0.6 * hue} }
        local place = glint.translate(spacing * (i - (n - 1) / 2), 0, spacing * (j - (n - 1) / 2)) *
                      glint.rotate(37 * (i * n + j), {0, 1, 0})
        row[#row + 1] = kinds[(i + 2 * j) % #kinds + 1](m, place)
    end
    if layout == "rows" then
        glint.add(glint.union(row))
    else
        for _, part in ipairs(row) do glint.add(part) end
    end
end
