#include <glint/core/cancel.h>
#include <glint/core/error.h>
#include <glint/core/file_access.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/gltf.h>
#include <glint/scene/import/keyframe_curve.h>

#include <fmt/format.h>
#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace glint {
namespace {

namespace fs = std::filesystem;

// tinygltf decodes every image with stb_image by default; glint's texture system reads the
// files itself, so the loader only keeps the encoded bytes (as_is) of embedded images.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->as_is = true;
    image->image.assign(bytes, bytes + std::max(size, 0));
    return true;
}

std::string percent_decoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

// JSON arrays and objects nested deeper than this are refused before tinygltf parses the
// text: its parser recurses once per level, and ~10^4 levels overflow the stack. glTF's own
// structure needs fewer than ten; `extras` may hold more, but not hundreds.
constexpr int kMaxJsonDepth = 256;

// The deepest nesting of arrays and objects in `json` (brackets inside strings skipped), or
// the byte offset where it first passes kMaxJsonDepth.
struct JsonDepth {
    int depth = 0;
    size_t too_deep_at = std::string::npos;
};

JsonDepth json_depth(std::string_view json) {
    JsonDepth result;
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            result.depth = std::max(result.depth, ++depth);
            if (depth > kMaxJsonDepth) {
                result.too_deep_at = i;
                return result;
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return result;
}

// The files a glTF file refers to (buffers, images) are read through these callbacks instead
// of tinygltf's own: only regular files (a FIFO would block for ever), only inside the glTF
// file's folder (a model from elsewhere must not read the user's other files), and names
// taken as they are (tinygltf's default expands them like a shell).
struct ReferencedFiles {
    std::string folder;
    bool confined = true;
};

std::string as_given(const std::string& path, void*) {
    return path;
}

// Any file that exists counts as found, so that reading it gives the reason it is refused
// (outside the folder, a FIFO, a directory) rather than tinygltf's "File not found".
bool referenced_file_exists(const std::string& path, void*) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0;
}

bool read_referenced_file(std::vector<unsigned char>* out, std::string* error,
                          const std::string& path, void* user) {
    const auto& files = *static_cast<ReferencedFiles*>(user);
    if (files.confined && !is_inside_folder(files.folder, path)) {
        if (error)
            *error += fmt::format(
                "'{}' lies outside the glTF file's folder, where the files it "
                "refers to must be\n",
                path);
        return false;
    }
    try {
        const std::string bytes = read_regular_file(path, "file");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const std::exception& e) {
        if (error) *error += std::string(e.what()) + "\n";
        return false;
    }
}

bool refuse_writing(std::string* error, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (error) *error += "glint writes no glTF files\n";
    return false;
}

// A node's translation, rotation and scale (glTF's TRS), from the node or an animation.
struct NodePose {
    Vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    Vec3 scale{1.0f};

    Mat4 matrix() const {
        return glm::translate(Mat4(1.0f), translation) * glm::mat4_cast(rotation) *
               glm::scale(Mat4(1.0f), scale);
    }
};

NodePose node_pose(const tinygltf::Node& node) {
    NodePose pose;
    if (node.translation.size() == 3)
        pose.translation = Vec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.rotation.size() == 4) {
        pose.rotation = glm::normalize(
            glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
    }
    if (node.scale.size() == 3) pose.scale = Vec3(node.scale[0], node.scale[1], node.scale[2]);
    return pose;
}

// The curves of one animated node (glTF's channels that target it).
struct NodeAnimation {
    std::optional<KeyframeCurve> translation, rotation, scale;

    NodePose at(NodePose pose, float time) const {
        float v[4];
        if (translation) {
            translation->evaluate(time, v);
            pose.translation = Vec3(v[0], v[1], v[2]);
        }
        if (rotation) {
            rotation->evaluate(time, v);
            pose.rotation = glm::quat(v[3], v[0], v[1], v[2]);
        }
        if (scale) {
            scale->evaluate(time, v);
            pose.scale = Vec3(v[0], v[1], v[2]);
        }
        return pose;
    }
};

// Motion keys taken from an animation over a time window: enough that a shutter's arc of a
// turning or accelerating node is followed closely (glint interpolates between keys).
constexpr int kAnimationKeys = 17;

