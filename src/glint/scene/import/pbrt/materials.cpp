// pbrt-v4 colours, textures and materials to glint's (see docs/scene-language.md, "pbrt-v4
// files", for the table of what maps to what).
#include <glint/core/error.h>
#include <glint/scene/import/pbrt/spectra.h>
#include <glint/scene/import/pbrt/translator.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace glint {
namespace {

constexpr int kMaxMaterialDepth = 16;  // mix materials naming each other


}  // namespace

std::optional<PbrtValue> PbrtTranslator::colour(const PbrtEntity& e, const std::string& name,
                                                SpectrumUse use) {
    const PbrtParam* p = e.params.find(name);
    if (!p) return std::nullopt;
    if (p->type == "texture") return texture(*p, "spectrum");
    PbrtValue v;
    try {
        if (p->type == "rgb") {
            v.constant = Vec3(p->numbers[0], p->numbers[1], p->numbers[2]);
        } else if (p->type == "float" && p->numbers.size() == 1) {
            v.constant = Vec3(static_cast<float>(p->numbers[0]));
        } else if (p->type == "blackbody") {
            v.constant = blackbody_rgb(p->numbers[0]);
        } else if (p->type == "spectrum" && !p->strings.empty()) {
            const std::string& s = p->strings[0];
            if (auto named = named_spectrum(s)) {
                v.constant = named->rgb;
            } else {
                std::filesystem::path file = s;
                if (file.is_relative()) file = std::filesystem::path(m_scene.directory) / file;
                if (!std::filesystem::exists(file)) {
                    warn(p->where, e.type,
                         fmt::format("spectrum \"{}\" is neither a named spectrum glint knows nor "
                                     "a file; the default is used",
                                     s));
                    ++m_skipped["spectra"];
                    return std::nullopt;
                }
                const std::vector<double> pairs = read_spectrum_file(file.string());
                v.constant =
                    use == SpectrumUse::Illuminant ? illuminant_rgb(pairs) : sampled_rgb(pairs);
            }
        } else if (p->type == "spectrum") {
            v.constant = use == SpectrumUse::Illuminant ? illuminant_rgb(p->numbers)
                                                        : sampled_rgb(p->numbers);
        } else {
            PbrtParams::fail(*p, fmt::format("declared as '{}', expected rgb, spectrum, blackbody "
                                             "or texture",
                                             p->type));
        }
    } catch (const Error& error) {
        if (std::string(error.what()).find(p->where.str()) == 0) throw;
        PbrtParams::fail(*p, error.what());
    }
    if (use == SpectrumUse::Albedo) {
        const Vec3 clamped = glm::clamp(v.constant, Vec3(0.0f), Vec3(1.0f));
        if (clamped != v.constant)
            warn(p->where, e.type,
                 fmt::format("reflectance \"{}\" outside [0, 1] is clamped", name));
        v.constant = clamped;
    }
    return v;
}

std::optional<PbrtValue> PbrtTranslator::scalar(const PbrtEntity& e, const std::string& name) {
    const PbrtParam* p = e.params.find(name);
    if (!p) return std::nullopt;
    if (p->type == "texture") return texture(*p, "float");
    if (p->type != "float" || p->numbers.size() != 1)
        PbrtParams::fail(*p, fmt::format("declared as '{}' with {} values, expected one float or a "
                                         "texture",
                                         p->type, p->numbers.size()));
    return PbrtValue{Vec3(static_cast<float>(p->numbers[0])), std::nullopt};
}

std::optional<PbrtValue> PbrtTranslator::texture(const PbrtParam& p, const std::string& kind) {
    const std::string& name = p.strings.at(0);
    auto& made = kind == "float" ? m_float_textures : m_spectrum_textures;
    auto& constants = kind == "float" ? m_constant_float_textures : m_constant_spectrum_textures;
    if (auto it = made.find(name); it != made.end()) return PbrtValue{Vec3(0.0f), it->second};
    if (auto it = constants.find(name); it != constants.end()) return it->second;
    // The last definition of that name and kind; pbrt keeps float and spectrum textures apart,
    // but a spectrum parameter may take a float texture (its value is grey).
    const PbrtTexture* found = nullptr;
    for (const PbrtTexture& t : m_scene.textures)
        if (t.name == name && t.value_kind == kind) found = &t;
    if (!found)
        for (const PbrtTexture& t : m_scene.textures)
            if (t.name == name) found = &t;
    if (!found) PbrtParams::fail(p, fmt::format("texture \"{}\" is not defined", name));
    if (m_textures_in_progress.count(name))
        PbrtParams::fail(p, fmt::format("texture \"{}\" refers to itself", name));
    m_textures_in_progress.insert(name);
    const PbrtValue v = texture_value(*found);
    m_textures_in_progress.erase(name);
    if (v.texture)
        made[name] = *v.texture;
    else
        constants[name] = v;
    return v;
}

