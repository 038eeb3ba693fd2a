#include <glint/core/error.h>
#include <glint/geometry/shape_table.h>
#include <glint/light/registry.h>
#include <glint/material/registry.h>
#include <glint/material/texture/registry.h>
#include <glint/scene/import/import.h>
#include <glint/scene/lua/lua_loader.h>
#include <glint/scene/lua/lua_vm.h>
#include <glint/scene/solids.h>

#include <fmt/format.h>
#include <lua.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <new>

namespace glint {
namespace {

constexpr const char* kTransformMeta = "glint.transform";
constexpr const char* kHandleMeta = "glint.handle";
constexpr const char* kLoaderKey = "glint.loader";

struct Handle {
    int kind;  // 0 = material, 1 = group, 2 = solid, 3 = texture, 4 = medium
    int index;
};
constexpr const char* kHandleKinds[] = {"material", "group", "solid", "texture", "medium"};
constexpr int kSolidHandle = 2;
constexpr int kTextureHandle = 3;
constexpr int kMediumHandle = 4;

// What the bindings build, reachable from Lua through the registry (which a sandboxed
// script cannot see) while the script runs, and unreachable afterwards.
struct LoaderState {
    SceneDesc desc;
    std::vector<int> solid_depth;  // per solid: nodes from it down to its deepest primitive
};

LoaderState& loader_of(lua_State* L) {
    lua_getfield(L, LUA_REGISTRYINDEX, kLoaderKey);
    auto* loader = static_cast<LoaderState*>(lua_touserdata(L, -1));
    lua_pop(L, 1);
    // A __gc finaliser can run once the script has failed and the scene is gone.
    if (!loader) throw Error("glint functions cannot be called once the scene script has ended");
    return *loader;
}

SceneDesc& desc_of(lua_State* L) {
    return loader_of(L).desc;
}

// "file:line" of the innermost Lua function on `thread`'s stack from `level` up, or "".
std::string innermost_line(lua_State* thread, int level) {
    lua_Debug ar;
    for (; lua_getstack(thread, level, &ar); ++level) {
        if (lua_getinfo(thread, "Sl", &ar) && ar.currentline > 0)
            return fmt::format("{}:{}", ar.short_src, ar.currentline);
    }
    return "";
}

// "file:line" of the script statement that called into glint: the innermost Lua function
// with a line, so that a call made through pcall or another library function still names
// the script's line; a function run as a coroutine (coroutine.wrap(glint.sphere)) has no
// Lua caller on its own stack, so the thread that resumed it is asked (the main thread's
// innermost line).
std::string where(lua_State* L) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_MAINTHREAD);
    lua_State* main = lua_tothread(L, -1);
    lua_pop(L, 1);
    const std::string line = innermost_line(L, 1);
    if (!line.empty() || !main || main == L) return line.empty() ? "?" : line;
    const std::string resumed_from = innermost_line(main, 0);
    return resumed_from.empty() ? "?" : resumed_from;
}

// Runs a binding, turning glint errors into Lua errors (which carry their own location).
// The message is on the Lua stack before lua_error, whose jump skips C++ destructors. Its
// time does not count against the script's time limit.
template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
    try {
        const GlintCallTime own_time(L);
        return F(L);
    } catch (const std::bad_alloc&) {
        // C++ memory (the scene's description) is not under the script's memory limit.
        const std::string message = fmt::format(
            "{}: out of memory: the scene grew past what this machine can hold (a loop that adds "
            "objects without end?)",
            where(L));
        lua_pushstring(L, message.c_str());
    } catch (const std::exception& e) {
        lua_pushstring(L, e.what());
    }
    return lua_error(L);
}

[[noreturn]] void fail(lua_State* L, const std::string& message) {
    throw Error(fmt::format("{}: {}", where(L), message));
}

// Userdata count as glint's only when they carry glint's metatable, which a script can
// neither read (__metatable hides it) nor give to a value of its own.
Transform* to_transform(lua_State* L, int index) {
    return static_cast<Transform*>(luaL_testudata(L, index, kTransformMeta));
}

Handle* to_handle(lua_State* L, int index) {
    return static_cast<Handle*>(luaL_testudata(L, index, kHandleMeta));
}

