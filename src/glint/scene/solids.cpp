#include <glint/core/error.h>
#include <glint/geometry/csg/csg_node.h>
#include <glint/geometry/csg/primitives.h>
#include <glint/geometry/shape_table.h>
#include <glint/scene/import/import.h>
#include <glint/scene/solids.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <map>

namespace glint {
namespace {

using QuadricFactory = glm::dmat4 (*)(const Params&);

// Lengths of quadric solids (semi-axes, radius, height) lie in [1e-6, 1e6]: the quadric's
// matrix holds their inverse squares, and beyond this range the solid is numerically
// degenerate (a near-zero axis makes hits and normals that are not finite).
constexpr double kSmallestLength = 1e-6, kLargestLength = 1e6;
constexpr double kSmallestCoefficientRatio = 1e-24;  // (kSmallestLength / kLargestLength)^2

double positive(const Params& p, const char* name) {
    const float v = p.get_float(name, 1.0f);
    if (!(v >= kSmallestLength && v <= kLargestLength)) {
        p.fail_at(name, fmt::format("'{}' must be in [{:g}, {:g}], got {:g}", name, kSmallestLength,
                                    kLargestLength, v));
    }
    return v;
}

const std::map<std::string, QuadricFactory>& quadric_factories() {
    static const std::map<std::string, QuadricFactory> table = {
        {"ellipsoid",
         [](const Params& p) {
             return quadric_forms::ellipsoid(positive(p, "a"), positive(p, "b"), positive(p, "c"));
         }},
        {"hyperboloid_one_sheet",
         [](const Params& p) {
             return quadric_forms::hyperboloid_one_sheet(positive(p, "a"), positive(p, "b"),
                                                         positive(p, "c"));
         }},
        {"hyperboloid_two_sheets",
         [](const Params& p) {
             return quadric_forms::hyperboloid_two_sheets(positive(p, "a"), positive(p, "b"),
                                                          positive(p, "c"));
         }},
        {"elliptic_cone",
         [](const Params& p) {
             return quadric_forms::elliptic_cone(positive(p, "a"), positive(p, "b"),
                                                 positive(p, "c"));
         }},
        {"elliptic_paraboloid",
         [](const Params& p) {
             return quadric_forms::elliptic_paraboloid(positive(p, "a"), positive(p, "c"));
         }},
        {"hyperbolic_paraboloid",
         [](const Params& p) {
             return quadric_forms::hyperbolic_paraboloid(positive(p, "a"), positive(p, "c"));
         }},
        {"elliptic_cylinder",
         [](const Params& p) {
             return quadric_forms::elliptic_cylinder(positive(p, "a"), positive(p, "c"));
         }},
        {"hyperbolic_cylinder",
         [](const Params& p) {
             return quadric_forms::hyperbolic_cylinder(positive(p, "a"), positive(p, "c"));
         }},
        {"parabolic_cylinder",
         [](const Params& p) { return quadric_forms::parabolic_cylinder(positive(p, "a")); }},
        {"quadric", nullptr},  // the general form, from 'matrix'
    };
    return table;
}

// A general quadric from 16 numbers, row by row; it must be symmetric and really quadratic.
glm::dmat4 quadric_matrix(const Params& p) {
    const std::vector<double> m = p.get_numbers("matrix");
    if (m.size() != 16) p.fail("'matrix' must hold 16 numbers, row by row");
    glm::dmat4 q;
    double largest = 0.0;
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) {
            const double v = m[4 * row + col];
            if (!std::isfinite(v)) p.fail("'matrix' must be finite");
            q[col][row] = v;
            largest = std::max(largest, std::abs(v));
        }
    }
    for (int row = 0; row < 4; ++row) {
        for (int col = row + 1; col < 4; ++col) {
            if (std::abs(q[col][row] - q[row][col]) > 1e-9 * largest) {
                p.fail(fmt::format(
                    "'matrix' must be symmetric: entry ({}, {}) is {} but ({}, {}) is {}", row + 1,
                    col + 1, q[col][row], col + 1, row + 1, q[row][col]));
            }
        }
    }
    bool quadratic = false;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) quadratic |= q[col][row] != 0.0;
    }
    if (!quadratic)
        p.fail(
            "'matrix' has no quadratic terms (its upper-left 3x3 block is zero): that is a plane "
            "or nothing");
    // The surface is the same for the matrix times any positive number: scaled so that its
    // largest entry is 1, coefficients of 1e-30 give normals (the matrix times a point) that
    // are finite in float. Entries far smaller than the largest make lengths beyond what the
    // named solids accept (1e-6 to 1e6: inverse squares 1e-12 to 1e12, a ratio of 1e24).
    q /= largest;
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) {
            const double v = std::abs(q[col][row]);
            if (v != 0.0 && v < kSmallestCoefficientRatio) {
                p.fail(fmt::format(
                    "'matrix' entry ({}, {}) is {:g} times its largest: entries may differ by a "
                    "factor of at most {:g} (or be 0), so that lengths stay within [{:g}, {:g}]",
                    row + 1, col + 1, v, 1.0 / kSmallestCoefficientRatio, kSmallestLength,
                    kLargestLength));
            }
        }
    }
    return q;
}

