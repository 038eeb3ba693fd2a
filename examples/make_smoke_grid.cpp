// Writes examples/smoke.nvdb, the density grid examples/smoke.lua renders: the procedural
// fbm cloud (src/glint/medium/grid/fbm_cloud.h) at 32^3, stored sparsely (only voxels with
// density) as a NanoVDB fog volume, 1/16 scene units per voxel, index (0, 0, 0) at the origin. Run
// by scripts/make-example-grid.sh; the file is committed.
#include <glint/core/error.h>
#include <glint/medium/grid/fbm_cloud.h>
#include <glint/medium/grid/nanovdb_file.h>

#include <fmt/format.h>

#include <string>

int main(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : "examples/smoke.nvdb";
    try {
        const int n = 32;
        const glint::VoxelGrid cloud = glint::make_fbm_cloud(
            {.resolution = n, .frequency = 2.5f, .coverage = 0.7f, .offset = 11.0f},
            glint::Bounds3{glint::Vec3(0.0f), glint::Vec3(1.0f)});
        std::vector<glint::SparseVoxel> voxels;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const float v = cloud.voxel(x, y, z);
                    if (v > 0.0f) voxels.push_back({{x, y, z}, v});
                }
        glint::write_nanovdb_grid(path, "density", voxels, 1.0 / 16.0);
        fmt::print("{}: {} active voxels\n", path, voxels.size());
    } catch (const glint::Error& e) {
        fmt::print(stderr, "{}\n", e.what());
        return 1;
    }
    return 0;
}