// What the value at `index` is, for messages: "a material", "a string", ...
std::string describe(lua_State* L, int index) {
    if (Handle* h = to_handle(L, index)) return fmt::format("a {}", kHandleKinds[h->kind]);
    if (to_transform(L, index)) return "a transform";
    if (lua_isnone(L, index)) return "nothing";
    return fmt::format("a {}", luaL_typename(L, index));
}

// The one place a script's number enters glint: NaN, infinities and numbers past the
// range of a float (which would become infinite) are refused, naming the key.
double finite_number(lua_State* L, int index, const std::string& name, const std::string& type) {
    const double value = lua_tonumber(L, index);
    if (!std::isfinite(value) || std::abs(value) > FLT_MAX) {
        fail(L, fmt::format("{}: '{}' must be a finite number (at most {:g} in size), got {}", type,
                            name, FLT_MAX, std::isnan(value) ? "NaN" : fmt::format("{:g}", value)));
    }
    return value;
}

void push_transform(lua_State* L, const Transform& xf) {
    void* memory = lua_newuserdatauv(L, sizeof(Transform), 0);
    new (memory) Transform(xf);
    luaL_setmetatable(L, kTransformMeta);
}

void push_handle(lua_State* L, int kind, int index) {
    auto* handle = static_cast<Handle*>(lua_newuserdatauv(L, sizeof(Handle), 0));
    *handle = {kind, index};
    luaL_setmetatable(L, kHandleMeta);
}

// Converts the Lua value at `index` into a parameter value; `name` is for errors. Tables
// are read raw (no metamethods run) and `depth` tables deep at most, so a table nested
// without end, or one that contains itself, is an error rather than a stack overflow.
ParamValue to_param(lua_State* L, int index, const std::string& name, const std::string& type,
                    int depth = 0) {
    index = lua_absindex(L, index);
    switch (lua_type(L, index)) {
        case LUA_TBOOLEAN:
            return lua_toboolean(L, index) != 0;
        case LUA_TNUMBER:
            return finite_number(L, index, name, type);
        case LUA_TSTRING:
            return std::string(lua_tostring(L, index));
        case LUA_TUSERDATA:
            if (Transform* xf = to_transform(L, index)) return *xf;
            if (Handle* h = to_handle(L, index)) return ObjectRef{kHandleKinds[h->kind], h->index};
            break;
        case LUA_TTABLE: {
            if (depth >= kMaxParamTableDepth || !lua_checkstack(L, 4)) {
                fail(L, fmt::format("{}: '{}' holds tables nested more than {} deep (does a table "
                                    "contain itself?)",
                                    type, name, kMaxParamTableDepth));
            }
            const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
            std::vector<double> numbers;
            std::vector<std::vector<double>> rows;
            std::vector<std::string> strings;
            for (lua_Integer i = 1; i <= n; ++i) {
                lua_rawgeti(L, index, i);
                if (lua_type(L, -1) == LUA_TNUMBER && rows.empty() && strings.empty()) {
                    numbers.push_back(finite_number(L, -1, name, type));
                } else if (lua_type(L, -1) == LUA_TSTRING && rows.empty() && numbers.empty()) {
                    strings.emplace_back(lua_tostring(L, -1));
                } else if (lua_type(L, -1) == LUA_TTABLE && numbers.empty() && strings.empty()) {
                    if (lua_rawequal(L, -1, index))
                        fail(L, fmt::format("{}: '{}' contains itself", type, name));
                    ParamValue row = to_param(L, -1, name, type, depth + 1);
                    auto* row_numbers = std::get_if<std::vector<double>>(&row);
                    if (!row_numbers)
                        fail(L, fmt::format("{}: entry {} of '{}' must be a list of numbers", type,
                                            i, name));
                    rows.push_back(std::move(*row_numbers));
                } else {
                    fail(L, fmt::format("{}: '{}' must be a list of numbers, of strings, or of "
                                        "lists of numbers",
                                        type, name));
                }
                lua_pop(L, 1);
            }
            if (!rows.empty()) return rows;
            if (!strings.empty()) return strings;
            return numbers;
        }
        default:
            break;
    }
    fail(L, fmt::format("{}: parameter '{}' has unsupported type {}", type, name,
                        luaL_typename(L, index)));
}

