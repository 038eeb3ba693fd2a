#pragma once
// A Material turns a surface hit into a BSDF (built in the per-thread arena, or once for all
// hits when it does not vary over the surface) and states what the surface emits and which
// media it separates.
#include <glint/core/arena.h>
#include <glint/core/interaction.h>
#include <glint/core/medium.h>
#include <glint/material/bsdf.h>
#include <glint/material/normal_perturbation.h>

#include <optional>

namespace glint {

class Material {
public:
    virtual ~Material() = default;

    // What an integrator calls at a hit: applies the bump or normal map to si's shading
    // frame, then returns the BSDF (nullptr for a surface that does not scatter). The
    // integrator sets si's texture footprint first when uses_textures() says so.
    const Bsdf* scatter(SurfaceInteraction& si, Arena& arena) const {
        if (m_perturbation) m_perturbation->apply(si);
        return bsdf(si, arena);
    }
    // The BSDF at this hit, with the shading frame already final.
    virtual const Bsdf* bsdf(const SurfaceInteraction& si, Arena& arena) const = 0;
    // Reflectance colour for the albedo feature channel.
    virtual Spectrum albedo(const SurfaceInteraction&) const { return Spectrum(0.0f); }

    // Radiance leaving the front side (and the back too when two-sided).
    // A colour, not a Spectrum: it is fixed when the scene is built, and spectral mode reads
    // it at each path's wavelengths.
    virtual SceneColor emission() const { return {}; }
    virtual bool emits_two_sided() const { return false; }
    bool is_emissive() const { return !emission().is_black(); }

    // The media this surface separates (see core/medium.h): those the scene attached
    // (`interior`/`exterior`, set_media), else the material's own (an absorbing
    // dielectric's inside is an AbsorbingMedium); most surfaces separate none.
    MediumInterface medium_interface() const {
        return m_media.is_transition() ? m_media : intrinsic_media();
    }
    // Media the scene attaches to the two sides (glint.medium handles).
    void set_media(const MediumInterface& media) { m_media = media; }
    // The media the material itself brings, when the scene attaches none.
    virtual MediumInterface intrinsic_media() const { return {}; }
    // Whether the surface only bounds media and does not scatter (glint.interface): shadow
    // rays pass through it (transport/visibility.h), and walks cross it straight on.
    virtual bool is_interface() const { return false; }
    // Whether the surface may scatter through a specular (delta) lobe anywhere, as a mirror
    // or smooth glass does: without such surfaces a scene has no caustic paths, and photon
    // methods need not aim at them. True unless the material knows it never does.
    virtual bool may_scatter_specularly() const { return true; }

    // Set by the registry after the factory ran: textures need the pixel footprint.
    void set_uses_textures(bool uses) { m_uses_textures = uses; }
    bool uses_textures() const { return m_uses_textures; }
    void set_perturbation(const NormalPerturbation& perturbation) {
        m_perturbation = perturbation;
        m_uses_textures = true;
    }

private:
    bool m_uses_textures = false;
    std::optional<NormalPerturbation> m_perturbation;
    MediumInterface m_media;
};

}  // namespace glint
