// pbrt-v4 shapes to glint's: spheres stay analytic; triangle and bilinear meshes, PLY files
// (read in parallel), disks and cylinders (as fine polygon meshes of equal area) become
// glint meshes; ObjectBegin/ObjectInstance become groups and their placements.
#include <glint/core/error.h>
#include <glint/scene/import/pbrt/loop_subdivision.h>
#include <glint/scene/import/pbrt/translator.h>
#include <glint/scene/import/ply.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {

constexpr int kSegments = 64;  // polygon sides standing for a disk or cylinder

// Points on a circle of `count` segments over `phi_max` radians, with the radius scaled so
// that the polygon's area (or, for `perimeter`, its length) is the circle's.
std::vector<Vec2> ring(double radius, double phi_max, int count, bool perimeter) {
    const double step = phi_max / count;
    const double f = perimeter ? phi_max / (count * 2.0 * std::sin(step / 2.0))
                               : std::sqrt(phi_max / (count * std::sin(step)));
    std::vector<Vec2> out;
    for (int i = 0; i <= count; ++i)
        out.emplace_back(f * radius * std::cos(i * step), f * radius * std::sin(i * step));
    return out;
}

uint32_t add_vertex(MeshData& m, const Vec3& p) {
    m.positions.push_back(p);
    return static_cast<uint32_t>(m.positions.size() - 1);
}

MeshData disk_mesh(double height, double radius, double inner, double phi_max) {
    MeshData m;
    const int n = std::max(3, static_cast<int>(std::ceil(kSegments * phi_max / (2 * kPi))));
    const std::vector<Vec2> outer = ring(radius, phi_max, n, false);
    const std::vector<Vec2> in = ring(inner, phi_max, n, false);
    for (int i = 0; i < n; ++i) {
        const uint32_t a = add_vertex(m, Vec3(in[i], height)),
                       b = add_vertex(m, Vec3(outer[i], height));
        const uint32_t c = add_vertex(m, Vec3(outer[i + 1], height));
        m.indices.insert(m.indices.end(), {a, b, c});  // counter-clockwise about +z: front +z
        if (inner > 0.0) {
            const uint32_t d = add_vertex(m, Vec3(in[i + 1], height));
            m.indices.insert(m.indices.end(), {a, c, d});
        }
    }
    return m;
}

MeshData cylinder_mesh(double radius, double z0, double z1, double phi_max) {
    MeshData m;
    const int n = std::max(3, static_cast<int>(std::ceil(kSegments * phi_max / (2 * kPi))));
    const std::vector<Vec2> r = ring(radius, phi_max, n, true);
    for (int i = 0; i <= n; ++i) {
        for (double z : {z0, z1}) {
            add_vertex(m, Vec3(r[i], z));
            m.normals.push_back(glm::normalize(Vec3(r[i], 0.0f)));
        }
    }
    for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i) {
        const uint32_t a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});  // outward, as pbrt's
    }
    return m;
}