// Reads the table argument at `index` into Params of the given type.
Params to_params(lua_State* L, int index, const std::string& type) {
    Params params(type, where(L));
    if (lua_isnoneornil(L, index)) return params;
    if (!lua_istable(L, index)) {
        fail(L, fmt::format("{} expects a table of named parameters, e.g. {{radius = 1}}, got {}",
                            type, describe(L, index)));
    }
    index = lua_absindex(L, index);
    lua_pushnil(L);
    while (lua_next(L, index) != 0) {
        if (lua_type(L, -2) != LUA_TSTRING) {
            fail(L, fmt::format("{}: parameters must be named (name = value)", type));
        }
        const std::string name = lua_tostring(L, -2);
        params.set(name, to_param(L, -1, name, type));
        lua_pop(L, 1);
    }
    return params;
}

// glint.<material>{...} -> material handle. The type name is the closure's upvalue.
int new_material(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    SceneDesc& desc = desc_of(L);
    desc.materials.push_back(to_params(L, 1, type));
    push_handle(L, 0, static_cast<int>(desc.materials.size()) - 1);
    return 1;
}

// glint.texture.<type>{...} -> texture handle, usable wherever a material takes one.
int new_texture(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    SceneDesc& desc = desc_of(L);
    desc.textures.push_back(to_params(L, 1, type));
    push_handle(L, kTextureHandle, static_cast<int>(desc.textures.size()) - 1);
    return 1;
}

// glint.medium{...} -> medium handle, for a surface's interior/exterior or the camera.
int new_medium(lua_State* L) {
    SceneDesc& desc = desc_of(L);
    desc.media.push_back(to_params(L, 1, "medium"));
    push_handle(L, kMediumHandle, static_cast<int>(desc.media.size()) - 1);
    return 1;
}

int new_light(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    desc_of(L).lights.push_back(to_params(L, 1, type));
    return 0;
}

int group_index_of(lua_State* L, int index) {
    Handle* h = to_handle(L, index);
    if (!h || h->kind != 1)
        fail(L,
             fmt::format("expected a group (made by glint.group()), got {}", describe(L, index)));
    return h->index;
}

// glint.<shape>{...} adds to the world group; group:<shape>{...} to that group.
int new_shape(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    int group = 0;
    int args = 1;
    if (Handle* h = to_handle(L, 1); h && h->kind == 1) {
        group = h->index;
        args = 2;
    }
    // Read before the group is looked up: reading may run a script's __gc finaliser, which
    // may add a group and so move every group (a reference taken before would dangle).
    Params params = to_params(L, args, type);
    desc_of(L).groups[group].shapes.push_back(std::move(params));
    return 0;
}

// glint.solid.<type>{...} -> solid handle (not yet in the scene; see glint.add).
int new_solid(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    LoaderState& loader = loader_of(L);
    loader.desc.solids.push_back({to_params(L, 1, type), {}});
    loader.solid_depth.push_back(1);
    SceneDesc& desc = loader.desc;
    push_handle(L, kSolidHandle, static_cast<int>(desc.solids.size()) - 1);
    return 1;
}

// glint.union{a, b, ..., material = m, transform = xf}: solids in the list part, settings
// by name.
int new_csg_node(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    if (!lua_istable(L, 1))
        fail(L,
             fmt::format("glint.{} expects a table: glint.{}{{a, b, material = m}}", type, type));
    std::vector<int> children;
    LoaderState& loader = loader_of(L);
    int depth = 0;
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, 1));
    for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, 1, i);
        Handle* h = to_handle(L, -1);
        if (!h || h->kind != kSolidHandle) {
            fail(L, fmt::format("glint.{}: entry {} is not a solid (made by glint.solid.* or "
                                "another CSG node), got {}",
                                type, i, describe(L, -1)));
        }
        children.push_back(h->index);
        depth = std::max(depth, loader.solid_depth.at(h->index));
        lua_pop(L, 1);
    }
    // Building and tracing a CSG tree recurse through it: its depth is bounded here, where
    // the message can name the line.
    if (depth + 1 > kMaxCsgDepth) {
        fail(L, fmt::format("glint.{}: this CSG tree would be {} nodes deep; the limit is {} "
                            "(combine many solids in one node: glint.{}{{a, b, c, ...}})",
                            type, depth + 1, kMaxCsgDepth, type));
    }
    // The named entries are the node's parameters.
    lua_newtable(L);
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
        if (lua_type(L, -2) == LUA_TSTRING) {
            lua_pushvalue(L, -2);
            lua_insert(L, -2);
            lua_settable(L, -4);
        } else {
            lua_pop(L, 1);
        }
    }
    if (children.empty()) {
        fail(L,
             fmt::format("glint.{} needs at least one solid, e.g. glint.{}{{a, b}}", type, type));
    }
    SceneDesc& desc = loader.desc;
    desc.solids.push_back({to_params(L, -1, type), std::move(children)});
    loader.solid_depth.push_back(depth + 1);
    push_handle(L, kSolidHandle, static_cast<int>(desc.solids.size()) - 1);
    return 1;
}

