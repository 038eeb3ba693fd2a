#include <glint/core/error.h>
#include <glint/scene/import/pbrt/parser.h>
#include <glint/scene/import/pbrt/translator.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {


}  // namespace

ParamValue PbrtValue::as_number() const {
    if (texture) return *texture;
    return static_cast<double>(constant.x);
}

ParamValue PbrtValue::as_param() const {
    if (texture) return *texture;
    return numbers_of(constant);
}

PbrtTranslator::PbrtTranslator(const PbrtScene& scene, SceneDesc& desc, const ImportTarget& target)
    : m_scene(scene), m_desc(desc), m_target(target), m_mirror(world_mirror(scene.camera)) {}

Mat4 PbrtTranslator::world_mirror(const std::optional<PbrtCamera>& camera) {
    // pbrt's default camera (none given) is the identity: not a mirror.
    const float det = camera ? glm::determinant(Mat3(camera->camera_to_world)) : 1.0f;
    return det > 0.0f ? glm::scale(Mat4(1.0f), Vec3(-1.0f, 1.0f, 1.0f)) : Mat4(1.0f);
}

std::string PbrtTranslator::where(const PbrtLocation& at) const {
    if (m_target.where == m_target.path) return at.str();
    return fmt::format("{}: {}", m_target.where, at.str());
}

void PbrtTranslator::warn(const PbrtLocation& at, const std::string& directive,
                          const std::string& what) {
    m_desc.warnings.push_back(fmt::format("{}: {}: {}", where(at), directive, what));
}

void PbrtTranslator::check_unused(const PbrtEntity& e, const std::string& directive) {
    for (const PbrtParam* p : e.params.unused()) {
        m_desc.warnings.push_back(
            fmt::format("{}: {} \"{}\": parameter \"{} {}\" is not supported "
                        "(ignored)",
                        where(p->where), directive, e.type, p->type, p->name));
        ++m_skipped["parameters"];
    }
}

Transform PbrtTranslator::glint_transform(const Mat4& pbrt_to_world) const {
    return Transform(m_target.transform.matrix() * m_mirror * pbrt_to_world);
}

Bounds3 PbrtTranslator::run() {
    const size_t warnings_before = m_desc.warnings.size();
    const bool is_scene = m_target.where == m_target.path;
    for (const std::string& w : m_scene.warnings)
        m_desc.warnings.push_back(is_scene ? w : fmt::format("{}: {}", m_target.where, w));
    render_settings();
    camera();
    for (const PbrtLight& l : m_scene.lights) light(l);
    shapes();
    instances();
    std::string read;
    for (const auto& [name, count] : m_scene.directive_counts)
        read += fmt::format("{}{} {}", read.empty() ? "" : ", ", count, name);
    m_desc.notes.push_back(fmt::format("{}: read {}", m_target.path, read));
    std::string skipped;
    for (const auto& [what, count] : m_skipped)
        skipped += fmt::format("{}{} {}", skipped.empty() ? "" : ", ", count, what);
    m_desc.notes.push_back(fmt::format("{}: {} warnings; not rendered as pbrt-v4 would: {}",
                                       m_target.path, m_desc.warnings.size() - warnings_before,
                                       skipped.empty() ? "nothing" : skipped));
    return m_bounds;
}