Mat4 node_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        Mat4 m;  // glTF stores column-major, as glm does
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = static_cast<float>(node.matrix[i]);
        return m;
    }
    Mat4 m(1.0f);
    if (node.translation.size() == 3) {
        m = glm::translate(m, Vec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (node.rotation.size() == 4) {
        const glm::quat q(
            static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
            static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3)
        m = glm::scale(m, Vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// The extensions glint follows (docs/scene-language.md, "glTF"); a file that requires
// another one is refused, as the specification asks.
bool is_supported_extension(const std::string& name) {
    static const std::set<std::string> supported = {
        "KHR_lights_punctual",        "KHR_materials_emissive_strength",
        "KHR_materials_specular",     "KHR_materials_ior",
        "KHR_materials_transmission", "KHR_materials_volume",
        "KHR_materials_clearcoat",    "KHR_materials_sheen",
        "KHR_materials_dispersion",   "KHR_texture_transform"};
    return supported.count(name) > 0;
}

class GltfImporter {
public:
    GltfImporter(SceneDesc& desc, const ImportTarget& target) : m_desc(desc), m_target(target) {}

    Bounds3 run() {
        load();
        if (m_model.scenes.empty()) {
            // A file without scenes still holds its nodes: take the roots.
            std::vector<bool> is_child(m_model.nodes.size(), false);
            for (const tinygltf::Node& n : m_model.nodes)
                for (int c : n.children)
                    if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[c] = true;
            for (size_t i = 0; i < m_model.nodes.size(); ++i)
                if (!is_child[i]) m_roots.push_back(static_cast<int>(i));
        } else {
            const int scene = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
            if (static_cast<size_t>(scene) >= m_model.scenes.size())
                fail(fmt::format("the default scene {} does not exist", scene));
            m_roots = m_model.scenes[scene].nodes;
        }
        // First pass: how often each mesh is placed, so that repeated meshes become one
        // group placed several times (Embree instances) instead of copies.
        std::vector<int> path;
        for (int root : m_roots) count_uses(root, path);
        read_animation();
        const std::vector<Mat4> placed(m_key_times.size(), m_target.transform.matrix());
        for (int root : m_roots) visit(root, placed, path);
        return m_bounds;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(fmt::format("{}: {}", m_target.path, what));
    }

    void warn(const std::string& what) {
        m_desc.warnings.push_back(fmt::format("{}: {}", origin(), what));
    }

    // "script:line: file" for messages about the file's content; just the file when the
    // file is the scene (`glint render model.glb`).
    std::string origin() const {
        if (m_target.where == m_target.path) return m_target.path;
        return fmt::format("{}: {}", m_target.where, m_target.path);
    }

    void load() {
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(keep_image_bytes, nullptr);
        std::string error, warning;
        std::string ext = fs::path(m_target.path).extension().string();
        const bool binary = ext == ".glb" || ext == ".GLB";
        m_directory = fs::path(m_target.path).parent_path();
        const std::string bytes = read_file_bytes(m_target.path, binary ? "GLB" : "glTF");
        if (binary) check_glb(bytes);
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        const auto size = static_cast<unsigned int>(bytes.size());
        const std::string base = m_directory.empty() ? std::string(".") : m_directory.string();
        if (bytes.size() > std::numeric_limits<unsigned int>::max()) fail("the file is over 4 GB");
        check_json_depth(binary ? glb_json(bytes) : std::string_view(bytes));
        m_files.folder = base;
        m_files.confined = m_target.confine_references;
        loader.SetFsCallbacks(tinygltf::FsCallbacks{
            referenced_file_exists, as_given, read_referenced_file, refuse_writing, &m_files});
        const bool ok =
            binary
                ? loader.LoadBinaryFromMemory(&m_model, &error, &warning, data, size, base)
                : loader.LoadASCIIFromString(&m_model, &error, &warning, bytes.data(), size, base);
        if (!ok) {
            while (!error.empty() && (error.back() == '\n' || error.back() == ' '))
                error.pop_back();
            fail(fmt::format("not a valid glTF file: {}", error.empty() ? "unknown error" : error));
        }
        while (!warning.empty() && warning.back() == '\n') warning.pop_back();
        if (!warning.empty()) warn(warning);
        check_extensions();
    }

    // The specification: a loader must refuse a file that requires an extension it does not
    // support; one that is only used may be ignored (glint says so).
    void check_extensions() {
        for (const std::string& name : m_model.extensionsRequired) {
            if (!is_supported_extension(name))
                fail(fmt::format("the file requires extension {}, which glint does not support",
                                 name));
        }
        for (const std::string& name : m_model.extensionsUsed) {
            if (!is_supported_extension(name) && m_warned_extensions.insert(name).second)
                warn(fmt::format("extension {} is not supported (ignored)", name));
        }
    }

    void check_json_depth(std::string_view json) const {
        const JsonDepth depth = json_depth(json);
        if (depth.too_deep_at != std::string::npos) {
            fail(fmt::format("JSON byte {}: arrays and objects nest more than {} deep",
                             depth.too_deep_at, kMaxJsonDepth));
        }
    }

    // The JSON chunk of a GLB file that check_glb() accepted.
    static std::string_view glb_json(const std::string& bytes) {
        uint32_t length;
        std::memcpy(&length, bytes.data() + 12, 4);
        return std::string_view(bytes).substr(20, length);
    }

    // The GLB container checked before tinygltf sees it: a header, a JSON chunk and an
    // optional binary chunk, each wholly inside the file, so that a truncated file is
    // named as such (with the byte offset where it falls short).
    void check_glb(const std::string& bytes) const {
        auto u32 = [&](size_t offset) {
            uint32_t v;
            std::memcpy(&v, bytes.data() + offset, 4);
            return v;
        };
        if (bytes.size() < 12)
            fail(fmt::format("byte {}: the GLB header is cut short (truncated?)", bytes.size()));
        if (u32(0) != 0x46546C67) fail("byte 0: not a GLB file (no 'glTF' magic)");
        if (u32(4) != 2) fail(fmt::format("byte 4: GLB version {}; glint reads version 2", u32(4)));
        if (u32(8) != bytes.size()) {
            fail(fmt::format("byte 8: the header gives a length of {} bytes, the file has {}{}",
                             u32(8), bytes.size(), u32(8) > bytes.size() ? " (truncated?)" : ""));
        }
        size_t offset = 12;
        for (int chunk = 0; offset < bytes.size(); ++chunk) {
            if (bytes.size() - offset < 8)
                fail(fmt::format("byte {}: a chunk header is cut short (truncated?)", offset));
            const uint32_t length = u32(offset);
            const uint32_t type = u32(offset + 4);
            if (chunk == 0 && type != 0x4E4F534A)
                fail(fmt::format("byte {}: the first chunk is not JSON", offset + 4));
            if (length > bytes.size() - offset - 8)
                fail(
                    fmt::format("byte {}: chunk {} of {} bytes runs past the end of the file "
                                "(truncated?)",
                                offset, chunk, length));
            offset += 8 + length;
        }
        if (offset == 12) fail("byte 12: the GLB file has no JSON chunk");
    }

    template <typename T>
    const T& at(const std::vector<T>& list, int index, const char* what) const {
        if (index < 0 || static_cast<size_t>(index) >= list.size())
            fail(fmt::format("{} {} does not exist (the file has {})", what, index, list.size()));
        return list[static_cast<size_t>(index)];
    }

    void count_uses(int node_index, std::vector<int>& path) {
        enter(node_index, path);
        const tinygltf::Node& node = at(m_model.nodes, node_index, "node");
        if (node.mesh >= 0) ++m_uses[node.mesh];
        for (int child : node.children) count_uses(child, path);
        path.pop_back();
    }

    // Guards the walk: glTF's nodes form trees, but a malformed file can make a cycle.
    void enter(int node_index, std::vector<int>& path) {
        if (std::find(path.begin(), path.end(), node_index) != path.end())
            fail(fmt::format("node {} is its own ancestor", node_index));
        if (path.size() >= kMaxGroupDepth)
            fail(fmt::format("nodes nest more than {} deep", kMaxGroupDepth));
        if ((m_node_visits & 0xfff) == 0) throw_if_cancelled();
        // Nodes that share children (not a tree, as glTF requires, but a graph with repeated
        // edges) would be walked once per path: exponentially many times.
        if (++m_node_visits > 2 * kMaxPlacements) {
            fail(
                fmt::format("the node graph places nodes more than {} times (do nodes share "
                            "children? glTF nodes must form trees)",
                            kMaxPlacements));
        }
        path.push_back(node_index);
    }

    // `parent`: the parent's world matrix at each of m_key_times (one: standing still).
    void visit(int node_index, const std::vector<Mat4>& parent, std::vector<int>& path) {
        enter(node_index, path);
        const tinygltf::Node& node = m_model.nodes[static_cast<size_t>(node_index)];
        std::vector<Mat4> world(parent.size());
        auto animation = m_animations.find(node_index);
        bool hidden = false;
        for (size_t k = 0; k < world.size(); ++k) {
            const Mat4 local = animation == m_animations.end()
                                   ? node_matrix(node)
                                   : animation->second.at(node_pose(node), m_key_times[k]).matrix();
            world[k] = parent[k] * local;
            for (int i = 0; i < 16; ++i) {
                if (!std::isfinite(world[k][i / 4][i % 4]))
                    fail(fmt::format("node {} has a transform that is not finite", node_index));
            }
            // A node scaled to nothing (a way to hide it) places nothing: its transform has
            // no inverse.
            hidden |= !(std::abs(glm::determinant(Mat3(world[k]))) > 1e-30f);
        }
        const bool moving =
            std::any_of(world.begin(), world.end(), [&](const Mat4& m) { return m != world[0]; });
        if (node.mesh >= 0 && !hidden) {
            if (moving)
                place_moving_mesh(node.mesh, world);
            else
                place_mesh(node.mesh, Transform(world[0]));
        }
        if (moving && (node.camera >= 0 || node.extensions.count("KHR_lights_punctual")) &&
            !m_warned_still_pose) {
            m_warned_still_pose = true;
            warn(
                "animated cameras and lights stand where the animation starts (glint moves "
                "meshes only)");
        }
        if (node.camera >= 0) add_camera(at(m_model.cameras, node.camera, "camera"), world[0]);
        if (node.extensions.count("KHR_lights_punctual")) {
            const tinygltf::Value& ext = node.extensions.at("KHR_lights_punctual");
            if (ext.Has("light") && ext.Get("light").IsNumber())
                add_light(ext.Get("light").GetNumberAsInt(), world[0]);
        }
        for (int child : node.children) visit(child, world, path);
        path.pop_back();
    }

    // The first animation's channels, as motion keys over the import's window (see
    // ImportTarget::animation): m_key_times are the file's seconds that the keys stand for.
    // Without a window every node stands as the file places it.
    void read_animation() {
        if (!m_target.animation) {
            m_key_times = {0.0f};
            return;
        }
        const auto [start, end] = *m_target.animation;
        if (start == end) {
            m_key_times = {start};
        } else {
            for (int k = 0; k < kAnimationKeys; ++k)
                m_key_times.push_back(start + (end - start) * static_cast<float>(k) /
                                                  static_cast<float>(kAnimationKeys - 1));
        }
        if (m_model.animations.empty()) {
            warn("'animation' is set but the file has no animations");
            return;
        }
        if (m_model.animations.size() > 1)
            warn(fmt::format("the file has {} animations; glint plays the first, '{}'",
                             m_model.animations.size(), m_model.animations[0].name));
        const tinygltf::Animation& animation = m_model.animations[0];
        for (size_t c = 0; c < animation.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = animation.channels[c];
            const std::string what = fmt::format("animation 0 channel {}", c);
            const std::string& property = channel.target_path;
            if (property == "weights") {
                warn("morph target weights are animated; glint does not import morph targets");
                continue;
            }
            if (property != "translation" && property != "rotation" && property != "scale")
                fail(fmt::format("{}: unknown target path '{}'", what, property));
            at(m_model.nodes, channel.target_node, "node");
            if (!m_model.nodes[static_cast<size_t>(channel.target_node)].matrix.empty())
                fail(fmt::format("{}: node {} is placed by a matrix, which cannot be animated",
                                 what, channel.target_node));
            const tinygltf::AnimationSampler& sampler =
                at(animation.samplers, channel.sampler, "animation sampler");
            KeyframeCurve curve;
            curve.components = property == "rotation" ? 4 : 3;
            if (sampler.interpolation == "STEP")
                curve.interpolation = KeyframeCurve::Interpolation::kStep;
            else if (sampler.interpolation == "CUBICSPLINE")
                curve.interpolation = KeyframeCurve::Interpolation::kCubicSpline;
            else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR")
                curve.interpolation = KeyframeCurve::Interpolation::kLinear;
            else
                fail(fmt::format("{}: unknown interpolation '{}'", what, sampler.interpolation));
            curve.times = read_floats(sampler.input, 1, what + " times");
            curve.values = read_floats(sampler.output, curve.components, what + " values");
            const char* reason = nullptr;
            if (!curve.valid(&reason)) fail(fmt::format("{}: the curve {}", what, reason));
            NodeAnimation& node = m_animations[channel.target_node];
            (property == "translation" ? node.translation
             : property == "rotation"  ? node.rotation
                                       : node.scale) = std::move(curve);
        }
    }

    // A mesh whose node moves: its primitives in a group of their own (shared by every
    // moving placement of the mesh), placed with motion keys.
    void place_moving_mesh(int mesh_index, const std::vector<Mat4>& world) {
        const std::vector<Primitive>& primitives = primitives_of(mesh_index);
        std::vector<Transform> keys;
        keys.reserve(world.size());
        for (const Mat4& m : world) {
            keys.emplace_back(m);
            for (const Primitive& p : primitives)
                m_bounds.expand(p.bounds.transformed(keys.back()));
        }
        auto [it, inserted] = m_group_of_mesh.try_emplace(mesh_index, -1);
        if (inserted) {
            m_desc.groups.push_back(GroupDesc{m_target.where, {}, {}});
            it->second = static_cast<int>(m_desc.groups.size()) - 1;
            for (const Primitive& p : primitives) add_shape(it->second, p, Transform());
        }
        m_desc.groups[0].instances.push_back({it->second, Transform(), m_target.where, keys});
    }

    struct Primitive {
        int mesh_data;
        ObjectRef material;
        Bounds3 bounds;
    };

    void place_mesh(int mesh_index, const Transform& to_world) {
        const std::vector<Primitive>& primitives = primitives_of(mesh_index);
        for (const Primitive& p : primitives) m_bounds.expand(p.bounds.transformed(to_world));
        if (m_uses[mesh_index] <= 1) {
            for (const Primitive& p : primitives) add_shape(0, p, to_world);
            return;
        }
        auto [it, inserted] = m_group_of_mesh.try_emplace(mesh_index, -1);
        if (inserted) {
            m_desc.groups.push_back(GroupDesc{m_target.where, {}, {}});
            it->second = static_cast<int>(m_desc.groups.size()) - 1;
            for (const Primitive& p : primitives) add_shape(it->second, p, Transform());
        }
        m_desc.groups[0].instances.push_back({it->second, to_world, m_target.where});
    }

    void add_shape(int group, const Primitive& p, const Transform& xf) {
        Params shape("mesh", m_target.where);
        shape.set("data", ObjectRef{"mesh_data", p.mesh_data});
        shape.set("material", m_target.material ? *m_target.material : p.material);
        if (!xf.is_identity()) shape.set("transform", xf);
        m_desc.groups.at(group).shapes.push_back(std::move(shape));
    }

    // A mesh's primitives, read once however often the mesh is placed.
    const std::vector<Primitive>& primitives_of(int mesh_index) {
        auto it = m_primitives.find(mesh_index);
        if (it != m_primitives.end()) return it->second;
        const tinygltf::Mesh& mesh = at(m_model.meshes, mesh_index, "mesh");
        std::vector<Primitive> result;
        for (size_t i = 0; i < mesh.primitives.size(); ++i) {
            const tinygltf::Primitive& prim = mesh.primitives[i];
            const std::string what = fmt::format("mesh {} primitive {}", mesh_index, i);
            MeshData data = read_primitive(prim, what);
            if (data.indices.empty()) continue;
            Bounds3 bounds;
            for (const Vec3& v : data.positions) bounds.expand(v);
            m_desc.meshes.push_back(std::make_shared<const MeshData>(std::move(data)));
            result.push_back({static_cast<int>(m_desc.meshes.size()) - 1,
                              m_target.material ? *m_target.material : material(prim.material),
                              bounds});
        }
        return m_primitives.emplace(mesh_index, std::move(result)).first->second;
    }

    // An accessor's elements as floats, `components` per element, every byte range checked.
    std::vector<float> read_floats(int accessor_index, int components, const std::string& what) {
        const tinygltf::Accessor& a = at(m_model.accessors, accessor_index, "accessor");
        if (tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) != components)
            fail(fmt::format("{}: accessor {} has {} components, expected {}", what, accessor_index,
                             tinygltf::GetNumComponentsInType(a.type), components));
        const auto [bytes, stride] = element_bytes(a, accessor_index, what);
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        std::vector<float> out(a.count * static_cast<size_t>(components));
        for (size_t e = 0; e < a.count; ++e) {
            const unsigned char* element = bytes + e * stride;
            for (int c = 0; c < components; ++c) {
                const unsigned char* p = element + c * size;
                float v = 0.0f;
                switch (a.componentType) {
                    case TINYGLTF_COMPONENT_TYPE_FLOAT:
                        std::memcpy(&v, p, 4);
                        break;
                    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                        v = *p / 255.0f;
                        break;
                    case TINYGLTF_COMPONENT_TYPE_BYTE:
                        v = std::max(static_cast<int8_t>(*p) / 127.0f, -1.0f);
                        break;
                    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                        uint16_t u;
                        std::memcpy(&u, p, 2);
                        v = u / 65535.0f;
                        break;
                    }
                    case TINYGLTF_COMPONENT_TYPE_SHORT: {
                        int16_t s;
                        std::memcpy(&s, p, 2);
                        v = std::max(s / 32767.0f, -1.0f);
                        break;
                    }
                    default:
                        fail(fmt::format("{}: accessor {} has an unsupported component type {}",
                                         what, accessor_index, a.componentType));
                }
                if (!std::isfinite(v))
                    fail(fmt::format("{}: accessor {} element {} is not finite", what,
                                     accessor_index, e));
                out[e * components + c] = v;
            }
        }
        return out;
    }

    std::vector<uint32_t> read_indices(int accessor_index, size_t vertex_count,
                                       const std::string& what) {
        const tinygltf::Accessor& a = at(m_model.accessors, accessor_index, "accessor");
        if (a.type != TINYGLTF_TYPE_SCALAR)
            fail(fmt::format("{}: index accessor {} is not scalar", what, accessor_index));
        const auto [bytes, stride] = element_bytes(a, accessor_index, what);
        std::vector<uint32_t> out(a.count);
        for (size_t e = 0; e < a.count; ++e) {
            const unsigned char* p = bytes + e * stride;
            uint32_t v = 0;
            if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                v = *p;
            } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                uint16_t u;
                std::memcpy(&u, p, 2);
                v = u;
            } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
                std::memcpy(&v, p, 4);
            } else {
                fail(fmt::format("{}: indices must be unsigned integers", what));
            }
            if (v >= vertex_count)
                fail(fmt::format("{}: index {} refers to vertex {} of {}", what, e, v,
                                 vertex_count));
            out[e] = v;
        }
        return out;
    }

    // The first element's bytes and the stride, once the whole range is known to lie
    // inside its buffer view and the view inside its buffer.
    std::pair<const unsigned char*, size_t> element_bytes(const tinygltf::Accessor& a,
                                                          int accessor_index,
                                                          const std::string& what) {
        if (a.sparse.isSparse)
            fail(fmt::format("{}: accessor {} is sparse, which glint does not read", what,
                             accessor_index));
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        if (size <= 0 || components <= 0)
            fail(fmt::format("{}: accessor {} has an invalid type", what, accessor_index));
        const tinygltf::BufferView& view = at(m_model.bufferViews, a.bufferView, "buffer view");
        const tinygltf::Buffer& buffer = at(m_model.buffers, view.buffer, "buffer");
        const size_t element = static_cast<size_t>(size) * static_cast<size_t>(components);
        const size_t stride = view.byteStride ? view.byteStride : element;
        if (stride < element)
            fail(fmt::format("{}: buffer view {} has a stride of {} bytes for {}-byte elements",
                             what, a.bufferView, stride, element));
        if (view.byteOffset > buffer.data.size() ||
            view.byteLength > buffer.data.size() - view.byteOffset) {
            fail(fmt::format("{}: buffer view {} lies outside its buffer of {} bytes (truncated?)",
                             what, a.bufferView, buffer.data.size()));
        }
        if (a.count == 0) fail(fmt::format("{}: accessor {} is empty", what, accessor_index));
        const size_t last = a.count - 1;
        if (a.byteOffset > view.byteLength || last > (view.byteLength - a.byteOffset) / stride ||
            a.byteOffset + last * stride + element > view.byteLength) {
            fail(
                fmt::format("{}: accessor {} ({} elements) runs past the end of buffer view {} "
                            "(truncated?)",
                            what, accessor_index, a.count, a.bufferView));
        }
        return {buffer.data.data() + view.byteOffset + a.byteOffset, stride};
    }

    MeshData read_primitive(const tinygltf::Primitive& prim, const std::string& what) {
        MeshData data;
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            prim.mode != TINYGLTF_MODE_TRIANGLE_FAN && prim.mode != -1) {
            warn(fmt::format("{}: points and lines are not rendered; skipped", what));
            return data;
        }
        auto attribute = [&](const char* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int position = attribute("POSITION");
        if (position < 0) fail(fmt::format("{}: no POSITION attribute", what));
        const std::vector<float> p = read_floats(position, 3, what + " POSITION");
        const size_t n = p.size() / 3;
        if (n > std::numeric_limits<uint32_t>::max())
            fail(fmt::format("{}: more than 2^32 - 1 vertices", what));
        data.positions.resize(n);
        for (size_t i = 0; i < n; ++i) data.positions[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
        if (const int normal = attribute("NORMAL"); normal >= 0) {
            const std::vector<float> v = read_floats(normal, 3, what + " NORMAL");
            if (v.size() != p.size())
                fail(fmt::format("{}: NORMAL and POSITION differ in count", what));
            data.normals.resize(n);
            for (size_t i = 0; i < n; ++i) data.normals[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        }
        if (const int uv = attribute("TEXCOORD_0"); uv >= 0) {
            const std::vector<float> v = read_floats(uv, 2, what + " TEXCOORD_0");
            if (v.size() != 2 * n)
                fail(fmt::format("{}: TEXCOORD_0 and POSITION differ in count", what));
            data.uvs.resize(n);
            // glTF puts v = 0 at the top of an image, glint at the bottom.
            for (size_t i = 0; i < n; ++i) data.uvs[i] = {v[2 * i], 1.0f - v[2 * i + 1]};
        }
        std::vector<uint32_t> order;
        if (prim.indices >= 0) {
            order = read_indices(prim.indices, n, what);
        } else {
            order.resize(n);
            for (size_t i = 0; i < n; ++i) order[i] = static_cast<uint32_t>(i);
        }
        if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < order.size(); ++i) {
                // Every other triangle of a strip is wound the other way round.
                const bool odd = i % 2 == 1;
                data.indices.insert(data.indices.end(), {order[i], order[odd ? i + 2 : i + 1],
                                                         order[odd ? i + 1 : i + 2]});
            }
        } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
            for (size_t i = 1; i + 1 < order.size(); ++i)
                data.indices.insert(data.indices.end(), {order[0], order[i], order[i + 1]});
        } else {
            if (order.size() % 3 != 0)
                fail(fmt::format("{}: {} indices is not a whole number of triangles", what,
                                 order.size()));
            data.indices = std::move(order);
        }
        return data;
    }

    // The file name of an image: its own file, or for an embedded one (GLB buffer view or
    // data: URI) a copy of its encoded bytes in glint's image cache, named by their hash so
    // that the same image is written once and never changes under a running render.
    std::string image_file(int image_index) {
        auto it = m_image_files.find(image_index);
        if (it != m_image_files.end()) return it->second;
        const tinygltf::Image& image = at(m_model.images, image_index, "image");
        std::string file;
        if (image.bufferView < 0 && !image.uri.empty() && image.uri.rfind("data:", 0) != 0) {
            fs::path path = percent_decoded(image.uri);
            if (path.is_relative()) path = fs::absolute(m_directory / path);
            file = path.lexically_normal().string();
            if (m_files.confined && !is_inside_folder(m_files.folder, file)) {
                fail(
                    fmt::format("image {}: '{}' lies outside the glTF file's folder, where the "
                                "files it refers to must be",
                                image_index, file));
            }
        } else {
            if (image.image.empty()) fail(fmt::format("image {} has no data", image_index));
            uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
            for (unsigned char b : image.image) hash = (hash ^ b) * 0x100000001b3ull;
            const std::string ext = image.mimeType == "image/jpeg" ? ".jpg" : ".png";
            const fs::path path = embedded_image_folder() /
                                  fmt::format("{:016x}-{}{}", hash, image.image.size(), ext);
            const std::string bytes(image.image.begin(), image.image.end());
            if (!cached_copy_matches(path, bytes)) {
                try {
                    write_file_atomically(path.string(), bytes, "an embedded image");
                } catch (const Error& e) {
                    fail(fmt::format("image {}: {}", image_index, e.what()));
                }
            }
            file = path.string();
        }
        return m_image_files.emplace(image_index, file).first->second;
    }

    // KHR_texture_transform of a texture reference: glTF's uv' = T R S uv, in glTF's uv
    // (v down). glint's uv has v up (t = 1 - v) and its image lookup too, so the same
    // lookup is st = (su u + ou, sv t + 1 - sv - ov). Rotation has no glint counterpart.
    struct UvTransform {
        double su = 1.0, sv = 1.0, ou = 0.0, ov = 0.0;
        auto key() const { return std::make_tuple(su, sv, ou, ov); }
    };

    template <typename Info>
    UvTransform uv_transform(const Info& info, const std::string& where, const char* map) {
        UvTransform t;
        auto it = info.extensions.find("KHR_texture_transform");
        if (it == info.extensions.end()) return t;
        const tinygltf::Value& ext = it->second;
        auto pair = [&](const char* key, double& a, double& b) {
            if (!ext.Has(key)) return;
            const tinygltf::Value& v = ext.Get(key);
            if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
                fail(fmt::format("{}: {}: KHR_texture_transform '{}' must be two numbers", where,
                                 map, key));
            a = v.Get(0).GetNumberAsDouble();
            b = v.Get(1).GetNumberAsDouble();
        };
        double ou = 0.0, ov = 0.0;
        pair("offset", ou, ov);
        pair("scale", t.su, t.sv);
        if (!std::isfinite(ou) || !std::isfinite(ov) || !std::isfinite(t.su) ||
            !std::isfinite(t.sv) || t.su == 0.0 || t.sv == 0.0)
            fail(
                fmt::format("{}: {}: KHR_texture_transform needs finite values and a scale "
                            "that is not zero",
                            where, map));
        t.ou = ou;
        t.ov = 1.0 - t.sv - ov;
        if (ext.Has("rotation") && ext.Get("rotation").IsNumber() &&
            ext.Get("rotation").GetNumberAsDouble() != 0.0)
            warn(fmt::format("{}: {}: KHR_texture_transform's rotation is ignored", where, map));
        if (ext.Has("texCoord") && ext.Get("texCoord").IsNumber() &&
            ext.Get("texCoord").GetNumberAsInt() != 0)
            warn(fmt::format("{}: {}: uses TEXCOORD_{}; glint reads TEXCOORD_0", where, map,
                             ext.Get("texCoord").GetNumberAsInt()));
        return t;
    }

    // The texture a material's texture reference names (with its texture transform),
    // made once per (texture, encoding, transform).
    template <typename Info>
    ObjectRef texture_of(const Info& info, bool colour, const std::string& where, const char* map) {
        if (info.texCoord != 0)
            warn(fmt::format("{}: {} uses TEXCOORD_{}; glint reads TEXCOORD_0", where, map,
                             info.texCoord));
        return texture(info.index, colour, uv_transform(info, where, map), where);
    }

    // glint's cache of embedded images: a private folder of this user's own
    // (core/file_access.h says why it must be).
    fs::path embedded_image_folder() const {
        try {
            return private_cache_folder("glint-gltf-images");
        } catch (const Error& e) {
            fail(e.what());
        }
    }

    // Whether `path` is a regular file (not a link) of this user holding exactly `bytes`: only
    // then is an earlier copy used.
    static bool cached_copy_matches(const fs::path& path, const std::string& bytes) {
        struct stat info {};
        if (::lstat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
            info.st_uid != ::getuid() || static_cast<size_t>(info.st_size) != bytes.size())
            return false;
        try {
            return read_regular_file(path.string(), "cached image") == bytes;
        } catch (const Error&) {
            return false;
        }
    }

    // An image texture for a glTF texture: sRGB for colours, linear for data.
    ObjectRef texture(int texture_index, bool colour, const UvTransform& uv,
                      const std::string& where) {
        const auto key = std::make_tuple(texture_index, colour, uv.key());
        auto it = m_textures.find(key);
        if (it != m_textures.end()) return it->second;
        const tinygltf::Texture& tex = at(m_model.textures, texture_index, "texture");
        Params params("image", where);
        params.set("file", image_file(tex.source));
        params.set("encoding", std::string(colour ? "srgb" : "linear"));
        if (uv.key() != UvTransform().key()) {
            params.set("scale", std::vector<double>{uv.su, uv.sv});
            params.set("offset", std::vector<double>{uv.ou, uv.ov});
        }
        if (tex.sampler >= 0) {
            const tinygltf::Sampler& s = at(m_model.samplers, tex.sampler, "sampler");
            if (s.wrapS != s.wrapT)
                warn(fmt::format("{}: texture {} wraps s and t differently; glint uses s's", where,
                                 texture_index));
            if (s.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
                params.set("wrap", std::string("clamp"));
            else if (s.wrapS == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT)
                params.set("wrap", std::string("mirror"));
        }
        m_desc.textures.push_back(std::move(params));
        const ObjectRef ref{"texture", static_cast<int>(m_desc.textures.size()) - 1};
        m_textures.emplace(key, ref);
        return ref;
    }

    // An extension of a material, or nullptr.
    static const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
        auto it = m.extensions.find(name);
        return it == m.extensions.end() ? nullptr : &it->second;
    }

    double number(const tinygltf::Value* ext, const char* key, double fallback, double lo,
                  double hi, const std::string& where) const {
        if (ext == nullptr || !ext->Has(key)) return fallback;
        const tinygltf::Value& v = ext->Get(key);
        const double value = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
        if (!(value >= lo && value <= hi))
            fail(fmt::format("{}: '{}' must be a number in [{}, {}]", where, key, lo, hi));
        return value;
    }

    Vec3 colour(const tinygltf::Value* ext, const char* key, const Vec3& fallback,
                const std::string& where) const {
        if (ext == nullptr || !ext->Has(key)) return fallback;
        const tinygltf::Value& v = ext->Get(key);
        Vec3 c;
        for (int i = 0; i < 3; ++i) {
            const bool ok = v.IsArray() && v.ArrayLen() == 3 && v.Get(i).IsNumber();
            c[i] = ok ? static_cast<float>(v.Get(i).GetNumberAsDouble()) : -1.0f;
            if (!(c[i] >= 0.0f) || !std::isfinite(c[i]))
                fail(fmt::format("{}: '{}' must be three finite numbers >= 0", where, key));
        }
        return c;
    }

    // Textures inside an extension that glint does not read, named in one warning each.
    void warn_textures(const tinygltf::Value* ext, const char* name,
                       std::initializer_list<const char*> keys, const std::string& where) {
        for (const char* key : keys)
            if (ext != nullptr && ext->Has(key))
                warn(fmt::format("{}: {}.{} is ignored (its factor is used)", where, name, key));
    }

    // KHR_materials_dispersion: `dispersion` is 20 / V_d (0: none), the Abbe number of the
    // transmission around n_d = ior; the principled material's `abbe` takes V_d.
    void read_dispersion(const tinygltf::Material& m, Params& params, const std::string& where) {
        const tinygltf::Value* ext = extension(m, "KHR_materials_dispersion");
        const double dispersion = number(ext, "dispersion", 0.0, 0.0, 4.0, where);
        if (dispersion > 0.0) params.set("abbe", std::max(20.0 / dispersion, 5.0));
    }

    // KHR_materials_specular and _ior: a dielectric's reflectance at normal incidence is
    // F0 = min(((ior - 1) / (ior + 1))^2 specularColor, 1) specular. glint's `specular`
    // gives F0 = 0.08 specular (a grey F0 up to 0.08); `ior` stays the transmission's.
    void read_specular_and_ior(const tinygltf::Material& m, Params& params,
                               const std::string& where) {
        const tinygltf::Value* ior_ext = extension(m, "KHR_materials_ior");
        // ior 0 is the specification's "no refraction, F0 = 1"; glint's glass needs >= 1.
        double ior = number(ior_ext, "ior", 1.5, 0.0, 10.0, where);
        if (ior < 1.0) {
            warn(fmt::format("{}: KHR_materials_ior {} is read as 1", where, ior));
            ior = 1.0;
        }
        if (ior_ext != nullptr) params.set("ior", ior);
        read_dispersion(m, params, where);
        const tinygltf::Value* ext = extension(m, "KHR_materials_specular");
        if (ext == nullptr) return;
        const double factor = number(ext, "specularFactor", 1.0, 0.0, 1.0, where);
        const Vec3 tint = colour(ext, "specularColorFactor", Vec3(1.0f), where);
        warn_textures(ext, "KHR_materials_specular", {"specularTexture", "specularColorTexture"},
                      where);
        if (tint.x != tint.y || tint.y != tint.z)
            warn(
                fmt::format("{}: KHR_materials_specular's colour is made grey (its mean): "
                            "glint's specular reflection is not tinted",
                            where));
        const double f0_ior = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
        const double mean_tint = (tint.x + tint.y + tint.z) / 3.0;
        const double f0 = std::min(f0_ior * mean_tint, 1.0) * factor;
        const double specular = f0 / 0.08;
        if (specular > 1.0)
            warn(
                fmt::format("{}: a specular reflectance of {:.3g} at normal incidence is "
                            "limited to glint's 0.08",
                            where, f0));
        params.set("specular", std::min(specular, 1.0));
    }

    // KHR_materials_transmission and _volume. A path tracer has the real geometry, so the
    // volume's thickness (a hint for rasterisers) is not needed; its attenuation becomes
    // Beer-Lambert absorption sigma = -ln(attenuationColor) / attenuationDistance.
    void read_transmission_and_volume(const tinygltf::Material& m, Params& params,
                                      const std::string& where) {
        if (const tinygltf::Value* ext = extension(m, "KHR_materials_transmission")) {
            const double factor = number(ext, "transmissionFactor", 0.0, 0.0, 1.0, where);
            if (ext->Has("transmissionTexture") && ext->Get("transmissionTexture").Has("index")) {
                tinygltf::TextureInfo info;
                info.index = ext->Get("transmissionTexture").Get("index").GetNumberAsInt();
                if (factor != 1.0)
                    warn(
                        fmt::format("{}: transmissionFactor is ignored where the transmission "
                                    "is a texture",
                                    where));
                params.set("transmission", texture(info.index, false, UvTransform(), where));
            } else if (factor != 0.0) {
                params.set("transmission", factor);
            }
        }
        const tinygltf::Value* ext = extension(m, "KHR_materials_volume");
        if (ext == nullptr) return;
        warn_textures(ext, "KHR_materials_volume", {"thicknessTexture"}, where);
        const double distance =
            number(ext, "attenuationDistance", std::numeric_limits<double>::infinity(), 0.0,
                   std::numeric_limits<double>::infinity(), where);
        const Vec3 tint = colour(ext, "attenuationColor", Vec3(1.0f), where);
        if (!std::isfinite(distance) || tint == Vec3(1.0f)) return;
        if (!(distance > 0.0)) fail(fmt::format("{}: 'attenuationDistance' must be > 0", where));
        std::vector<double> sigma(3);
        for (int i = 0; i < 3; ++i) {
            if (!(tint[i] > 0.0f && tint[i] <= 1.0f))
                fail(fmt::format("{}: 'attenuationColor' must lie in (0, 1]", where));
            sigma[static_cast<size_t>(i)] = -std::log(static_cast<double>(tint[i])) / distance;
        }
        params.set("absorption", sigma);
    }

    // KHR_materials_clearcoat and _sheen. glTF's sheen is a colour with its own roughness;
    // glint's is Burley's, a weight tinted between white and the base hue: the weight is
    // the colour's largest channel, white, and the roughness is not followed.
    void read_coat_and_sheen(const tinygltf::Material& m, Params& params,
                             const std::string& where) {
        if (const tinygltf::Value* ext = extension(m, "KHR_materials_clearcoat")) {
            warn_textures(
                ext, "KHR_materials_clearcoat",
                {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"}, where);
            // Blender 3's Principled BSDF weighs its clear coat by a quarter (Burley's
            // clearcoat lobe), and its exporter writes the weight as it is.
            const double coat = number(ext, "clearcoatFactor", 0.0, 0.0, 1.0, where) *
                                (from_blender() ? 0.25 : 1.0);
            if (coat > 0.0) {
                params.set("clearcoat", coat);
                params.set("clearcoat_roughness",
                           number(ext, "clearcoatRoughnessFactor", 0.0, 0.0, 1.0, where));
            }
        }
        if (const tinygltf::Value* ext = extension(m, "KHR_materials_sheen")) {
            warn_textures(ext, "KHR_materials_sheen",
                          {"sheenColorTexture", "sheenRoughnessTexture"}, where);
            const Vec3 sheen = colour(ext, "sheenColorFactor", Vec3(0.0f), where);
            const float weight = std::min(std::max({sheen.x, sheen.y, sheen.z}), 1.0f);
            if (weight > 0.0f) {
                params.set("sheen", static_cast<double>(weight));
                params.set("sheen_tint", 0.0);
                warn(
                    fmt::format("{}: KHR_materials_sheen is approximated by a white Burley "
                                "sheen of weight {:.3g} (colour and roughness not followed)",
                                where, weight));
            }
        }
    }

    // emissiveFactor x KHR_materials_emissive_strength, times the import's emission_scale.
    void read_emission(const tinygltf::Material& m, Params& params, const std::string& where) {
        Vec3 emission(0.0f);
        if (m.emissiveFactor.size() == 3)
            emission = Vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
        // glint's area lights emit one radiance over their surface, so an emissive
        // texture cannot be followed: the factor alone is the emission.
        if (m.emissiveTexture.index >= 0 && emission != Vec3(0.0f)) {
            warn(
                fmt::format("{}: emissiveTexture is ignored (an emitting surface emits its "
                            "emissiveFactor evenly)",
                            where));
        }
        if (emission == Vec3(0.0f)) return;
        params.set("emission", numbers_of(emission));
        const double strength =
            number(extension(m, "KHR_materials_emissive_strength"), "emissiveStrength", 1.0, 0.0,
                   std::numeric_limits<double>::max(), where) *
            m_target.emission_scale;
        if (strength != 1.0) params.set("emission_strength", strength);
    }

    void read_pbr(const tinygltf::Material& m, Params& params, const std::string& where) {
        const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
        Vec3 base(1.0f);
        if (pbr.baseColorFactor.size() >= 3)
            base = Vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
        if (pbr.baseColorTexture.index >= 0) {
            params.set("base_color",
                       texture_of(pbr.baseColorTexture, true, where, "baseColorTexture"));
            if (base != Vec3(1.0f))
                warn(
                    fmt::format("{}: baseColorFactor is ignored where the base colour is a "
                                "texture",
                                where));
        } else {
            params.set("base_color", numbers_of(base));
        }
        params.set("metallic", pbr.metallicFactor);
        params.set("roughness", pbr.roughnessFactor);
        if (pbr.metallicRoughnessTexture.index >= 0) {
            params.set("metallic_roughness", texture_of(pbr.metallicRoughnessTexture, false, where,
                                                        "metallicRoughnessTexture"));
        }
        if (m.normalTexture.index >= 0) {
            params.set("normal_map", texture_of(m.normalTexture, false, where, "normalTexture"));
            if (m.normalTexture.scale != 1.0)
                warn(fmt::format("{}: normalTexture.scale is ignored", where));
        }
    }

    // The principled material for a glTF material (see docs/scene-language.md, "glTF").
    ObjectRef material(int material_index) {
        auto it = m_materials.find(material_index);
        if (it != m_materials.end()) return it->second;
        const std::string where = fmt::format("{}: material {}", origin(), material_index);
        Params params("principled", where);
        if (material_index < 0) {
            // glTF's default material: white, fully metallic, fully rough.
            params.set("base_color", 1.0);
            params.set("metallic", 1.0);
            params.set("roughness", 1.0);
        } else {
            const tinygltf::Material& m = at(m_model.materials, material_index, "material");
            const std::string what = fmt::format("material {}", material_index);
            read_pbr(m, params, what);
            read_emission(m, params, what);
            read_specular_and_ior(m, params, what);
            read_transmission_and_volume(m, params, what);
            read_coat_and_sheen(m, params, what);
            if (m.alphaMode != "OPAQUE")
                warn(fmt::format("{}: alphaMode {} is not supported; rendered opaque", what,
                                 m.alphaMode));
            for (const auto& [name, value] : m.extensions) {
                if (!is_supported_extension(name) && m_warned_extensions.insert(name).second)
                    warn(fmt::format("{}: extension {} is not supported (ignored)", what, name));
            }
        }
        m_desc.materials.push_back(std::move(params));
        const ObjectRef ref{"material", static_cast<int>(m_desc.materials.size()) - 1};
        m_materials.emplace(material_index, ref);
        return ref;
    }

    // The first camera found, unless the scene already has one (set before the import).
    void add_camera(const tinygltf::Camera& camera, const Mat4& world) {
        if (m_desc.camera) return;
        const Vec3 eye(world * glm::vec4(0, 0, 0, 1));
        const Vec3 forward = glm::normalize(Vec3(world * glm::vec4(0, 0, -1, 0)));
        const Vec3 up = glm::normalize(Vec3(world * glm::vec4(0, 1, 0, 0)));
        const std::string where = fmt::format("{}: camera", origin());
        Params params("camera", where);
        params.set("eye", numbers_of(eye));
        params.set("look_at", numbers_of(eye + forward));
        params.set("up", numbers_of(up));
        double aspect = 0.0;
        if (camera.type == "orthographic") {
            params.set("type", std::string("orthographic"));
            // ymag is half the view's height; glint's scale is the whole height.
            params.set("scale", 2.0 * camera.orthographic.ymag);
            if (camera.orthographic.ymag > 0.0)
                aspect = camera.orthographic.xmag / camera.orthographic.ymag;
        } else {
            params.set("fov", camera.perspective.yfov * 180.0 / 3.14159265358979323846);
            aspect = camera.perspective.aspectRatio;
        }
        if (std::isfinite(aspect) && aspect > 0.0)
            m_desc.camera_aspect = static_cast<float>(aspect);
        m_desc.camera = std::move(params);
        m_desc.camera_imported = true;
    }

    // Whether Blender's exporter wrote the file: where it writes what Blender does not
    // render, glint reads what Blender renders (docs/scene-language.md, "glTF").
    bool from_blender() const {
        return m_model.asset.generator.rfind("Khronos glTF Blender I/O", 0) == 0;
    }

    // The angle (radians) where a spot's edge begins to fade: the file's innerConeAngle, as
    // the specification says, except in a file from Blender's exporter. Blender fades a
    // spot with blend b over cos(angle) from cos(outer) to cos(outer) + (1 - cos(outer)) b
    // (smoothstep in the cosine, as glint's spot does), but its exporter writes inner =
    // outer (1 - b), a wider fade; reading b back from that gives Blender's own cone.
    double falloff_start(double inner, double outer) const {
        if (!from_blender() || !(outer > 0.0)) return inner;
        const double blend = std::clamp(1.0 - inner / outer, 0.0, 1.0);
        const double cos_outer = std::cos(outer);
        return std::acos(std::min(cos_outer + (1.0 - cos_outer) * blend, 1.0));
    }

    // KHR_lights_punctual. glTF states candela (point, spot) and lux (directional); glint's
    // lights take W/sr and W/m^2. light_scale is watts per lumen: 1/683 by default, the
    // luminous efficacy that defines the candela (what Blender's importer and exporter use),
    // 1 for the unitless reading of real-time viewers (see the docs).
    void add_light(int light_index, const Mat4& world) {
        const tinygltf::Light& light = at(m_model.lights, light_index, "light");
        const std::string where = fmt::format("{}: light {}", origin(), light_index);
        Vec3 colour(1.0f);
        if (light.color.size() == 3) colour = Vec3(light.color[0], light.color[1], light.color[2]);
        const Vec3 power = colour * static_cast<float>(light.intensity) *
                           m_target.light_scale.value_or(kWattsPerLumen);
        const Vec3 position(world * glm::vec4(0, 0, 0, 1));
        const Vec3 direction = glm::normalize(Vec3(world * glm::vec4(0, 0, -1, 0)));
        Params params;
        if (light.type == "point") {
            params = Params("point_light", where);
            params.set("position", numbers_of(position));
            params.set("intensity", numbers_of(power));
        } else if (light.type == "spot") {
            params = Params("spot_light", where);
            params.set("position", numbers_of(position));
            params.set("look_at", numbers_of(position + direction));
            params.set("intensity", numbers_of(power));
            const double outer = light.spot.outerConeAngle;
            const double inner = falloff_start(light.spot.innerConeAngle, outer);
            params.set("cone_angle", glm::degrees(outer));
            params.set("falloff_start", glm::degrees(std::min(inner, outer)));
        } else if (light.type == "directional") {
            params = Params("directional_light", where);
            params.set("direction", numbers_of(direction));
            params.set("irradiance", numbers_of(power));
        } else {
            fail(fmt::format("light {} has unknown type '{}'", light_index, light.type));
        }
        if (light.range > 0.0) warn(fmt::format("light {}: 'range' is ignored", light_index));
        m_desc.lights.push_back(std::move(params));
    }

    SceneDesc& m_desc;
    const ImportTarget& m_target;
    tinygltf::Model m_model;
    fs::path m_directory;
    ReferencedFiles m_files;
    size_t m_node_visits = 0;                   // both walks over the node graph together
    std::vector<float> m_key_times;             // the file's seconds of each motion key
    std::map<int, NodeAnimation> m_animations;  // node -> its curves
    bool m_warned_still_pose = false;
    std::vector<int> m_roots;
    std::map<int, int> m_uses;           // mesh -> placements
    std::map<int, int> m_group_of_mesh;  // repeated mesh -> its group
    std::map<int, std::vector<Primitive>> m_primitives;
    std::map<int, ObjectRef> m_materials;
    std::map<std::tuple<int, bool, std::tuple<double, double, double, double>>, ObjectRef>
        m_textures;
    std::set<std::string> m_warned_extensions;
    std::map<int, std::string> m_image_files;
    Bounds3 m_bounds;
};

}  // namespace

Bounds3 import_gltf(SceneDesc& desc, const ImportTarget& target) {
    return GltfImporter(desc, target).run();
}

}  // namespace glint