PbrtValue PbrtTranslator::texture_value(const PbrtTexture& t) {
    const PbrtEntity& e = t.entity;
    const bool is_float = t.value_kind == "float";
    auto input = [&](const std::string& name, double fallback) {
        auto v = is_float ? scalar(e, name) : colour(e, name, SpectrumUse::Unbounded);
        return v ? *v : PbrtValue{Vec3(static_cast<float>(fallback)), std::nullopt};
    };
    auto done = [&](PbrtValue v) {
        check_unused(e, "Texture");
        return v;
    };
    if (e.type == "constant") return done(input("value", 1.0));
    if (e.type == "scale" || e.type == "mix") {
        const bool mix = e.type == "mix";
        const PbrtValue a = input(mix ? "tex1" : "tex", mix ? 0.0 : 1.0);
        const PbrtValue b = input(mix ? "tex2" : "scale", 1.0);
        const std::optional<PbrtValue> amount = mix ? scalar(e, "amount") : std::nullopt;
        if (!a.is_texture() && !b.is_texture() && !(amount && amount->is_texture())) {
            if (!mix) return done(PbrtValue{a.constant * b.constant, std::nullopt});
            const float w = amount ? amount->constant.x : 0.5f;
            return done(PbrtValue{(1.0f - w) * a.constant + w * b.constant, std::nullopt});
        }
        if (!mix && !b.is_texture() && b.constant == Vec3(1.0f)) return done(a);
        if (!mix && !a.is_texture() && a.constant == Vec3(1.0f)) return done(b);
        warn(e.where, "Texture",
             fmt::format("\"{}\" of textures is not supported: its first "
                         "input stands in for it",
                         e.type));
        ++m_skipped["textures"];
        return done(a.is_texture() || !b.is_texture() ? a : b);
    }
    if (e.type == "imagemap" || e.type == "checkerboard") {
        Params p(e.type == "imagemap" ? "image" : "checker", where(e.where));
        const std::string mapping = e.params.get_string("mapping", "uv");
        if (mapping != "uv")
            warn(e.where, "Texture",
                 fmt::format("mapping \"{}\" is not supported (uv is used)", mapping));
        const double su = e.params.get_float("uscale", 1.0), sv = e.params.get_float("vscale", 1.0);
        const double du = e.params.get_float("udelta", 0.0), dv = e.params.get_float("vdelta", 0.0);
        if (su != 1.0 || sv != 1.0) p.set("scale", std::vector<double>{su, sv});
        if (du != 0.0 || dv != 0.0) p.set("offset", std::vector<double>{du, dv});
        if (e.type == "imagemap") {
            image_texture(e, p);
        } else {
            if (e.params.get_int("dimension", 2) != 2)
                warn(e.where, "Texture", "a 3D checkerboard is not supported (2D is used)");
            const PbrtValue even = input("tex1", 1.0), odd = input("tex2", 0.0);
            if (even.is_texture() || odd.is_texture())
                warn(e.where, "Texture", "checkerboard of textures: their grey 0.5 stands in");
            p.set("even", numbers_of(even.is_texture() ? Vec3(0.5f) : even.constant));
            p.set("odd", numbers_of(odd.is_texture() ? Vec3(0.5f) : odd.constant));
        }
        m_desc.textures.push_back(std::move(p));
        const ObjectRef ref{"texture", static_cast<int>(m_desc.textures.size()) - 1};
        return done(PbrtValue{Vec3(0.0f), ref});
    }
    warn(e.where, "Texture",
         fmt::format("texture \"{}\" is not supported: a constant 0.5 stands in for it", e.type));
    ++m_skipped["textures"];
    for (const PbrtParam& param : e.params.all()) param.used = true;
    return PbrtValue{Vec3(0.5f), std::nullopt};
}

void PbrtTranslator::image_texture(const PbrtEntity& e, Params& p) {
    const std::string name = e.params.get_string("filename", "");
    if (name.empty())
        throw Error(fmt::format("{}: Texture \"imagemap\": no \"filename\"", e.where.str()));
    const std::string file = resolve(name);
    p.set("file", file);
    const std::string wrap = e.params.get_string("wrap", "repeat");
    if (wrap == "clamp" || wrap == "black")
        p.set("wrap", wrap);
    else if (wrap != "repeat")
        warn(e.where, "Texture", fmt::format("wrap \"{}\" is not supported (repeat)", wrap));
    // pbrt reads 8-bit images as sRGB and float ones as linear unless told: glint's "auto".
    const std::string encoding = e.params.get_string("encoding", "");
    if (encoding == "sRGB")
        p.set("encoding", std::string("srgb"));
    else if (encoding == "linear")
        p.set("encoding", std::string("linear"));
    else if (!encoding.empty())
        warn(e.where, "Texture", fmt::format("encoding \"{}\" is not supported (auto)", encoding));
    // pbrt-v4's default filter is bilinear on the full-resolution image: glint's "none".
    const std::string filter = e.params.get_string("filter", "bilinear");
    p.set("filter", std::string(filter == "ewa"         ? "anisotropic"
                                : filter == "trilinear" ? "trilinear"
                                                        : "none"));
    e.params.find("maxanisotropy");
    if (e.params.get_float("scale", 1.0) != 1.0)
        warn(e.where, "Texture", "imagemap \"scale\" is not supported (ignored)");
    if (e.params.get_bool("invert", false))
        warn(e.where, "Texture", "imagemap \"invert\" is not supported (ignored)");
}