// glint.add(solid [, {material = m}]) or group:add(solid): puts a solid into the scene.
int add_solid(lua_State* L) {
    int group = 0;
    int args = 1;
    if (Handle* h = to_handle(L, 1); h && h->kind == 1) {
        group = h->index;
        args = 2;
    }
    Handle* solid = to_handle(L, args);
    if (!solid || solid->kind != kSolidHandle) {
        fail(L,
             fmt::format("glint.add expects a solid (made by glint.solid.* or a CSG node), got {}",
                         describe(L, args)));
    }
    if (!lua_isnoneornil(L, args + 1) && !lua_istable(L, args + 1)) {
        fail(L, fmt::format("glint.add(solid, settings): the settings must be a table such as "
                            "{{material = m}}, got {}",
                            describe(L, args + 1)));
    }
    Params params = to_params(L, args + 1, "solid");
    params.set("solid", ObjectRef{"solid", solid->index});
    desc_of(L).groups[group].shapes.push_back(std::move(params));
    return 0;
}

int new_group(lua_State* L) {
    SceneDesc& desc = desc_of(L);
    desc.groups.push_back(GroupDesc{where(L), {}, {}});
    push_handle(L, 1, static_cast<int>(desc.groups.size()) - 1);
    return 1;
}

Transform optional_transform(lua_State* L, int index) {
    if (lua_isnoneornil(L, index)) return Transform();
    Transform* xf = to_transform(L, index);
    if (!xf)
        fail(L, "expected a transform (glint.translate, glint.rotate, glint.scale, glint.matrix)");
    return *xf;
}

// glint.place(group [, transform]) or parent:place(group [, transform]).
int place_group(lua_State* L) {
    int parent = 0;
    int args = 1;
    if (to_handle(L, 2)) {
        parent = group_index_of(L, 1);
        args = 2;
    }
    const int child = group_index_of(L, args);
    if (child == 0) fail(L, "the world group cannot be placed");
    // Both read before the group is looked up (where() allocates, which may run a
    // finaliser that adds a group, see new_shape).
    InstanceDesc instance{child, optional_transform(L, args + 1), where(L)};
    desc_of(L).groups[parent].instances.push_back(std::move(instance));
    return 0;
}

// A transform a script makes must map finite points to finite points and back: its matrix
// and its inverse finite, and the matrix far from singular relative to its own scale.
void push_checked_transform(lua_State* L, const Transform& xf, const char* what) {
    const Mat4& m = xf.matrix();
    const Mat4& inverse = xf.inverse_matrix();
    float largest = 0.0f;
    bool finite = true;
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            finite &= std::isfinite(m[col][row]) && std::isfinite(inverse[col][row]);
            if (row < 3 && col < 3) largest = std::max(largest, std::abs(m[col][row]));
        }
    }
    if (!finite) fail(L, fmt::format("{}: the transform is not finite (numbers too large?)", what));
    // |det| against the cube of the largest entry: scale-free, 1 for a rotation.
    const double det = glm::determinant(glm::dmat3(Mat3(m)));
    if (!(std::abs(det) > 1e-12 * static_cast<double>(largest) * largest * largest)) {
        fail(L, fmt::format("{}: the transform is singular or nearly so (it flattens space), "
                            "so it cannot be inverted",
                            what));
    }
    push_transform(L, xf);
}

Vec3 vec3_arguments(lua_State* L, int first, const char* what) {
    if (lua_istable(L, first)) {
        ParamValue v = to_param(L, first, what, what);
        auto* list = std::get_if<std::vector<double>>(&v);
        if (!list || list->size() != 3)
            fail(L, fmt::format("{} expects three numbers or {{x, y, z}}", what));
        return Vec3((*list)[0], (*list)[1], (*list)[2]);
    }
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
        if (lua_type(L, first + i) != LUA_TNUMBER)
            fail(L, fmt::format("{} expects three numbers or {{x, y, z}}", what));
        v[i] = static_cast<float>(finite_number(L, first + i, std::string(1, "xyz"[i]), what));
    }
    return v;
}

