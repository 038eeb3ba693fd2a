#include "compare_command.h"

#include "flags.h"

#include <glint/core/strict_number.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>

#include <optional>

namespace glint::cli {

CLI::App* add_compare_command(CLI::App& app, CompareOptions& options) {
    CLI::App* compare_cmd = app.add_subcommand("compare", "Compare an image with a reference");
    compare_cmd->add_option("test", options.test_image, "Image to check (.exr)")->required();
    compare_cmd->add_option("reference", options.reference_image, "Converged reference (.exr)")
        ->required();
    compare_cmd->add_option("--threshold", options.threshold,
                            "Exit with 1 when the relative MSE exceeds this (finite, >= 0)");
    return compare_cmd;
}

int run_compare(const CompareOptions& options) {
    const std::string& threshold_text = options.threshold;
    std::optional<double> threshold;
    if (!threshold_text.empty()) {
        threshold = parse_finite(threshold_text);
        if (!threshold || *threshold < 0.0)
            bad_flag("--threshold", threshold_text, "a finite number >= 0");
    }
    const CompareResult r =
        compare_images(read_image(options.test_image), read_image(options.reference_image));
    fmt::print("relative MSE: {:.6g}\n", r.rel_mse);
    fmt::print("RMSE:         {:.6g}\n", r.rmse);
    fmt::print("test mean:    ({:.6g}, {:.6g}, {:.6g})\n", r.test_mean[0], r.test_mean[1],
               r.test_mean[2]);
    fmt::print("ref mean:     ({:.6g}, {:.6g}, {:.6g})\n", r.ref_mean[0], r.ref_mean[1],
               r.ref_mean[2]);
    if (r.non_finite > 0) {
        fmt::print(stderr, "{} values are NaN or infinite; no threshold can pass\n", r.non_finite);
    }
    // Written so that NaN fails: NaN <= threshold is false.
    if (threshold && !(r.rel_mse <= *threshold)) {
        fmt::print(stderr, "relative MSE {:.6g} exceeds the threshold {:.6g}\n", r.rel_mse,
                   *threshold);
        return kExitInputError;
    }
    return 0;
}

}  // namespace glint::cli
