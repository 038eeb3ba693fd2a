#pragma once
// `glint view`: a window showing a scene as it renders pass by pass, with camera controls,
// light editing and a panel (GLFW, OpenGL 3.3 and Dear ImGui, all inside src/viewer/).
#include <glint/scene/render_settings.h>
#include <glint/scene/scene_desc.h>

#include <atomic>
#include <optional>
#include <string>

namespace glint::viewer {

struct ViewerOptions {
    std::string scene_path;  ///< for the window title and default save names
    float exposure = 0.0f;   ///< stops
    std::string tone_map = "clip";
    int reduced_scale = 4;  ///< the first pass after a change at 1/reduced_scale size
    bool hide_panel = false;
    /// Temporal mode (reprojected history after a camera move); unset: on for the preview
    /// integrator, off for the others.
    std::optional<bool> temporal;
    /// The real-time denoiser (SVGF) on every frame shown.
    bool svgf = false;
    // Headless use (tests, screenshots): render `frames` full passes in all, then write
    // what the window shows to `screenshot` and exit. 0: interactive.
    int frames = 0;
    std::string screenshot;
    // A scripted camera move: after `orbit_after` full passes, orbit by `orbit_degrees`
    // about the target (0: none).
    float orbit_degrees = 0.0f;
    int orbit_after = 0;
    /// Set to a signal number (SIGINT, SIGTERM) by the command's handler: the window closes
    /// (interactive), or glint::Interrupted is thrown (headless). Null: never.
    const std::atomic<int>* interrupt = nullptr;
};

/// Opens the window and runs until it is closed (or, headless, until the screenshot is
/// written); settings.spp is the number of passes after which accumulation stops. Returns
/// the exit code. Throws glint::Error for a bad scene or when no window can be opened (no
/// display).
int run_viewer(const SceneDesc& desc, const RenderSettings& settings, const ViewerOptions& options);

}  // namespace glint::viewer
