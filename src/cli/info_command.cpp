#include "info_command.h"

#include "flags.h"

#include <glint/scene/build.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint::cli {
namespace {

// One line per participating medium: where the script made it and its coefficients (at the
// origin, for a medium that varies), and which one the camera sits in.
void print_media(const SceneDesc& desc, const Scene& scene) {
    fmt::print("media:      {}\n", scene.media().size());
    for (size_t i = 0; i < scene.media().size(); ++i) {
        const Medium& medium = *scene.media()[i];
        const MediumPoint point = medium.at(Vec3(0.0f));
        const auto values = [](const Spectrum& s) {
            return fmt::format("({:g}, {:g}, {:g})", s.value(0), s.value(1), s.value(2));
        };
        fmt::print("  medium {} at {}: {}sigma_a {} sigma_s {} g {:g}{}{}\n", i + 1,
                   desc.media[i].where(), medium.is_homogeneous() ? "homogeneous, " : "",
                   values(point.sigma_a), values(point.sigma_s), medium.phase_asymmetry(),
                   medium.emits() ? ", emits" : "",
                   &medium == scene.camera_medium() ? ", the camera's" : "");
    }
}

}  // namespace

CLI::App* add_info_command(CLI::App& app, InfoOptions& options) {
    CLI::App* info_cmd =
        app.add_subcommand("info", "Print counts of shapes, triangles, lights and bounds");
    info_cmd
        ->add_option("scene", options.scene,
                     "Scene script (.lua) or model file (.obj, .ply, .gltf, .glb)")
        ->required();
    info_cmd->add_flag("--trusted-scene", options.trusted_scene, trusted_scene_help());
    info_cmd->add_option("--script-time-limit", options.script_time_limit,
                         script_time_limit_help());
    return info_cmd;
}

int run_info(const InfoOptions& options) {
    const std::string& scene_path = options.scene;
    const SceneDesc desc =
        load_scene(scene_path, loader_options(options.trusted_scene, options.script_time_limit));
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    for (const std::string& warning : scene->stats().warnings)
        fmt::print(stderr, "warning: {}\n", warning);
    const SceneStats& s = scene->stats();
    fmt::print("scene:      {}\n", scene_path);
    fmt::print("shapes:     {}\n", s.shapes);
    fmt::print("triangles:  {}\n", s.triangles);
    fmt::print("lights:     {}\n", s.lights);
    fmt::print("groups:     {} ({} instances)\n", s.groups, s.instances);
    fmt::print("materials:  {}\n", desc.materials.size());
    print_media(desc, *scene);
    // Memory of the geometry: glint's own arrays (positions, normals, uvs, indices and the
    // per-triangle frames) and Embree's (BVH and its copies of vertices and indices), per
    // triangle built (a group placed many times is built once).
    const double mib = 1.0 / (1024.0 * 1024.0);
    const double per_triangle =
        s.unique_triangles
            ? static_cast<double>(s.mesh_bytes + std::max<int64_t>(s.embree_bytes, 0)) /
                  static_cast<double>(s.unique_triangles)
            : 0.0;
    fmt::print(
        "memory:     {:.1f} MiB meshes + {:.1f} MiB Embree = {:.1f} bytes per triangle "
        "({} triangles built)\n",
        s.mesh_bytes * mib, s.embree_bytes * mib, per_triangle, s.unique_triangles);
    fmt::print("textures:   {}\n", desc.textures.size());
    if (scene->environment())
        fmt::print("environment: yes (lights the scene and is seen behind it)\n");
    if (s.bounds.is_empty()) {
        fmt::print("bounds:     empty\n");
    } else {
        fmt::print("bounds:     ({:g}, {:g}, {:g}) to ({:g}, {:g}, {:g})\n", s.bounds.min.x,
                   s.bounds.min.y, s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
    }
    fmt::print("render:     {}x{}, {} spp, integrator {}\n", settings.width, settings.height,
               settings.spp, settings.integrator);
    return 0;
}

}  // namespace glint::cli
