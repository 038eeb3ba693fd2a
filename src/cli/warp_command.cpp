#include "warp_command.h"

#include "flags.h"

#include <glint/camera/camera.h>
#include <glint/camera/camera_attributes.h>
#include <glint/core/strict_number.h>
#include <glint/film/image_io.h>
#include <glint/film/tonemap.h>
#include <glint/render/render_job.h>
#include <glint/view/image_warp.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace glint::cli {
namespace {

// --camera "eye=X,Y,Z look_at=X,Y,Z up=X,Y,Z fov=DEG scale=S" (spaces or semicolons between):
// the keys given replace the original camera's.
void apply_camera_flag(const std::string& text, Params& camera) {
    std::string spaced = text;
    std::replace(spaced.begin(), spaced.end(), ';', ' ');
    std::istringstream items(spaced);
    std::string item;
    int count = 0;
    const char* expected =
        "KEY=VALUE items: eye=X,Y,Z look_at=X,Y,Z up=X,Y,Z (points and directions) or fov=DEG, "
        "scale=S (numbers)";
    while (items >> item) {
        const std::size_t equals = item.find('=');
        if (equals == std::string::npos) bad_flag("--camera", text, expected);
        const std::string key = item.substr(0, equals), value = item.substr(equals + 1);
        if (key == "eye" || key == "look_at" || key == "up") {
            const std::optional<Vec3> v = parse_vec3(value);
            if (!v) bad_flag("--camera", text, fmt::format("{}=X,Y,Z with three numbers", key));
            camera.set(key, std::vector<double>{v->x, v->y, v->z}, "--camera");
        } else if (key == "fov" || key == "scale") {
            const std::optional<double> number = parse_finite(value);
            if (!number) bad_flag("--camera", text, fmt::format("{}=NUMBER", key));
            camera.set(key, *number, "--camera");
        } else {
            bad_flag("--camera", text, expected);
        }
        ++count;
    }
    if (count == 0) bad_flag("--camera", text, expected);
}

}  // namespace

CLI::App* add_warp_command(CLI::App& app, WarpOptions& options) {
    CLI::App* cmd = app.add_subcommand(
        "warp",
        "Show a rendered image from a nearby viewpoint by its depth AOV, disocclusions marked");
    cmd->add_option("image", options.image, "Rendered image with a depth AOV (.exr, --aovs)")
        ->required();
    cmd->add_option("--camera", options.camera,
                    "The new viewpoint: \"eye=X,Y,Z look_at=X,Y,Z up=X,Y,Z fov=DEG\" (keys "
                    "not given keep the original camera's)")
        ->required();
    cmd->add_option("-o,--output", options.output, "Output image (.png or .exr)")->required();
    cmd->add_option("--scene", options.scene,
                    "Scene whose camera rendered the image (when its header has none)");
    cmd->add_option("--exposure", options.exposure, "PNG exposure in stops");
    cmd->add_option("--tonemap", options.tone_map, "PNG tone mapping: clip, reinhard or filmic");
    cmd->add_flag("--trusted-scene", options.trusted_scene, trusted_scene_help());
    return cmd;
}

int run_warp(const WarpOptions& options) {
    WriteOptions write;
    if (!options.exposure.empty()) {
        const std::optional<double> stops = parse_finite(options.exposure);
        if (!stops || std::abs(*stops) > 64.0)
            bad_flag("--exposure", options.exposure, "a number of stops from -64 to 64");
        write.exposure = static_cast<float>(*stops);
    }
    if (options.tone_map != "clip" && options.tone_map != "reinhard" &&
        options.tone_map != "filmic")
        bad_flag("--tonemap", options.tone_map, "clip, reinhard or filmic");
    write.tonemap = parse_tonemap(options.tone_map);

    const Image source = read_image(options.image);
    if (source.channel_index("depth.Z") < 0) {
        throw Error(fmt::format(
            "{}: the image has no depth AOV (channel depth.Z) to warp it by; render it to an "
            "EXR file with --aovs (or glint.render{{aovs = true}})",
            options.image));
    }
    // The camera that rendered it: from the scene when given, else from the image's header.
    StoredCamera original{Params("camera", "default camera"), Vec2i(source.width, source.height)};
    if (!options.scene.empty()) {
        const SceneDesc desc = load_scene(options.scene, loader_options(options.trusted_scene, ""));
        if (desc.camera) original.params = *desc.camera;
    } else if (auto stored = camera_from_attributes(source.attributes, options.image)) {
        original = std::move(*stored);
    } else {
        throw Error(fmt::format(
            "{}: the image does not say which camera rendered it (no glint:camera.* header "
            "attributes; glint render writes them with --aovs): give the scene with --scene",
            options.image));
    }
    if (original.resolution != Vec2i(source.width, source.height)) {
        throw Error(fmt::format(
            "{}: the image is {}x{} but its camera rendered {}x{} (a crop window?); only whole "
            "images can be warped",
            options.image, source.width, source.height, original.resolution.x,
            original.resolution.y));
    }
    Params target_params = original.params;
    apply_camera_flag(options.camera, target_params);
    const auto source_camera = make_camera(original.params, original.resolution);
    std::unique_ptr<Camera> target_camera;
    try {
        target_camera = make_camera(target_params, original.resolution);
    } catch (const Error& e) {
        // The original camera was fine: what --camera changed is not.
        throw CLI::ValidationError(fmt::format("--camera '{}': {}", options.camera, e.what()));
    }

    const WarpResult warped =
        warp_image(source, *source_camera, *target_camera, source.width, source.height);
    write_outputs({{options.output, &warped.image, write}});
    const int64_t total = static_cast<int64_t>(source.width) * source.height;
    fmt::print("wrote {}: {} of {} pixels disoccluded ({:.2f} %), marked magenta\n", options.output,
               warped.holes, total, 100.0 * static_cast<double>(warped.holes) / total);
    return 0;
}

}  // namespace glint::cli
