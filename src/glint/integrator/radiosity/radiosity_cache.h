#pragma once
// Saving and loading a solved radiosity mesh: the solution is independent of the view, so a
// walkthrough solves once and renders from anywhere (`radiosity_cache = "file"`).
#include <glint/integrator/radiosity/radiosity_mesh.h>

#include <string>

namespace glint {

/// Writes the solved `mesh` to `path` (through a temporary name and a rename, so that no
/// half-written file is left). Throws glint::Error when the file cannot be written.
void save_radiosity_cache(const RadiosityMesh& mesh, const std::string& path);

/// Replaces the solution in `mesh` (freshly built from the scene, not yet solved) by the one
/// saved in `path`. Throws glint::Error naming the file when it is not a radiosity cache,
/// is damaged (size, checksum, an index out of range, a value not finite), or was solved
/// for another scene or mesh (its fingerprint differs from `mesh`'s).
void load_radiosity_cache(RadiosityMesh& mesh, const std::string& path);

}  // namespace glint