int translate(lua_State* L) {
    push_checked_transform(L, Transform::translate(vec3_arguments(L, 1, "glint.translate")),
                           "glint.translate");
    return 1;
}

int rotate(lua_State* L) {
    if (lua_type(L, 1) != LUA_TNUMBER)
        fail(L, "glint.rotate expects an angle in degrees and an axis {x, y, z}");
    // Reduced to one turn first: sin and cos of a float far from zero lose every digit.
    const float degrees =
        static_cast<float>(std::fmod(finite_number(L, 1, "angle", "glint.rotate"), 360.0));
    const Vec3 axis = vec3_arguments(L, 2, "glint.rotate axis");
    if (glm::length(axis) <= 0.0f) fail(L, "glint.rotate axis must not be zero");
    push_checked_transform(L, Transform::rotate(degrees, axis), "glint.rotate");
    return 1;
}

int scale(lua_State* L) {
    Vec3 factors;
    if (lua_type(L, 1) == LUA_TNUMBER && lua_isnone(L, 2))
        factors = Vec3(static_cast<float>(finite_number(L, 1, "factor", "glint.scale")));
    else
        factors = vec3_arguments(L, 1, "glint.scale");
    if (factors.x == 0.0f || factors.y == 0.0f || factors.z == 0.0f)
        fail(L, "glint.scale factors must not be zero");
    push_checked_transform(L, Transform::scale(factors), "glint.scale");
    return 1;
}

// glint.matrix{16 numbers, row by row}.
int matrix(lua_State* L) {
    ParamValue v = to_param(L, 1, "matrix", "glint.matrix");
    auto* list = std::get_if<std::vector<double>>(&v);
    if (!list || list->size() != 16)
        fail(L, "glint.matrix expects a table of 16 numbers, row by row");
    Mat4 m;
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) m[col][row] = static_cast<float>((*list)[4 * row + col]);
    }
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f) {
        fail(L, "glint.matrix must be affine: its last row must be 0, 0, 0, 1");
    }
    push_checked_transform(L, Transform(m), "glint.matrix");
    return 1;
}

// a * b applies b first, then a.
int transform_multiply(lua_State* L) {
    Transform* a = to_transform(L, 1);
    Transform* b = to_transform(L, 2);
    if (!a || !b) fail(L, "only two transforms can be multiplied");
    push_checked_transform(L, *a * *b, "transform * transform");
    return 1;
}

// glint.import{ file = ..., transform = ..., material = ..., light_scale = ...,
// emission_scale = ... }: the file's content goes into the scene; nothing is returned.
int import_model(lua_State* L) {
    SceneDesc& desc = desc_of(L);
    import_into(desc, to_params(L, 1, "import"));
    return 0;
}

template <std::optional<Params> SceneDesc::*Member>
int set_single(lua_State* L) {
    const std::string type = lua_tostring(L, lua_upvalueindex(1));
    SceneDesc& desc = desc_of(L);
    // A camera an imported file brought stands in until the script sets its own.
    if constexpr (Member == &SceneDesc::camera) {
        if (desc.camera_imported) {
            desc.camera.reset();
            desc.camera_imported = false;
        }
    }
    if (desc.*Member)
        fail(L, fmt::format("glint.{} was already called at {}", type, (desc.*Member)->where()));
    desc.*Member = to_params(L, 1, type);
    return 0;
}

void register_closure(lua_State* L, const std::string& name, lua_CFunction function) {
    lua_pushstring(L, name.c_str());
    lua_pushcclosure(L, function, 1);
    lua_setfield(L, -2, name.c_str());
}