class SolidBuilder {
public:
    SolidBuilder(const SceneDesc& desc, const std::vector<std::unique_ptr<Material>>& materials,
                 bool shortcuts)
        : m_desc(desc), m_materials(materials), m_shortcuts(shortcuts) {}

    std::shared_ptr<const Solid> build(int index, const Material* inherited, int depth = 1) {
        const SolidDesc& node = m_desc.solids.at(index);
        const Params& p = node.params;
        // The loader refuses deeper trees; a description made in C++ is checked here.
        if (depth > kMaxCsgDepth)
            p.fail(fmt::format("the CSG tree is more than {} nodes deep", kMaxCsgDepth));
        const Material* material = inherited;
        if (p.has("material"))
            material = m_materials.at(p.get_ref("material", "material").index).get();
        const Transform transform = p.get_transform("transform");
        const std::vector<Vec3> bounds = p.get_vec3_list("bounds");

        std::shared_ptr<const Solid> solid =
            node.children.empty() ? primitive(p, material) : combination(node, material, depth);
        if (p.has("bounds")) {
            if (bounds.size() != 2 || !(bounds[0].x < bounds[1].x && bounds[0].y < bounds[1].y &&
                                        bounds[0].z < bounds[1].z)) {
                p.fail(
                    "'bounds' must be {{xmin, ymin, zmin}, {xmax, ymax, zmax}} with min below max");
            }
            auto box = std::make_shared<BoxSolid>(bounds[0], bounds[1], new_part(p, material));
            solid = std::make_shared<CsgNode>(CsgOperation::kIntersection,
                                              std::vector<std::shared_ptr<const Solid>>{solid, box},
                                              m_shortcuts);
        }
        if (!transform.is_identity()) solid = std::make_shared<TransformedSolid>(solid, transform);
        p.check_all_used();
        return solid;
    }

    std::vector<const Material*> take_parts() { return std::move(m_parts); }

private:
    int new_part(const Params& p, const Material* material) {
        if (!material)
            p.fail("no material: give this solid, or a CSG node around it, a 'material'");
        m_parts.push_back(material);
        return static_cast<int>(m_parts.size()) - 1;
    }

    std::shared_ptr<const Solid> combination(const SolidDesc& node, const Material* material,
                                             int depth) {
        const std::string& type = node.params.type();
        const CsgOperation operation = type == "union"          ? CsgOperation::kUnion
                                       : type == "intersection" ? CsgOperation::kIntersection
                                                                : CsgOperation::kDifference;
        std::vector<std::shared_ptr<const Solid>> children;
        for (int child : node.children) children.push_back(build(child, material, depth + 1));
        return std::make_shared<CsgNode>(operation, std::move(children), m_shortcuts);
    }

    std::shared_ptr<const Solid> primitive(const Params& p, const Material* material) {
        const std::string& type = p.type();
        if (type == "union" || type == "intersection" || type == "difference") {
            p.fail(fmt::format("a {} needs at least one solid, e.g. glint.{}{{a, b}}", type, type));
        }
        // Read as the shapes read them (geometry/shape_table.h).
        if (type == "sphere") {
            const SphereParams sphere = read_sphere(p);
            return std::make_shared<SphereSolid>(sphere.center, sphere.radius,
                                                 new_part(p, material));
        }
        if (type == "box") {
            const BoxParams box = read_box(p);
            return std::make_shared<BoxSolid>(box.lo, box.hi, new_part(p, material));
        }
        if (type == "cylinder" || type == "cone") return capped(p, material);
        if (type == "mesh") return mesh(p, material);
        auto quadric = quadric_factories().find(type);
        if (quadric == quadric_factories().end()) p.fail("unknown solid type");
        const glm::dmat4 q = quadric->second ? quadric->second(p) : quadric_matrix(p);
        return std::make_shared<QuadricSolid>(q, type, new_part(p, material));
    }

