#pragma once
// Progressive refinement radiosity (Cohen, Chen, Wallace and Greenberg 1988) on a
// RadiosityMesh: the patch side with the most unshot power shoots it to every element
// vertex, form factors cast as rays to the vertices (Wallace et al. 1989), elements split
// where a shot changes the radiosity quickly across them, until the unshot power falls
// below a fraction of what the lights emitted.
#include <glint/core/params.h>
#include <glint/integrator/radiosity/radiosity_mesh.h>

#include <cstdint>

namespace glint {

class Progress;
class Scene;

/// What the solve reads from glint.render{...} (all optional; see docs/integrators.md).
struct RadiositySettings {
    /// Longest patch edge in scene units; 0: 1/6 of the scene's bounding-box diagonal.
    float patch_size = 0.0f;
    /// Elements split no finer than this edge; 0: 1/8 of the patch size.
    float element_size = 0.0f;
    /// An element splits when one shot changes the luminance across its vertices by more
    /// than this fraction of their largest radiosity (in [0, 1]; 1 never splits).
    float subdivide = 0.25f;
    /// Points on the shooting patch per receiving vertex (rays per form factor), >= 1.
    int shooter_samples = 8;
    /// The solve stops when the unshot power is at most this fraction of the power the
    /// lights put into the scene, in [0, 1).
    float unshot = 0.02f;
    /// At most this many patch shots (lights not counted), >= 0.
    int max_shots = 100000;
    /// At most this many elements in all; further splits are skipped.
    int max_elements = 1000000;
    /// Show the unshot power as Cohen et al.'s ambient term.
    bool ambient = true;

    /// Reads and validates the keys above (radiosity_patch_size, radiosity_element_size,
    /// radiosity_subdivide, radiosity_samples, radiosity_unshot, radiosity_max_shots,
    /// radiosity_max_elements, radiosity_ambient); errors name the key's location.
    static RadiositySettings read(const Params& params);
};

struct RadiositySolveStats {
    int shots = 0;                 ///< patch shots
    int light_shots = 0;           ///< lights that are not meshed, shot by sampling
    uint64_t rays = 0;             ///< visibility rays
    double seconds = 0.0;          ///< the solve's wall time
    double unshot_fraction = 0.0;  ///< unshot power over the lights' power at the end
};

/// The patch size `settings` asks for in `scene` (its default resolved).
float radiosity_patch_size(const Scene& scene, const RadiositySettings& settings);

/// Solves `mesh` (as RadiosityMesh::build made it from `scene`) in place: first every light
/// that is not a meshed emitter (point, spot, directional; emitting spheres) shoots by
/// sampling it from each vertex, then patches shoot by progressive refinement. Results
/// depend only on `seed` and the settings, never on the number of threads: vertices are
/// computed in parallel, each from its own random numbers, and summed in a fixed order.
/// `progress` shows the fall of the unshot power (log scale) in percent.
RadiositySolveStats solve_radiosity(const Scene& scene, RadiosityMesh& mesh,
                                    const RadiositySettings& settings, uint64_t seed,
                                    Progress& progress);

}  // namespace glint