void PbrtTranslator::camera() {
    if (m_desc.camera) return;
    // Without a Camera directive pbrt-v4 looks from the origin along +z, fov 90.
    const PbrtCamera fallback{
        PbrtEntity{"perspective", PbrtParams(), PbrtLocation{m_target.path, 0}}, Mat4(1.0f)};
    const PbrtCamera& c = m_scene.camera ? *m_scene.camera : fallback;
    const PbrtEntity& e = c.entity;
    const Mat4 to_world = m_target.transform.matrix() * m_mirror * c.camera_to_world;
    const Vec3 eye(to_world * Vec4(0, 0, 0, 1));
    const Vec3 forward = glm::normalize(Vec3(to_world * Vec4(0, 0, 1, 0)));
    const Vec3 up = glm::normalize(Vec3(to_world * Vec4(0, 1, 0, 0)));
    Params p("camera", where(e.where));
    p.set("eye", numbers_of(eye));
    p.set("look_at", numbers_of(eye + forward));
    p.set("up", numbers_of(up));
    // pbrt's screen window spans [-1, 1] on the image's shorter side (frameaspectratio
    // decides which); glint's fov is the vertical one.
    const int width = m_scene.film ? m_scene.film->params.get_int("xresolution", 1280) : 1280;
    const int height = m_scene.film ? m_scene.film->params.get_int("yresolution", 720) : 720;
    const double frame =
        e.params.get_float("frameaspectratio", static_cast<double>(width) / std::max(height, 1));
    const double half_height = frame > 1.0 ? 1.0 : 1.0 / frame;
    if (e.params.has("screenwindow"))
        warn(e.where, "Camera", "\"screenwindow\" is not supported (the full window is used)");
    const double shutter =
        e.params.get_float("shutterclose", 1.0) - e.params.get_float("shutteropen", 0.0);
    m_imaging_ratio *= shutter;
    if (e.type == "orthographic") {
        p.set("type", std::string("orthographic"));
        p.set("scale", 2.0 * half_height);
        if (e.params.get_float("lensradius", 0.0) > 0.0)
            warn(e.where, "Camera", "an orthographic camera's lens is not supported (pinhole)");
        e.params.find("focaldistance");
    } else {
        if (e.type != "perspective")
            warn(e.where, "Camera",
                 fmt::format("camera \"{}\" is not supported: a perspective camera with a 90 "
                             "degree field of view stands in for it",
                             e.type));
        const double fov = e.type == "perspective" ? e.params.get_float("fov", 90.0) : 90.0;
        if (!(fov > 0.0 && fov < 180.0))
            throw Error(fmt::format("{}: Camera: \"fov\" must be in (0, 180)", e.where.str()));
        const double tan_half = std::tan(glm::radians(fov) / 2.0) * half_height;
        p.set("fov", glm::degrees(2.0 * std::atan(tan_half)));
        const double lens = e.params.get_float("lensradius", 0.0);
        const double focus = e.params.get_float("focaldistance", 1e6);
        if (lens > 0.0) {
            p.set("aperture", lens);
            p.set("focus_distance", focus);
        }
    }
    check_unused(e, "Camera");
    m_desc.camera = std::move(p);
    m_desc.camera_imported = true;
}