    // A finite cylinder (centred, axis y) or cone (base at y = 0, apex at y = height): the
    // infinite quadric clipped by its bounding box, whose faces become the caps.
    std::shared_ptr<const Solid> capped(const Params& p, const Material* material) {
        const double radius = positive(p, "radius"), height = positive(p, "height");
        const int part = new_part(p, material);
        glm::dmat4 q;
        Vec3 lo, hi;
        if (p.type() == "cylinder") {
            q = quadric_forms::elliptic_cylinder(radius, radius);
            lo = Vec3(-radius, -0.5 * height, -radius);
            hi = Vec3(radius, 0.5 * height, radius);
        } else {
            // (x^2 + z^2) / r^2 = (y - h)^2 / h^2, the nappe below the apex.
            q = quadric_forms::elliptic_cone(radius, height, radius);
            q = glm::transpose(glm::inverse(
                    glm::dmat4(glm::translate(glm::dmat4(1.0), glm::dvec3(0, height, 0))))) *
                q * glm::inverse(glm::translate(glm::dmat4(1.0), glm::dvec3(0, height, 0)));
            lo = Vec3(-radius, 0.0, -radius);
            hi = Vec3(radius, height, radius);
        }
        auto surface = std::make_shared<QuadricSolid>(q, p.type(), part);
        auto box = std::make_shared<BoxSolid>(lo, hi, part);
        return std::make_shared<CsgNode>(CsgOperation::kIntersection,
                                         std::vector<std::shared_ptr<const Solid>>{surface, box},
                                         m_shortcuts);
    }

    std::shared_ptr<const Solid> mesh(const Params& p, const Material* material) {
        MeshData data;
        if (p.has("file")) {
            std::filesystem::path path = p.get_string("file");
            if (path.is_relative()) path = std::filesystem::path(m_desc.directory) / path;
            try {
                data = load_mesh_file(path.string());
            } catch (const Error& e) {
                p.fail(e.what());
            }
        } else {
            data.positions = p.get_vec3_list("vertices");
            for (double i : p.get_numbers("indices")) {
                // Checked before the conversion: a double past 2^32 does not fit a uint32_t.
                if (!(i >= 1 && i <= static_cast<double>(data.positions.size())) ||
                    i != std::floor(i)) {
                    p.fail(fmt::format("'indices' must be integers from 1 to the {} vertices",
                                       data.positions.size()));
                }
                data.indices.push_back(static_cast<uint32_t>(i) - 1);
            }
        }
        for (uint32_t i : data.indices) {
            if (i >= data.positions.size())
                p.fail(
                    fmt::format("index {} is past the {} vertices", i + 1, data.positions.size()));
        }
        try {
            return std::make_shared<MeshSolid>(data, new_part(p, material));
        } catch (const Error& e) {
            p.fail(e.what());
        }
    }

    const SceneDesc& m_desc;
    const std::vector<std::unique_ptr<Material>>& m_materials;
    bool m_shortcuts;
    std::vector<const Material*> m_parts;
};

}  // namespace

std::vector<std::string> solid_types() {
    std::vector<std::string> names = {"sphere", "box", "cylinder", "cone", "mesh"};
    for (const auto& [name, factory] : quadric_factories()) names.push_back(name);
    return names;
}

BuiltSolid build_solid(const SceneDesc& desc, int root, const Params& placement,
                       const std::vector<std::unique_ptr<Material>>& materials, bool shortcuts) {
    SolidBuilder builder(desc, materials, shortcuts);
    const Material* fallback = nullptr;
    if (placement.has("material"))
        fallback = materials.at(placement.get_ref("material", "material").index).get();
    std::shared_ptr<const Solid> solid = builder.build(root, fallback);
    BuiltSolid result;
    try {
        result.shape = std::make_unique<SolidShape>(solid, desc.solids[root].params.type());
    } catch (const Error& e) {
        desc.solids[root].params.fail(e.what());
    }
    result.part_materials = builder.take_parts();
    placement.check_all_used();
    return result;
}

}  // namespace glint