// Without "uv" each pbrt bilinear patch runs over [0, 1]^2 by itself: its corners get
// their own vertices with those uvs (the triangles come in pairs, as mesh_of makes them).
MeshData with_patch_uvs(const MeshData& shared) {
    MeshData m;
    const Vec2 corner_uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // a, b, d and c of a patch
    for (size_t t = 0; t + 5 < shared.indices.size(); t += 6) {
        const uint32_t corners[4] = {shared.indices[t], shared.indices[t + 1],
                                     shared.indices[t + 2], shared.indices[t + 5]};
        const auto base = static_cast<uint32_t>(m.positions.size());
        for (int k = 0; k < 4; ++k) {
            m.positions.push_back(shared.positions[corners[k]]);
            if (!shared.normals.empty()) m.normals.push_back(shared.normals[corners[k]]);
            m.uvs.push_back(corner_uv[k]);
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

}  // namespace

std::optional<MeshData> PbrtTranslator::mesh_of(const PbrtShape& s) {
    const PbrtEntity& e = s.entity;
    const PbrtParams& params = e.params;
    auto fail = [&](const std::string& name, const std::string& what) -> void {
        const PbrtParam* p = params.find(name);
        if (p) PbrtParams::fail(*p, what);
        throw Error(fmt::format("{}: Shape \"{}\": {}", e.where.str(), e.type, what));
    };
    MeshData m;
    if (e.type == "trianglemesh" || e.type == "bilinearmesh" || e.type == "loopsubdiv") {
        const size_t corners = e.type == "bilinearmesh" ? 4 : 3;
        m.positions = params.get_vec3s("P");
        if (m.positions.empty()) fail("P", "no vertex positions \"P\"");
        std::vector<int> indices = params.get_ints("indices");
        if (indices.empty() && m.positions.size() == corners)
            for (size_t i = 0; i < corners; ++i) indices.push_back(static_cast<int>(i));
        if (indices.empty() || indices.size() % corners != 0)
            fail("indices", fmt::format("{} indices is not a whole number of {}", indices.size(),
                                        corners == 4 ? "patches (4 each)" : "triangles (3 each)"));
        for (int i : indices)
            if (i < 0 || static_cast<size_t>(i) >= m.positions.size())
                fail("indices",
                     fmt::format("index {} is outside the {} vertices", i, m.positions.size()));
        if (e.type != "loopsubdiv") {
            m.normals = params.get_vec3s("N");
            m.uvs = params.get_vec2s("uv");
            if (!m.normals.empty() && m.normals.size() != m.positions.size())
                fail("N", fmt::format("{} normals for {} vertices", m.normals.size(),
                                      m.positions.size()));
            if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
                fail("uv", fmt::format("{} uvs for {} vertices", m.uvs.size(), m.positions.size()));
        }
        if (e.type == "loopsubdiv") {
            m.indices.assign(indices.begin(), indices.end());
            try {
                return loop_subdivide(m, params.get_int("levels", 3));
            } catch (const Error& error) {
                fail("levels", error.what());
            }
        }
        if (corners == 3) {
            m.indices.assign(indices.begin(), indices.end());
        } else {
            // Patch (p00, p10, p01, p11) as triangles (p00, p10, p11), (p00, p11, p01): the
            // front is dpdu x dpdv, as pbrt's.
            for (size_t i = 0; i < indices.size(); i += 4) {
                const uint32_t a = indices[i], b = indices[i + 1], c = indices[i + 2],
                               d = indices[i + 3];
                m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
            }
            if (m.uvs.empty()) m = with_patch_uvs(m);
        }
        return m;
    }
    if (e.type == "plymesh") {
        const std::string file = resolve(params.get_string("filename", ""));
        auto it = m_ply_meshes.find(file);
        if (it == m_ply_meshes.end()) fail("filename", "no \"filename\"");
        if (params.has("displacement")) {
            warn(e.where, "Shape", "plymesh: \"displacement\" is not supported (ignored)");
            params.find("edgelength");
            ++m_skipped["displacements"];
        }
        // The last shape to use a file takes its mesh; earlier ones copy it.
        if (--m_ply_uses[file] == 0) return std::move(it->second);
        return it->second;
    }
    if (e.type == "disk") {
        return disk_mesh(params.get_float("height", 0.0), params.get_float("radius", 1.0),
                         params.get_float("innerradius", 0.0),
                         glm::radians(std::clamp(params.get_float("phimax", 360.0), 0.0, 360.0)));
    }
    if (e.type == "cylinder") {
        return cylinder_mesh(
            params.get_float("radius", 1.0), params.get_float("zmin", -1.0),
            params.get_float("zmax", 1.0),
            glm::radians(std::clamp(params.get_float("phimax", 360.0), 0.0, 360.0)));
    }
    warn(e.where, "Shape", fmt::format("shape \"{}\" is not supported (not rendered)", e.type));
    ++m_skipped["shapes"];
    for (const PbrtParam& p : params.all()) p.used = true;
    return std::nullopt;
}

std::string PbrtTranslator::resolve(const std::string& file) const {
    std::filesystem::path path = file;
    if (path.is_relative()) path = std::filesystem::path(m_scene.directory) / path;
    return path.lexically_normal().string();
}

void PbrtTranslator::load_ply_files() {
    std::vector<std::pair<std::string, PbrtLocation>> files;
    auto collect = [&](const PbrtShape& s) {
        if (s.entity.type != "plymesh") return;
        const PbrtParam* p = s.entity.params.find("filename");
        if (!p || p->strings.size() != 1) return;
        p->used = false;  // read again where the shape is placed
        const std::string file = resolve(p->strings[0]);
        ++m_ply_uses[file];
        if (m_ply_meshes.emplace(file, MeshData{}).second) files.emplace_back(file, p->where);
    };
    for (const PbrtShape& s : m_scene.shapes) collect(s);
    for (const PbrtObject& o : m_scene.objects)
        for (const PbrtShape& s : o.shapes) collect(s);
    // Many scenes split their geometry over hundreds of PLY files: read them in parallel.
    std::vector<std::string> errors(files.size());
    std::vector<MeshData> meshes(files.size());
    tbb::parallel_for(size_t(0), files.size(), [&](size_t i) {
        try {
            meshes[i] = load_ply(files[i].first).mesh;
        } catch (const Error& error) {
            errors[i] =
                fmt::format("{}: Shape \"plymesh\": {}", files[i].second.str(), error.what());
        }
    });
    for (const std::string& error : errors)
        if (!error.empty()) throw Error(error);
    for (size_t i = 0; i < files.size(); ++i) m_ply_meshes[files[i].first] = std::move(meshes[i]);
}

Bounds3 PbrtTranslator::place_shape(const PbrtShape& s, int group, const Transform& transform) {
    const PbrtEntity& e = s.entity;
    Bounds3 bounds;
    if (const std::optional<PbrtValue> alpha = scalar(e, "alpha")) {
        if (!alpha->is_texture() && alpha->constant.x <= 0.0f) return bounds;  // pbrt skips it
        if (alpha->is_texture() || alpha->constant.x < 1.0f) {
            warn(e.where, "Shape", "\"alpha\" cut-outs are not supported (rendered opaque)");
            ++m_skipped["alpha cut-outs"];
        }
    }
    std::optional<ObjectRef> material = this->material(s.material, e.where);
    if (!material) {
        for (const PbrtParam& p : e.params.all()) p.used = true;
        ++m_skipped["interface shapes (media boundaries)"];
        return bounds;
    }
    const bool emits = s.area_light && group == 0;
    if (s.area_light && group != 0) {
        warn(s.area_light->where, "AreaLightSource",
             "area lights in object instances are ignored, as pbrt-v4 does");
    }
    if (e.type == "sphere") {
        const double radius = e.params.get_float("radius", 1.0);
        if (e.params.get_float("zmin", -radius) > -radius ||
            e.params.get_float("zmax", radius) < radius ||
            e.params.get_float("phimax", 360.0) < 360.0) {
            warn(e.where, "Shape", "a partial sphere (zmin, zmax, phimax) is rendered whole");
            ++m_skipped["partial spheres"];
        }
        if (emits) {
            if (s.reverse_orientation)
                warn(e.where, "Shape", "an emitting sphere with ReverseOrientation emits outwards");
            const double scale = std::cbrt(std::abs(glm::determinant(Mat3(transform.matrix()))));
            material =
                area_light_material(*s.area_light, 4.0 * kPi * radius * radius * scale * scale);
            if (!material) material = this->material(s.material, e.where);
        }
        Params p("sphere", where(e.where));
        p.set("radius", radius);
        p.set("material", *material);
        // pbrt's sphere runs u around its z axis (from +x towards +y) and v from -z to +z;
        // glint's around y (from +x towards +z) and from -y to +y: glint's sphere is placed
        // with y and z swapped so that textures land where pbrt puts them.
        const Mat4 swap_yz(Vec4(1, 0, 0, 0), Vec4(0, 0, 1, 0), Vec4(0, 1, 0, 0), Vec4(0, 0, 0, 1));
        p.set("transform", Transform(transform.matrix() * swap_yz));
        check_unused(e, "Shape");
        m_desc.groups.at(group).shapes.push_back(std::move(p));
        const Vec3 r(static_cast<float>(radius));
        return Bounds3{-r, r}.transformed(transform);
    }
    std::optional<MeshData> mesh = mesh_of(s);
    check_unused(e, "Shape");
    if (!mesh) return bounds;
    if (s.reverse_orientation) {
        for (size_t t = 0; t < mesh->indices.size(); t += 3)
            std::swap(mesh->indices[t + 1], mesh->indices[t + 2]);
        for (Vec3& n : mesh->normals) n = -n;
    }
    for (const Vec3& p : mesh->positions) bounds.expand(transform.point(p));
    if (emits) {
        // pbrt-v4 gives "power" to each of its shapes: every triangle of a triangle mesh
        // or PLY file, every patch (two triangles) of a bilinear mesh, a whole disk or
        // cylinder.
        const bool by_power = s.area_light->params.has("power");
        const bool whole = e.type == "disk" || e.type == "cylinder";
        const double per_element = e.type == "bilinearmesh" ? 2.0 : 1.0;
        const double triangles = static_cast<double>(mesh->indices.size() / 3);
        const double area = !by_power ? 0.0
                            : whole   ? mean_triangle_area(*mesh, transform, e, false) * triangles
                                      : per_element * mean_triangle_area(*mesh, transform, e, true);
        material = area_light_material(*s.area_light, area);
        if (!material) material = this->material(s.material, e.where);
    }
    add_mesh_shape(m_desc, group, std::move(*mesh), *material, transform, where(e.where));
    return bounds;
}

// pbrt-v4 makes each triangle a shape with an area light of its own, so "power" is the
// power of every triangle; glint's emissive material is one radiance for the mesh, which is
// right when the triangles are of equal area (a quad's two, a regular tessellation).
double PbrtTranslator::mean_triangle_area(const MeshData& mesh, const Transform& transform,
                                          const PbrtEntity& e, bool warn_if_uneven) {
    double total = 0.0, smallest = INFINITY, largest = 0.0;
    const size_t count = mesh.indices.size() / 3;
    for (size_t t = 0; t < count; ++t) {
        const Vec3 a = transform.point(mesh.positions[mesh.indices[3 * t]]);
        const Vec3 b = transform.point(mesh.positions[mesh.indices[3 * t + 1]]);
        const Vec3 c = transform.point(mesh.positions[mesh.indices[3 * t + 2]]);
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        total += area;
        smallest = std::min(smallest, area);
        largest = std::max(largest, area);
    }
    if (count == 0) return 0.0;
    if (warn_if_uneven && largest > 1.01 * smallest)
        warn(e.where, "AreaLightSource",
             "\"power\" on triangles of different areas: pbrt-v4 gives "
             "each triangle that power, glint their mean radiance");
    return total / static_cast<double>(count);
}

void PbrtTranslator::shapes() {
    load_ply_files();
    for (const PbrtShape& s : m_scene.shapes)
        m_bounds.expand(place_shape(s, 0, glint_transform(s.to_world)));
}

void PbrtTranslator::instances() {
    std::map<std::string, std::pair<int, Bounds3>> groups;
    for (const PbrtInstance& inst : m_scene.instances) {
        auto it = groups.find(inst.object);
        if (it == groups.end()) {
            const PbrtObject* object = nullptr;
            for (const PbrtObject& o : m_scene.objects)
                if (o.name == inst.object) object = &o;
            if (!object)
                throw Error(fmt::format("{}: ObjectInstance \"{}\": no object of that name",
                                        inst.where.str(), inst.object));
            m_desc.groups.push_back(GroupDesc{where(object->where), {}, {}});
            const int group = static_cast<int>(m_desc.groups.size()) - 1;
            Bounds3 bounds;
            for (const PbrtShape& s : object->shapes)
                bounds.expand(place_shape(s, group, Transform(s.to_world)));
            it = groups.emplace(inst.object, std::make_pair(group, bounds)).first;
        }
        const Transform placement = glint_transform(inst.to_world);
        if (glm::abs(glm::determinant(Mat3(placement.matrix()))) < 1e-30f)
            throw Error(fmt::format("{}: ObjectInstance: the transform is not invertible",
                                    inst.where.str()));
        m_desc.groups[0].instances.push_back(
            InstanceDesc{it->second.first, placement, where(inst.where)});
        if (!it->second.second.is_empty())
            m_bounds.expand(it->second.second.transformed(placement));
    }
}

}  // namespace glint