// Builds the `glint` table, leaves it on the stack.
int open_glint(lua_State* L) {
    luaL_newmetatable(L, kTransformMeta);
    lua_pushcfunction(L, guarded<transform_multiply>);
    lua_setfield(L, -2, "__mul");
    lua_pushliteral(L, "glint.transform");  // getmetatable() sees this, not the table
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);

    // Handles double as group objects: group:sphere{...}, group:place(other, xf).
    luaL_newmetatable(L, kHandleMeta);
    lua_newtable(L);
    for (const std::string& type : shape_types()) register_closure(L, type, guarded<new_shape>);
    lua_pushcfunction(L, guarded<place_group>);
    lua_setfield(L, -2, "place");
    lua_pushcfunction(L, guarded<add_solid>);
    lua_setfield(L, -2, "add");
    lua_setfield(L, -2, "__index");
    lua_pushliteral(L, "glint.handle");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);

    lua_newtable(L);
    for (const std::string& type : material_types())
        register_closure(L, type, guarded<new_material>);
    for (const std::string& type : light_types()) register_closure(L, type, guarded<new_light>);
    for (const std::string& type : shape_types()) register_closure(L, type, guarded<new_shape>);
    lua_newtable(L);
    for (const std::string& type : solid_types()) register_closure(L, type, guarded<new_solid>);
    lua_setfield(L, -2, "solid");
    lua_newtable(L);
    for (const std::string& type : texture_types()) register_closure(L, type, guarded<new_texture>);
    lua_setfield(L, -2, "texture");
    for (const char* operation : {"union", "intersection", "difference"}) {
        register_closure(L, operation, guarded<new_csg_node>);
    }
    lua_pushcfunction(L, guarded<add_solid>);
    lua_setfield(L, -2, "add");
    register_closure(L, "medium", guarded<new_medium>);
    register_closure(L, "camera", guarded<set_single<&SceneDesc::camera>>);
    register_closure(L, "render", guarded<set_single<&SceneDesc::render>>);
    register_closure(L, "background", guarded<set_single<&SceneDesc::background>>);
    const std::pair<const char*, lua_CFunction> functions[] = {
        {"group", guarded<new_group>},     {"place", guarded<place_group>},
        {"translate", guarded<translate>}, {"rotate", guarded<rotate>},
        {"scale", guarded<scale>},         {"matrix", guarded<matrix>},
        {"import", guarded<import_model>},
    };
    for (const auto& [name, function] : functions) {
        lua_pushcfunction(L, function);
        lua_setfield(L, -2, name);
    }
    return 1;
}

// Takes the loader out of the registry when the run ends, however it ends: finalisers that
// lua_close runs afterwards find no scene to write into and fail cleanly.
struct DetachLoader {
    lua_State* L;
    ~DetachLoader() {
        lua_pushnil(L);
        lua_setfield(L, LUA_REGISTRYINDEX, kLoaderKey);
    }
};

int open_glint_protected(lua_State* L) {
    // `glint` is a global and also what require("glint") returns.
    luaL_requiref(L, "glint", open_glint, 1);
    return 0;
}

SceneDesc run_chunk(const std::function<int(lua_State*)>& load, const std::string& chunk_name,
                    const std::string& directory, const LoaderOptions& options) {
    LoaderState loader;
    loader.desc.directory = directory;
    loader.desc.trusted = options.trusted;
    LuaVm vm(options, directory);  // closed before `loader` goes
    lua_State* L = vm.state();
    lua_pushlightuserdata(L, &loader);
    lua_setfield(L, LUA_REGISTRYINDEX, kLoaderKey);
    const DetachLoader detach{L};

    lua_pushcfunction(L, open_glint_protected);
    vm.call_main(chunk_name);
    vm.check_load(load(L), chunk_name);
    vm.call_main(chunk_name);
    return std::move(loader.desc);
}

}  // namespace

SceneDesc load_scene_file(const std::string& path, const LoaderOptions& options) {
    if (!std::filesystem::is_regular_file(path))
        throw Error(fmt::format("cannot open scene file '{}'", path));
    std::string directory = std::filesystem::path(path).parent_path().string();
    if (directory.empty()) directory = ".";
    return run_chunk(
        [&](lua_State* L) {
            // Text only, also for a trusted scene: a precompiled chunk can crash the VM.
            return luaL_loadfilex(L, path.c_str(), "t");
        },
        path, directory, options);
}

SceneDesc load_scene_string(const std::string& code, const std::string& chunk_name,
                            const std::string& directory, const LoaderOptions& options) {
    const std::string lua_chunk_name = "=" + chunk_name;
    return run_chunk(
        [&](lua_State* L) {
            return luaL_loadbufferx(L, code.data(), code.size(), lua_chunk_name.c_str(), "t");
        },
        chunk_name, directory, options);
}

}  // namespace glint
