#include "merge_command.h"

#include "flags.h"

#include <glint/core/strict_number.h>
#include <glint/film/image_io.h>
#include <glint/render/render_job.h>

#include <fmt/format.h>

#include <cmath>

namespace glint::cli {

CLI::App* add_merge_command(CLI::App& app, MergeOptions& options) {
    CLI::App* merge_cmd = app.add_subcommand(
        "merge", "Add partial renders (glint render --samples A:B) into one image");
    merge_cmd->add_option("parts", options.parts, "Partial renders (.exr)")->required();
    merge_cmd->add_option("-o,--output", options.outputs, "Output image, .exr or .png (repeatable)")
        ->required()
        ->allow_extra_args(false);
    merge_cmd->add_option("--exposure", options.exposure, "Exposure in stops for PNG output");
    merge_cmd->add_option("--tonemap", options.tonemap,
                          "Tone curve of PNG output: clip (default), reinhard, filmic (ACES fit)");
    merge_cmd->add_flag("-q,--quiet", options.quiet, "No summary on stderr");
    return merge_cmd;
}

int run_merge(const MergeOptions& options) {
    WriteOptions write_options;
    if (!options.exposure.empty()) {
        const auto stops = parse_finite(options.exposure);
        if (!stops || std::abs(*stops) > 100.0)
            bad_flag("--exposure", options.exposure, "a number of stops from -100 to 100");
        write_options.exposure = static_cast<float>(*stops);
    }
    if (!options.tonemap.empty()) {
        try {
            write_options.tonemap = parse_tonemap(options.tonemap);
        } catch (const Error& e) {
            throw CLI::ValidationError(fmt::format("--tonemap: {}", e.what()));
        }
    }
    std::vector<Image> parts;
    for (const std::string& path : options.parts) parts.push_back(read_image(path));
    std::vector<std::string> warnings;
    const Image image = merge_partial_renders(parts, options.parts, warnings);
    for (const std::string& warning : warnings) fmt::print(stderr, "warning: {}\n", warning);
    std::vector<OutputFile> files;
    for (const std::string& path : options.outputs) files.push_back({path, &image, write_options});
    write_outputs(files);
    if (!options.quiet) {
        for (const std::string& path : options.outputs) fmt::print(stderr, "wrote {}\n", path);
    }
    return 0;
}

}  // namespace glint::cli
