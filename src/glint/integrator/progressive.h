#pragma once
// Rendering one pass at a time, for the interactive viewer: the viewer owns the film and
// the scene, calls render_pass() while nothing changes, and says what changed when the
// user moves the camera, a light or an object, so that an integrator keeps what is still
// valid (world-space photons survive a camera move, not a light move).
// Included by integrator.h (every TileIntegrator is progressive), so it includes only
// what its declarations need.
#include <glint/film/film.h>
#include <glint/integrator/render_stats.h>
#include <glint/scene/scene.h>

namespace glint {

class Progress;

/// What changed in the scene since the previous pass.
enum class SceneChange {
    camera,             ///< only the camera (position, orientation, lens, resolution)
    lights_or_objects,  ///< a light or an object moved, or a light's power changed
};

/// An integrator the viewer can drive one pass at a time. An integrator that renders
/// progressively derives from this as well as from Integrator; the viewer finds out with
/// dynamic_cast on what make_integrator() returns.
class ProgressiveIntegrator {
public:
    virtual ~ProgressiveIntegrator() = default;

    /// Renders pass number `pass` (0 for the first pass after the film was cleared) over
    /// `film`'s window; afterwards film.resolve() is the image to show. A pass takes one
    /// sample per pixel. Tile integrators add their sample `pass` of every pixel to the
    /// film, so that passes 0 .. N-1 into a cleared film give bit for bit what render()
    /// gives with spp = N (same seed, sampler and filter); stateful integrators (preview)
    /// may keep state between passes and write the film as they need.
    ///
    /// The film's size may differ from call to call: after a change the viewer renders one
    /// pass 0 at reduced resolution (a smaller film, with the scene's camera made for that
    /// resolution) to show something at once, then clears the full film and starts again
    /// at pass 0. Progress::advance() may throw glint::Interrupted when the viewer cancels
    /// a pass; the film is cleared before it is used again.
    virtual RenderStats render_pass(const Scene& scene, Film& film, int pass,
                                    Progress& progress) = 0;

    /// Called before the next pass when the scene changed; the viewer clears the film and
    /// starts again at pass 0. The default keeps nothing, so there is nothing to drop.
    virtual void scene_changed(SceneChange change) { (void)change; }
};

}  // namespace glint
