#include <glint/core/error.h>
#include <glint/medium/grid/fbm_cloud.h>
#include <glint/medium/grid/grid_file.h>
#include <glint/medium/heterogeneous_medium.h>
#include <glint/medium/homogeneous_medium.h>
#include <glint/medium/registry.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

namespace glint {
namespace {

Rgb non_negative_rgb(const Params& params, const char* name, const Rgb& fallback) {
    const Rgb value = params.get_rgb(name, fallback);
    if (!(value.min_value() >= 0.0f) || !std::isfinite(value.max_value()))
        params.fail(fmt::format("'{}' must be finite and not negative", name));
    return value;
}

// What every medium type reads: its coefficients and phase function.
struct Coefficients {
    Rgb sigma_a, sigma_s;
    float g;
};

//   sigma_a   spectrum  0    absorption coefficient per scene unit (times scale)
//   sigma_s   spectrum  0    scattering coefficient per scene unit (times scale)
//   density   spectrum  -    extinction sigma_a + sigma_s per scene unit; with `albedo`,
//                            instead of sigma_a and sigma_s
//   albedo    spectrum  1    sigma_s / (sigma_a + sigma_s), in [0, 1], with `density`
//   scale     float     1    multiplies the coefficients (a unit change), > 0
//   g         float     0    Henyey-Greenstein asymmetry in (-1, 1): > 0 scatters forwards
// For "grid" and "cloud" the coefficients are those at density 1 of the grid.
Coefficients read_coefficients(const Params& params) {
    const bool by_density = params.has("density") || params.has("albedo");
    if (by_density && (params.has("sigma_a") || params.has("sigma_s")))
        params.fail("give either 'sigma_a' and 'sigma_s', or 'density' and 'albedo', not both");
    Rgb sigma_a(0.0f), sigma_s(0.0f);
    if (by_density) {
        const Rgb density = non_negative_rgb(params, "density", Rgb(1.0f));
        const Rgb albedo = non_negative_rgb(params, "albedo", Rgb(1.0f));
        if (albedo.max_value() > 1.0f) params.fail("'albedo' must lie in [0, 1]");
        sigma_s = density * albedo;
        sigma_a = density - sigma_s;
    } else {
        sigma_a = non_negative_rgb(params, "sigma_a", Rgb(0.0f));
        sigma_s = non_negative_rgb(params, "sigma_s", Rgb(0.0f));
    }
    const float scale = params.get_float("scale", 1.0f);
    if (!(scale > 0.0f) || !std::isfinite(scale)) params.fail("'scale' must be a positive number");
    const float g = params.get_float("g", 0.0f);
    if (!(g > -1.0f && g < 1.0f)) params.fail("'g' must lie in (-1, 1)");
    return {sigma_a * scale, sigma_s * scale, g};
}

//   emission  spectrum  0    radiance of the medium's emission (its source is sigma_a times it)
std::unique_ptr<Medium> make_homogeneous(const Params& params) {
    const Coefficients c = read_coefficients(params);
    const Rgb emission = non_negative_rgb(params, "emission", Rgb(0.0f));
    params.check_all_used();
    return std::make_unique<HomogeneousMedium>(c.sigma_a, c.sigma_s, c.g, emission);
}

int int_in(const Params& params, const char* name, int fallback, int lo, int hi) {
    const int value = params.get_int(name, fallback);
    if (value < lo || value > hi)
        params.fail(fmt::format("'{}' must lie in [{}, {}]", name, lo, hi));
    return value;
}

// type = "grid": densities from a NanoVDB (.nvdb) or OpenVDB (.vdb) file.
//   file      string    -    the grid file, relative to the scene's folder
//   grid      string    ""   the grid's name in the file (default: its first float grid)
// type = "cloud": a procedural fbm cloud (grid/fbm_cloud.h) baked over a box.
//   min, max  vec3  (-1,-1,-1), (1,1,1)  the box's corners
//   resolution int 64   voxels per axis, in [1, 512]
//   frequency float 3   noise cycles across the box; octaves int 5, in [1, 16]
//   coverage float 0.45 in (0, 1]: how much of the box the cloud fills
//   seed      float 0    a different cloud for each value
// Both:
//   transform  transform  identity   places the grid (its file's world space, or the box)
//   majorant_resolution int 16       majorant cells per axis, in [1, 256] (1: one global bound)
VoxelGrid read_grid(const Params& params, const std::string& type, const std::string& directory) {
    if (type == "grid") {
        std::filesystem::path path = params.get_string("file");
        if (path.is_relative()) path = std::filesystem::path(directory) / path;
        const std::string name = params.get_string("grid", "");
        try {
            return read_density_grid(path.string(), name);
        } catch (const Error& e) {
            params.fail(e.what());
        }
    }
    FbmCloudSettings cloud;
    cloud.resolution = int_in(params, "resolution", cloud.resolution, 1, 512);
    cloud.octaves = int_in(params, "octaves", cloud.octaves, 1, 16);
    cloud.frequency = params.get_float("frequency", cloud.frequency);
    if (!(cloud.frequency > 0.0f) || !std::isfinite(cloud.frequency))
        params.fail("'frequency' must be a positive number");
    cloud.coverage = params.get_float("coverage", cloud.coverage);
    if (!(cloud.coverage > 0.0f && cloud.coverage <= 1.0f))
        params.fail("'coverage' must lie in (0, 1]");
    cloud.offset = params.get_float("seed", 0.0f);
    if (!std::isfinite(cloud.offset)) params.fail("'seed' must be a finite number");
    const Bounds3 box{params.get_vec3("min", Vec3(-1.0f)), params.get_vec3("max", Vec3(1.0f))};
    const Vec3 extent = box.extent();
    if (!(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f) ||
        !std::isfinite(extent.x + extent.y + extent.z))
        params.fail("'max' must exceed 'min' on every axis, both finite");
    return make_fbm_cloud(cloud, box);
}

std::unique_ptr<Medium> make_heterogeneous(const Params& params, const std::string& type,
                                           const std::string& directory) {
    const Coefficients c = read_coefficients(params);
    VoxelGrid grid = read_grid(params, type, directory);
    const Transform transform = params.get_transform("transform");
    const int majorant_resolution =
        int_in(params, "majorant_resolution", MajorantGrid::kDefaultResolution, 1, 256);
    params.check_all_used();
    return std::make_unique<HeterogeneousMedium>(std::move(grid), transform, c.sigma_a, c.sigma_s,
                                                 c.g, majorant_resolution);
}

}  // namespace

// glint.medium{...}: a participating medium, for a shape's interior or exterior (the
// `interior`/`exterior` of glint.interface and glint.dielectric) or the camera's `medium`.
//   type      string    "homogeneous"   homogeneous, grid or cloud (parameters above)
std::unique_ptr<Medium> make_medium(const Params& params, const std::string& directory) {
    const std::string type = params.get_string("type", "homogeneous");
    if (type == "homogeneous") return make_homogeneous(params);
    if (type != "grid" && type != "cloud") {
        params.fail(
            fmt::format("unknown medium type '{}' (expected homogeneous, grid or cloud)", type));
    }
    return make_heterogeneous(params, type, directory);
}

}  // namespace glint