double PbrtTranslator::alpha_of(const PbrtEntity& e, double roughness) const {
    // pbrt-v4's TrowbridgeReitzDistribution::RoughnessToAlpha is the square root.
    return e.params.get_bool("remaproughness", true) ? std::sqrt(std::max(roughness, 0.0))
                                                     : roughness;
}

PbrtValue PbrtTranslator::roughness(const PbrtEntity& e, double* anisotropy,
                                    const std::string& prefix) {
    const std::optional<PbrtValue> r = scalar(e, prefix + "roughness");
    std::optional<PbrtValue> u = scalar(e, prefix + "uroughness");
    std::optional<PbrtValue> v = scalar(e, prefix + "vroughness");
    if (!u) u = r;
    if (!v) v = r;
    if (!u || !v) return PbrtValue{Vec3(0.0f), std::nullopt};
    if (u->is_texture() || v->is_texture()) {
        warn(e.where, "Material",
             "a roughness texture is used as glint's roughness (alpha = "
             "value squared), without pbrt's remapping");
        return u->is_texture() ? *u : *v;
    }
    // glint's roughness is the square root of the GGX alpha.
    const double au = alpha_of(e, u->constant.x), av = alpha_of(e, v->constant.x);
    const double alpha = std::sqrt(au * av);
    if (anisotropy && au != av) {
        const double ratio = std::min(au, av) / std::max(au, av);
        *anisotropy = std::min(1.0, (1.0 - ratio) / 0.9) * (au > av ? 1.0 : -1.0);
    } else if (au != av) {
        warn(e.where, "Material", "anisotropic roughness is not supported here (the mean is used)");
    }
    return PbrtValue{Vec3(static_cast<float>(std::clamp(std::sqrt(alpha), 0.0, 1.0))),
                     std::nullopt};
}

std::optional<ObjectRef> PbrtTranslator::material(const PbrtMaterialRef& ref,
                                                  const PbrtLocation& used_at) {
    if (ref.index >= 0) {
        auto it = m_anonymous_materials.find(ref.index);
        if (it != m_anonymous_materials.end()) return it->second;
        const auto made = make_material(m_scene.materials.at(static_cast<size_t>(ref.index)), 0);
        m_anonymous_materials[ref.index] = made;
        return made;
    }
    return named_material(ref.name, used_at, 0);
}

std::optional<ObjectRef> PbrtTranslator::named_material(const std::string& name,
                                                        const PbrtLocation& used_at, int depth) {
    auto it = m_named_materials.find(name);
    if (it != m_named_materials.end()) return it->second;
    auto def = m_scene.named_materials.find(name);
    if (def == m_scene.named_materials.end())
        throw Error(fmt::format("{}: NamedMaterial \"{}\" is not defined", used_at.str(), name));
    const auto made = make_material(def->second, depth);
    m_named_materials[name] = made;
    return made;
}