void PbrtTranslator::render_settings() {
    const bool is_scene = m_target.where == m_target.path;
    Params r("render", m_scene.film ? where(m_scene.film->where) : m_target.path);
    // Film "rgb": resolution, crop, output file, ISO (pbrt's imaging ratio, which scales
    // every emitter: glint's EXR output has no exposure of its own).
    int width = 1280, height = 720;
    if (const auto& film = m_scene.film) {
        if (film->type != "rgb")
            warn(film->where, "Film",
                 fmt::format("film \"{}\" is rendered as \"rgb\"", film->type));
        width = film->params.get_int("xresolution", 1280);
        height = film->params.get_int("yresolution", 720);
        m_imaging_ratio *= film->params.get_float("iso", 100.0) / 100.0;
        const std::string file = film->params.get_string("filename", "");
        const std::string ext = std::filesystem::path(file).extension().string();
        if (ext == ".exr" || ext == ".png")
            r.set("output", file);
        else if (!file.empty())
            warn(film->where, "Film",
                 fmt::format("output \"{}\": glint writes .exr or .png; "
                             "the default output is used",
                             file));
        const std::vector<double> cw = film->params.get_floats("cropwindow");
        const std::vector<int> pb = film->params.get_ints("pixelbounds");
        if (cw.size() == 4) {
            r.set("crop", std::vector<double>{std::ceil(width * cw[0]), std::ceil(height * cw[2]),
                                              std::ceil(width * cw[1]), std::ceil(height * cw[3])});
        } else if (pb.size() == 4) {
            r.set("crop",
                  std::vector<double>{double(pb[0]), double(pb[2]), double(pb[1]), double(pb[3])});
        }
        film->params.find("savefp16");  // glint writes 32-bit floats
        if (film->params.get_float("maxcomponentvalue", INFINITY) < INFINITY)
            warn(film->where, "Film", "\"maxcomponentvalue\" is not supported (no clamping)");
        check_unused(*film, "Film");
    }
    r.set("width", static_cast<double>(width));
    r.set("height", static_cast<double>(height));
    int spp = 16;
    std::string sampler = "sobol";
    if (const auto& s = m_scene.sampler) {
        if (s->type == "stratified") {
            sampler = "stratified";
            spp = s->params.get_int("xsamples", 4) * s->params.get_int("ysamples", 4);
            s->params.find("jitter");
        } else {
            spp = s->params.get_int("pixelsamples", 16);
            if (s->type == "independent")
                sampler = "independent";
            else if (s->type != "zsobol" && s->type != "sobol" && s->type != "paddedsobol" &&
                     s->type != "halton" && s->type != "pmj02bn")
                warn(s->where, "Sampler",
                     fmt::format("unknown sampler \"{}\": sobol is used", s->type));
            s->params.find("randomization");
        }
        if (s->params.has("seed")) r.set("seed", static_cast<double>(s->params.get_int("seed", 0)));
        check_unused(*s, "Sampler");
    }
    r.set("spp", static_cast<double>(std::max(spp, 1)));
    r.set("sampler", sampler);
    int max_depth = 5;
    std::string integrator = "path";
    if (const auto& in = m_scene.integrator) {
        max_depth = in->params.get_int("maxdepth", 5);
        const std::string& t = in->type;
        if (t == "bdpt" || t == "mlt" || t == "sppm") {
            integrator = t;
        } else if (t == "lightpath") {
            integrator = "light";
        } else if (t != "path" && t != "volpath") {
            warn(in->where, "Integrator",
                 fmt::format("integrator \"{}\" is not in glint: the path tracer stands in for it",
                             t));
        }
        if (t == "volpath")
            warn(in->where, "Integrator",
                 "volpath: glint has no media yet; rendered with \"path\"");
        if (t == "sppm") {
            if (in->params.has("photonsperiteration"))
                r.set("photons",
                      static_cast<double>(in->params.get_int("photonsperiteration", -1)));
            if (in->params.has("radius"))
                r.set("photon_radius", in->params.get_float("radius", 1.0));
            if (in->params.has("iterations"))
                r.set("spp", static_cast<double>(in->params.get_int("iterations", 64)));
        }
        if (in->params.has("regularize") && in->params.get_bool("regularize", false))
            warn(in->where, "Integrator", "\"regularize\" is not supported (ignored)");
        check_unused(*in, "Integrator");
    }
    r.set("max_depth", static_cast<double>(std::clamp(max_depth, -1, 1024)));
    r.set("integrator", integrator);
    // pbrt-v4's default pixel filter is a Gaussian of radius 1.5 and sigma 0.5, glint's
    // Gaussian defaults.
    std::string filter = "gaussian";
    double radius = 1.5;
    if (const auto& f = m_scene.filter) {
        const double x = f->params.get_float("xradius", -1.0);
        const double y = f->params.get_float("yradius", -1.0);
        if (f->type == "box") {
            filter = "box";
            radius = 0.5;
        } else if (f->type == "mitchell") {
            filter = "mitchell";
            radius = 2.0;
            if (f->params.get_float("B", 1.0 / 3.0) != 1.0 / 3.0 ||
                f->params.get_float("C", 1.0 / 3.0) != 1.0 / 3.0)
                warn(f->where, "PixelFilter", "mitchell: B and C other than 1/3 are not supported");
        } else if (f->type == "gaussian") {
            if (f->params.get_float("sigma", 0.5) != 0.5)
                warn(f->where, "PixelFilter", "gaussian: a sigma other than 0.5 is not supported");
        } else {
            warn(
                f->where, "PixelFilter",
                fmt::format("filter \"{}\" is not in glint: a Gaussian stands in for it", f->type));
        }
        if (x > 0.0) radius = x;
        if (y > 0.0 && y != radius)
            warn(f->where, "PixelFilter",
                 "different x and y radii are not supported (xradius is used)");
        check_unused(*f, "PixelFilter");
    }
    r.set("filter", filter);
    r.set("filter_radius", radius);
    if (is_scene && !m_desc.render) m_desc.render = std::move(r);
}

Bounds3 import_pbrt(SceneDesc& desc, const ImportTarget& target) {
    if (target.material)
        throw Error(fmt::format("{}: 'material' cannot replace the materials of a pbrt scene",
                                target.path));
    const PbrtScene scene = parse_pbrt_file(target.path);
    return PbrtTranslator(scene, desc, target).run();
}

}  // namespace glint
