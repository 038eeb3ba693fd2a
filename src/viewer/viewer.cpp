// The window: GLFW for the window and input, OpenGL 3.3 core for the texture the image is
// drawn from, Dear ImGui for the panel. The image is drawn by ImGui as a textured
// rectangle behind the panel, so this file needs no shaders of its own.
#include <glint/core/error.h>
#include <glint/film/image_io.h>
#include <glint/render/render_job.h>
#include <glint/view/camera_controller.h>
#include <glint/view/display.h>
#include <glint/view/light_edits.h>
#include <viewer/render_thread.h>
#include <viewer/viewer.h>

#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace glint::viewer {
namespace {

// GLFW reports errors through a callback; the last one names why a window did not open.
std::string g_glfw_error;  // written only on the UI thread, by GLFW, during glfw calls
void on_glfw_error(int code, const char* description) {
    g_glfw_error = fmt::format("{} (GLFW error {:#x})", description, code);
}

// GLFW's library state, for exactly the life of the viewer.
struct GlfwLibrary {
    GlfwLibrary() {
        glfwSetErrorCallback(on_glfw_error);
        if (!glfwInit()) {
            throw Error(fmt::format(
                "glint view needs a display and none could be opened: {}. Set DISPLAY, or run "
                "it under a virtual X server: xvfb-run -a glint view ...",
                g_glfw_error.empty() ? "no reason given" : g_glfw_error));
        }
    }
    ~GlfwLibrary() { glfwTerminate(); }
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

struct WindowDeleter {
    void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
};
using Window = std::unique_ptr<GLFWwindow, WindowDeleter>;

// Dear ImGui's context and its GLFW and OpenGL backends.
struct ImGuiLayer {
    explicit ImGuiLayer(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 330");
    }
    ~ImGuiLayer() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
};

// The texture the image is shown from, one texel per image pixel.
class ImageTexture {
public:
    ImageTexture(int width, int height) : m_width(width), m_height(height) {
        glGenTextures(1, &m_id);
        glBindTexture(GL_TEXTURE_2D, m_id);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
    }
    ~ImageTexture() { glDeleteTextures(1, &m_id); }
    ImageTexture(const ImageTexture&) = delete;
    ImageTexture& operator=(const ImageTexture&) = delete;

    void upload(const std::vector<uint8_t>& rgba) {
        glBindTexture(GL_TEXTURE_2D, m_id);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.data());
    }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(m_id)); }

private:
    GLuint m_id = 0;
    int m_width, m_height;
};