std::optional<ObjectRef> PbrtTranslator::make_material(const PbrtEntity& e, int depth) {
    if (depth > kMaxMaterialDepth)
        throw Error(fmt::format("{}: mix materials nest more than {} deep (a cycle?)",
                                e.where.str(), kMaxMaterialDepth));
    const std::string& t = e.type;
    if (t == "interface" || t == "none" || t.empty()) return std::nullopt;
    if (t == "mix") {
        const PbrtParam* names = e.params.find("materials");
        if (!names || names->strings.size() != 2)
            throw Error(fmt::format("{}: mix: \"string materials\" must name two materials",
                                    e.where.str()));
        const std::optional<PbrtValue> amount = scalar(e, "amount");
        const double w = amount && !amount->is_texture() ? amount->constant.x : 0.5;
        warn(e.where, "Material", "\"mix\" is rendered as its more likely material");
        ++m_skipped["materials"];
        check_unused(e, "Material");
        return named_material(names->strings[w > 0.5 ? 1 : 0], e.where, depth + 1);
    }
    Params p("diffuse", where(e.where));
    if (t == "diffuse" || t == "diffusetransmission") {
        p.set("reflectance", colour(e, "reflectance", SpectrumUse::Albedo)
                                 .value_or(PbrtValue{Vec3(t == "diffuse" ? 0.5f : 0.25f), {}})
                                 .as_param());
        if (t == "diffusetransmission") {
            warn(e.where, "Material", "diffusetransmission: the transmitted part is not rendered");
            ++m_skipped["materials"];
            e.params.find("transmittance");
        }
    } else if (t == "coateddiffuse") {
        p = Params("plastic", where(e.where));
        p.set("diffuse", colour(e, "reflectance", SpectrumUse::Albedo)
                             .value_or(PbrtValue{Vec3(0.5f), {}})
                             .as_param());
        p.set("ior", std::clamp(e.params.get_float("eta", 1.5), 1.0, 10.0));
        p.set("roughness", roughness(e, nullptr, "").as_number());
    } else if (t == "conductor" || t == "coatedconductor") {
        conductor(e, p, t == "coatedconductor" ? "conductor." : "");
    } else if (t == "dielectric" || t == "thindielectric") {
        p = Params("dielectric", where(e.where));
        double ior = 1.5;
        if (const PbrtParam* eta = e.params.find("eta")) {
            if (eta->type == "float") {
                ior = e.params.get_float("eta", 1.5);
            } else {
                const auto c = colour(e, "eta", SpectrumUse::Unbounded);
                if (c && !c->is_texture()) {
                    ior = c->constant.y;
                    warn(e.where, "Material",
                         "a spectral \"eta\" is taken at 550 nm (no dispersion)");
                }
            }
        }
        p.set("ior", std::clamp(ior, 0.01, 100.0));
        p.set("roughness", roughness(e, nullptr, "").as_number());
        if (t == "thindielectric") {
            warn(e.where, "Material", "thindielectric is rendered as a dielectric (refracting)");
            ++m_skipped["materials"];
        }
    } else {
        warn(e.where, "Material",
             fmt::format("material \"{}\" is not supported: diffuse 0.5 stands in for it", t));
        ++m_skipped["materials"];
        for (const PbrtParam& param : e.params.all()) param.used = true;
        p.set("reflectance", 0.5);
    }
    e.params.find("type");  // MakeNamedMaterial's
    check_unused(e, "Material");
    m_desc.materials.push_back(std::move(p));
    return ObjectRef{"material", static_cast<int>(m_desc.materials.size()) - 1};
}

void PbrtTranslator::conductor(const PbrtEntity& e, Params& p, const std::string& prefix) {
    p = Params("conductor", where(e.where));
    if (!prefix.empty()) {
        warn(e.where, "Material", "coatedconductor: the coat is not rendered (the bare metal)");
        ++m_skipped["materials"];
    }
    if (const auto r = colour(e, prefix + "reflectance", SpectrumUse::Albedo)) {
        // pbrt-v4 turns a reflectance r into eta = 1, k = 2 sqrt(r) / sqrt(1 - r), whose
        // Fresnel reflectance at normal incidence is r.
        if (r->is_texture()) {
            p.set("eta", 1.0);
            p.set("k", 1000.0);
            p.set("tint", r->as_param());
        } else {
            const Vec3 c = glm::min(r->constant, Vec3(0.9999f));
            const Vec3 k = 2.0f * glm::sqrt(c) / glm::sqrt(Vec3(1.0f) - c);
            p.set("eta", 1.0);
            p.set("k", numbers_of(k));
        }
    } else {
        auto index = [&](const char* name, const char* fallback) {
            const PbrtValue v = colour(e, prefix + name, SpectrumUse::Unbounded)
                                    .value_or(PbrtValue{named_spectrum(fallback)->rgb, {}});
            if (!v.is_texture()) return v.constant;
            warn(e.where, "Material", fmt::format("a textured \"{}\" is not supported", name));
            return named_spectrum(fallback)->rgb;
        };
        p.set("eta", numbers_of(glm::max(index("eta", "metal-Cu-eta"), Vec3(1e-3f))));
        p.set("k", numbers_of(glm::max(index("k", "metal-Cu-k"), Vec3(0.0f))));
    }
    double anisotropy = 0.0;
    p.set("roughness", roughness(e, &anisotropy, prefix).as_number());
    if (anisotropy != 0.0) p.set("anisotropy", anisotropy);
    if (!prefix.empty())
        for (const PbrtParam& param : e.params.all())
            if (param.name.rfind("interface.", 0) == 0 || param.name == "thickness" ||
                param.name == "albedo" || param.name == "g" || param.name == "maxdepth" ||
                param.name == "nsamples")
                param.used = true;
}

}  // namespace glint
