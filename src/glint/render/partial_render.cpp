#include <glint/core/error.h>
#include <glint/core/strings.h>
#include <glint/render/partial_render.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace glint {

namespace {

// What must be equal for parts to be samples of one render: everything that decides a
// sample's value. The scene itself cannot be told apart by the file (docs/cluster.md).
std::string render_fingerprint(const RenderSettings& settings) {
    return fmt::format("{} {}x{} crop {},{},{},{} sampler {} seed {} filter {} {} depth {} aovs {}",
                       settings.integrator, settings.width, settings.height, settings.crop[0],
                       settings.crop[1], settings.crop[2], settings.crop[3], settings.sampler,
                       settings.seed, settings.filter, settings.filter_radius, settings.max_depth,
                       settings.aovs ? 1 : 0);
}

struct PartInfo {
    SampleRange samples;
    int spp = 0;
    std::string render;
};

PartInfo read_part_info(const Image& part, const std::string& name) {
    const std::string* samples = part.attribute("samples");
    const std::string* spp = part.attribute("spp");
    const std::string* render = part.attribute("render");
    if (!samples || !spp || !render) {
        throw Error(
            fmt::format("{}: not a partial render (no glint:samples, glint:spp and "
                        "glint:render attributes; write it with glint render --samples)",
                        name));
    }
    PartInfo info;
    char colon = 0;
    if (std::sscanf(samples->c_str(), "%d%c%d", &info.samples.first, &colon, &info.samples.end) !=
            3 ||
        colon != ':' || std::sscanf(spp->c_str(), "%d", &info.spp) != 1) {
        throw Error(fmt::format("{}: unreadable glint:samples '{}' or glint:spp '{}'", name,
                                *samples, *spp));
    }
    info.render = *render;
    return info;
}

}  // namespace

TileIntegrator* partial_render_integrator(Integrator& integrator, const RenderSettings& settings,
                                          SampleRange samples) {
    auto* tile = dynamic_cast<TileIntegrator*>(&integrator);
    if (!tile) {
        throw Error(
            fmt::format("{}: integrator '{}' renders whole images; sample ranges need a "
                        "tile integrator (path, whitted, photon, ...)",
                        settings.where_of("integrator"), settings.integrator));
    }
    if (settings.adaptive != "none")
        throw Error(fmt::format("{}: sample ranges need uniform sampling (adaptive = 'none')",
                                settings.where_of("adaptive")));
    if (settings.denoise)
        throw Error(fmt::format("{}: a partial render cannot be denoised; denoise the merged image",
                                settings.where_of("denoise")));
    if (!settings.debug.empty())
        throw Error(
            fmt::format("{}: a partial render writes no debug views", settings.where_of("debug")));
    if (samples.first < 0 || samples.first >= samples.end || samples.end > settings.spp) {
        throw Error(fmt::format("--samples {}:{}: expected 0 <= A < B <= spp ({})", samples.first,
                                samples.end, settings.spp));
    }
    return tile;
}

Image partial_sums_image(const Film& film, const RenderSettings& settings, SampleRange samples) {
    Image image = film.sums_image();
    image.attributes = {{"samples", fmt::format("{}:{}", samples.first, samples.end)},
                        {"spp", std::to_string(settings.spp)},
                        {"render", render_fingerprint(settings)}};
    return image;
}

void check_partial_outputs(const RenderSettings& settings) {
    for (const std::string& output : settings.outputs) {
        const std::string extension = lower_extension(output);
        if (extension != ".exr") {
            throw Error(
                fmt::format("{}: a partial render writes its sums to EXR files only, not "
                            "'{}' (merge the parts with glint merge -o {})",
                            settings.where_of("output"), output, output));
        }
    }
}

Image merge_partial_renders(const std::vector<Image>& parts, const std::vector<std::string>& names,
                            std::vector<std::string>& warnings) {
    if (parts.empty()) throw Error("merge: no partial renders given");
    std::vector<PartInfo> infos;
    for (size_t i = 0; i < parts.size(); ++i) infos.push_back(read_part_info(parts[i], names[i]));
    for (size_t i = 1; i < parts.size(); ++i) {
        if (infos[i].render != infos[0].render || infos[i].spp != infos[0].spp ||
            parts[i].width != parts[0].width || parts[i].height != parts[0].height) {
            throw Error(fmt::format(
                "{} and {} are parts of different renders ({}x{}, {} spp, {}; "
                "{}x{}, {} spp, {})",
                names[0], names[i], parts[0].width, parts[0].height, infos[0].spp, infos[0].render,
                parts[i].width, parts[i].height, infos[i].spp, infos[i].render));
        }
    }
    // Order by range to find overlaps (a sample counted twice) and gaps.
    std::vector<size_t> order(parts.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return infos[a].samples.first < infos[b].samples.first; });
    int covered = 0;
    int missing = 0;
    for (size_t k = 0; k < order.size(); ++k) {
        const PartInfo& info = infos[order[k]];
        if (k > 0 && info.samples.first < infos[order[k - 1]].samples.end) {
            throw Error(fmt::format("{} (samples {}:{}) overlaps {} (samples {}:{})",
                                    names[order[k]], info.samples.first, info.samples.end,
                                    names[order[k - 1]], infos[order[k - 1]].samples.first,
                                    infos[order[k - 1]].samples.end));
        }
        missing += info.samples.first - covered;
        covered = info.samples.end;
    }
    missing += infos[0].spp - covered;
    if (missing > 0) {
        warnings.push_back(fmt::format(
            "the parts hold {} of the render's {} samples per pixel: the image is an unbiased "
            "estimate, but not the image of a --spp {} render",
            infos[0].spp - missing, infos[0].spp, infos[0].spp));
    }
    const bool aovs = parts[0].channel_index("sum.aov_weight.0") >= 0;
    Film film(parts[0].width, parts[0].height, aovs);
    for (size_t i = 0; i < parts.size(); ++i) {
        try {
            film.add_sums_image(parts[i]);
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}", names[i], e.what()));
        }
    }
    return film.resolve();
}

}  // namespace glint