// The framebuffer as RGBA bytes, top row first: what the window shows.
std::vector<uint8_t> read_framebuffer(int width, int height) {
    std::vector<uint8_t> bottom_up(static_cast<size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    std::vector<uint8_t> rgba(bottom_up.size());
    const size_t row = static_cast<size_t>(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(&bottom_up[(height - 1 - y) * row], row, &rgba[y * row]);
    return rgba;
}

// Everything the panel changes, and the camera.
struct UiState {
    float exposure = 0.0f;
    int tone_map = 0;  // index into kToneMaps
    bool show_panel = true;
    int integrator = 0;
    int light = 0;
    bool denoise = false;   // the network denoises the image while the camera stands still
    bool temporal = false;  // reprojected history blended in after a camera move
    bool svgf = false;      // the real-time denoiser on every frame
    std::array<char, 512> save_path{};
    std::string message;  // the last save, camera line or error, shown in the panel
};
constexpr const char* kToneMaps[] = {"clip", "reinhard", "filmic"};

class Viewer {
public:
    Viewer(const SceneDesc& desc, const RenderSettings& settings, const ViewerOptions& options)
        : m_settings(settings),
          m_options(options),
          m_controller(desc.camera ? &*desc.camera : nullptr),
          m_lights(desc),
          m_integrators(ProgressiveSession::progressive_integrators(settings)) {
        m_ui.exposure = options.exposure;
        m_ui.tone_map = static_cast<int>(parse_tonemap(options.tone_map));
        m_ui.show_panel = !options.hide_panel;
        const auto it = std::find(m_integrators.begin(), m_integrators.end(), settings.integrator);
        m_ui.integrator =
            it == m_integrators.end() ? 0 : static_cast<int>(it - m_integrators.begin());
        const std::string stem = std::filesystem::path(options.scene_path).stem().string();
        fmt::format_to_n(m_ui.save_path.data(), m_ui.save_path.size() - 1, "{}.view.png", stem);

        SessionOptions session_options;
        session_options.reduced_scale = options.reduced_scale;
        session_options.aovs = true;  // for the denoiser
        session_options.realtime = true;
        session_options.temporal = options.temporal.value_or(settings.integrator == "preview");
        m_ui.temporal = session_options.temporal;
        m_ui.svgf = options.svgf;
        ProgressiveSession session(desc, settings, session_options);
        const Bounds3 bounds = session.scene().stats().bounds;
        m_scene_size = bounds.is_empty() ? 1.0f : glm::length(bounds.max - bounds.min);
        m_thread = std::make_unique<RenderThread>(std::move(session), options.frames > 0 ? 0 : -1);
        m_ui.denoise = settings.denoise;
        if (m_ui.denoise) m_thread->set_denoise(true);
        if (m_ui.svgf) m_thread->set_svgf(true);
    }

    int run() {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        const std::string title = fmt::format("glint view {}", m_options.scene_path);
        Window window(
            glfwCreateWindow(m_settings.width, m_settings.height, title.c_str(), nullptr, nullptr));
        if (!window) {
            throw Error(fmt::format("glint view could not open an OpenGL 3.3 window: {}",
                                    g_glfw_error.empty() ? "no reason given" : g_glfw_error));
        }
        glfwMakeContextCurrent(window.get());
        // Headless frames must not wait for a vertical blank that a virtual server fakes.
        glfwSwapInterval(m_options.frames > 0 ? 0 : 1);
        const ImGuiLayer imgui(window.get());
        ImageTexture texture(m_settings.width, m_settings.height);
        return m_options.frames > 0 ? run_headless(window.get(), texture)
                                    : run_interactive(window.get(), texture);
    }

private:
    // Takes the newest frame from the render thread and uploads it; true when there was one.
    bool update_texture(ImageTexture& texture, bool force) {
        const bool fresh = m_thread->latest(m_frame);
        if (fresh && !m_frame.error.empty()) m_ui.message = m_frame.error;
        if ((fresh || force) && !m_frame.image.pixels.empty()) {
            m_shown = display_pixels(
                m_frame.image, ToneMapping{parse_tonemap(kToneMaps[m_ui.tone_map]), m_ui.exposure});
            texture.upload(m_shown);
        }
        return fresh;
    }

    void draw(GLFWwindow* window, const ImageTexture& texture) {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        glViewport(0, 0, width, height);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const ImVec2 size = ImGui::GetIO().DisplaySize;
        ImGui::GetBackgroundDrawList()->AddImage(texture.id(), ImVec2(0, 0), size);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    void new_frame() {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
    }

    int run_interactive(GLFWwindow* window, ImageTexture& texture) {
        while (!glfwWindowShouldClose(window) && interrupted() == 0) {
            // Wake at least 60 times a second for new passes; input wakes it at once.
            glfwWaitEventsTimeout(1.0 / 60.0);
            new_frame();
            bool restyle = false;
            handle_input(window);
            if (m_ui.show_panel) restyle = panel();
            update_texture(texture, restyle);
            draw(window, texture);
            glfwSwapBuffers(window);
        }
        return 0;
    }

    // N full passes, one at a time, a scripted move on the way; then the screenshot.
    int run_headless(GLFWwindow* window, ImageTexture& texture) {
        int frames = 0;
        m_thread->allow_passes(1);
        while (frames < m_options.frames) {
            if (glfwWindowShouldClose(window)) {
                throw Error(fmt::format("the window was closed after {} of the {} frames", frames,
                                        m_options.frames));
            }
            // Draw only what is new: on two cores a spinning window would slow the passes.
            glfwWaitEventsTimeout(0.005);
            if (const int signal = interrupted()) throw Interrupted(signal);
            if (m_thread->version() == m_frame.version) continue;
            new_frame();
            if (m_ui.show_panel) panel();
            const bool fresh = update_texture(texture, false);
            draw(window, texture);
            glfwSwapBuffers(window);
            if (!m_frame.error.empty()) throw Error(m_frame.error);
            if (!fresh || m_frame.reduced) continue;
            ++frames;
            fmt::print(stderr, "frame {}: {} spp, {} pass {:.1f} ms{}{}\n", frames, m_frame.passes,
                       m_frame.integrator, m_frame.pass_seconds * 1e3,
                       m_frame.temporal ? ", with reprojected history" : "",
                       m_frame.svgf ? ", SVGF" : "");
            if (m_options.orbit_degrees != 0.0f && frames == m_options.orbit_after) {
                m_controller.orbit(m_options.orbit_degrees, 0.0f);
                m_thread->request_camera(m_controller.params());
                fmt::print(stderr, "orbit {} degrees: {}\n", m_options.orbit_degrees,
                           m_controller.lua());
            }
            if (frames < m_options.frames) m_thread->allow_passes(1);
        }
        // The last frame once more, so the back buffer surely holds it, then read it back.
        new_frame();
        if (m_ui.show_panel) panel();
        draw(window, texture);
        glFinish();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        const Image shot = image_from_display(read_framebuffer(width, height), width, height);
        glfwSwapBuffers(window);
        if (!m_options.screenshot.empty()) {
            write_outputs({{m_options.screenshot, &shot, {}}});
            fmt::print(stderr, "wrote {} ({}x{}, {} spp)\n", m_options.screenshot, width, height,
                       m_frame.passes);
        }
        return 0;
    }

    int interrupted() const { return m_options.interrupt ? m_options.interrupt->load() : 0; }

    void handle_input(GLFWwindow* window) {
        const ImGuiIO& io = ImGui::GetIO();
        bool moved = false;
        if (!io.WantCaptureMouse) {
            const float height = std::max(1.0f, io.DisplaySize.y);
            const bool pan_drag =
                io.MouseDown[1] || io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift);
            if (pan_drag && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
                m_controller.pan(-io.MouseDelta.x / height, io.MouseDelta.y / height);
                moved = true;
            } else if (io.MouseDown[0] && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
                m_controller.orbit(-0.25f * io.MouseDelta.x, 0.25f * io.MouseDelta.y);
                moved = true;
            }
            if (io.MouseWheel != 0.0f) {
                m_controller.zoom(std::pow(0.9f, io.MouseWheel));
                moved = true;
            }
        }
        if (!io.WantCaptureKeyboard) {
            // Fly: a tenth of the scene per second, four times faster with shift.
            const float step = 0.1f * m_scene_size * io.DeltaTime * (io.KeyShift ? 4.0f : 1.0f);
            Vec3 fly(0.0f);
            auto held = [&](int key) {
                return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f;
            };
            fly.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
            fly.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
            fly.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
            if (fly != Vec3(0.0f)) {
                m_controller.fly(fly * step);
                moved = true;
            }
            if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) {
                m_controller.reset();
                moved = true;
            }
            if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) {
                m_ui.message = m_controller.lua();
                fmt::print("{}\n", m_ui.message);
                std::fflush(stdout);
            }
            if (ImGui::IsKeyPressed(GLFW_KEY_H, false)) m_ui.show_panel = !m_ui.show_panel;
            if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(window, 1);
            move_light_by_keys(window);
        }
        if (moved) m_thread->request_camera(m_controller.params());
    }

    // The selected light moves with the arrow keys (x and z) and page up and down (y).
    void move_light_by_keys(GLFWwindow* window) {
        if (m_lights.lights().empty()) return;
        EditableLight& light = m_lights.lights()[m_ui.light];
        if (!light.movable) return;
        auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        const Vec3 direction(held(GLFW_KEY_RIGHT) - held(GLFW_KEY_LEFT),
                             held(GLFW_KEY_PAGE_UP) - held(GLFW_KEY_PAGE_DOWN),
                             held(GLFW_KEY_UP) - held(GLFW_KEY_DOWN));
        if (direction == Vec3(0.0f)) return;
        light.offset += direction * (0.1f * m_scene_size * ImGui::GetIO().DeltaTime);
        m_thread->request_lights(m_lights);
    }

    // The panel; returns whether the display settings changed (re-encode the image).
    bool panel() {
        bool restyle = false;
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.8f);
        ImGui::Begin("glint", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::PushItemWidth(ImGui::GetFontSize() * 11.0f);
        if (!m_integrators.empty()) {
            const char* current = m_integrators[m_ui.integrator].c_str();
            if (ImGui::BeginCombo("integrator", current)) {
                for (int i = 0; i < static_cast<int>(m_integrators.size()); ++i) {
                    if (ImGui::Selectable(m_integrators[i].c_str(), i == m_ui.integrator) &&
                        i != m_ui.integrator) {
                        m_ui.integrator = i;
                        m_thread->request_integrator(m_integrators[i]);
                    }
                }
                ImGui::EndCombo();
            }
        }
        restyle |= ImGui::SliderFloat("exposure", &m_ui.exposure, -8.0f, 8.0f, "%.2f stops");
        restyle |= ImGui::Combo("tone mapping", &m_ui.tone_map, kToneMaps, 3);
        if (ImGui::Checkbox("denoise when still", &m_ui.denoise))
            m_thread->set_denoise(m_ui.denoise);
        if (ImGui::Checkbox("temporal reprojection", &m_ui.temporal))
            m_thread->set_temporal(m_ui.temporal);
        if (ImGui::Checkbox("denoise (SVGF)", &m_ui.svgf)) m_thread->set_svgf(m_ui.svgf);
        ImGui::Text("%d / %d spp%s%s", m_frame.passes, m_settings.spp,
                    m_frame.reduced    ? " (reduced preview)"
                    : m_frame.denoised ? " (denoised)"
                    : m_frame.svgf     ? " (SVGF)"
                                       : "",
                    m_frame.temporal ? " + history" : "");
        const double rate =
            m_frame.pass_seconds > 0.0 ? m_frame.pass_samples / m_frame.pass_seconds : 0.0;
        ImGui::Text("%.2f M samples/s, pass %.1f ms", rate * 1e-6, m_frame.pass_seconds * 1e3);
        ImGui::Text("frame %.1f ms", ImGui::GetIO().DeltaTime * 1e3);
        if (!m_lights.lights().empty()) {
            ImGui::Separator();
            std::vector<const char*> names;
            for (const EditableLight& light : m_lights.lights())
                names.push_back(light.name.c_str());
            ImGui::Combo("light", &m_ui.light, names.data(), static_cast<int>(names.size()));
            EditableLight& light = m_lights.lights()[m_ui.light];
            bool changed = false;
            if (light.movable) {
                changed |= ImGui::DragFloat3("offset", &light.offset.x, 0.005f * m_scene_size);
            }
            changed |= ImGui::SliderFloat("power", &light.power_scale, 0.0f, 16.0f, "x %.3f",
                                          ImGuiSliderFlags_Logarithmic);
            if (changed) m_thread->request_lights(m_lights);
        }
        ImGui::Separator();
        ImGui::InputText("file", m_ui.save_path.data(), m_ui.save_path.size());
        if (ImGui::Button("save")) save();
        ImGui::SameLine();
        if (ImGui::Button("print camera")) {
            m_ui.message = m_controller.lua();
            fmt::print("{}\n", m_ui.message);
            std::fflush(stdout);
        }
        if (!m_ui.message.empty()) {
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
            ImGui::TextUnformatted(m_ui.message.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::PopItemWidth();
        ImGui::End();
        return restyle;
    }

    // .png: the bytes shown (exposure and tone mapping applied); .exr: linear radiance.
    void save() {
        const std::string path = m_ui.save_path.data();
        try {
            if (m_frame.image.pixels.empty()) throw Error("nothing rendered yet");
            const std::string extension = std::filesystem::path(path).extension().string();
            // Written as `glint render` writes: complete, or not at all.
            if (extension == ".png" || extension == ".PNG") {
                const Image shown =
                    image_from_display(m_shown, m_frame.image.width, m_frame.image.height);
                write_outputs({{path, &shown, {}}});
            } else {
                write_outputs({{path, &m_frame.image, {}}});
            }
            m_ui.message = fmt::format("wrote {} ({} spp{}{})", path, m_frame.passes,
                                       m_frame.svgf ? ", SVGF" : "",
                                       m_frame.temporal ? ", with reprojected history" : "");
        } catch (const Error& e) {
            m_ui.message = e.what();
        }
    }

    RenderSettings m_settings;
    ViewerOptions m_options;
    CameraController m_controller;
    LightEdits m_lights;
    std::vector<std::string> m_integrators;
    float m_scene_size = 1.0f;
    UiState m_ui;
    Frame m_frame;
    std::vector<uint8_t> m_shown;  // the image's bytes as displayed
    std::unique_ptr<RenderThread> m_thread;
};

}  // namespace

int run_viewer(const SceneDesc& desc, const RenderSettings& settings,
               const ViewerOptions& options) {
    const GlfwLibrary glfw;
    // Made before the window: a bad scene is reported without one flashing up.
    Viewer viewer(desc, settings, options);
    return viewer.run();
}

}  // namespace glint::viewer
