#pragma once
// Bump and normal mapping: a change of the shading normal that every material accepts
// (parameters `bump`, `bump_scale`, `normal_map`, `normal_map_flip_y`).
//
// Bump mapping (Blinn 1978) displaces the surface along its normal by scale * h(u, v) and
// takes the normal of the displaced surface, from finite differences of h over the pixel
// footprint in u and v: a raised bump faces away from its uphill side, so a bump lit from
// above is brighter on its upper slope.
//
// Normal mapping reads a tangent-space normal from an image stored as (n + 1) / 2: x along
// dp/du (the tangent), y along dp/dv (OpenGL convention: +y is up in the image, where v
// grows), z along the surface normal. `flip_y` reads DirectX-convention maps.
#include <glint/core/interaction.h>
#include <glint/material/texture/texture.h>

namespace glint {

class NormalPerturbation {
public:
    static NormalPerturbation bump(const Texture* height, float scale) {
        return NormalPerturbation(height, scale, false, false);
    }
    static NormalPerturbation normal_map(const Texture* map, bool flip_y) {
        return NormalPerturbation(map, 1.0f, true, flip_y);
    }

    // Replaces si.shading (and si.dpdu, si.dpdv for bumps) with the perturbed frame.
    void apply(SurfaceInteraction& si) const;

private:
    NormalPerturbation(const Texture* texture, float scale, bool is_normal_map, bool flip_y)
        : m_texture(texture), m_scale(scale), m_is_normal_map(is_normal_map), m_flip_y(flip_y) {}

    void apply_bump(SurfaceInteraction& si) const;
    void apply_normal_map(SurfaceInteraction& si) const;

    const Texture* m_texture;
    float m_scale;
    bool m_is_normal_map;
    bool m_flip_y;
};

}  // namespace glint
