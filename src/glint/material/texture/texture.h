#pragma once
// The Texture interface: a value (colour or scalar) that varies over a surface.
//
// A texture is evaluated at a TextureContext, built from a SurfaceInteraction: the uv
// parameterisation, the hit in world and object space, and the footprint of a pixel
// there (du/dx, ...), which image textures use to choose a mipmap level and filter
// anisotropically. Solid (3D) textures use the object-space point, so they stay on an
// object that is moved by a transform or placed as a group instance.
//
// Textures are built once with the scene and are read-only and thread-safe while
// rendering; evaluation allocates nothing.
#include <glint/core/interaction.h>
#include <glint/core/rgb.h>

namespace glint {

struct TextureContext {
    Vec3 p;         // world space
    Vec3 p_object;  // the shape's own space
    Vec3 n;         // shading normal, world space
    Vec2 uv;
    float dudx = 0.0f, dudy = 0.0f, dvdx = 0.0f, dvdy = 0.0f;
    Vec3 dpdx{0.0f}, dpdy{0.0f};  // world-space footprint

    TextureContext() = default;
    explicit TextureContext(const SurfaceInteraction& si)
        : p(si.p),
          p_object(si.p_object),
          n(si.shading.n()),
          uv(si.uv),
          dudx(si.dudx),
          dudy(si.dudy),
          dvdx(si.dvdx),
          dvdy(si.dvdy),
          dpdx(si.dpdx),
          dpdy(si.dpdy) {}
};

class Texture {
public:
    virtual ~Texture() = default;
    // Linear RGB value: a colour, which a material makes into a Spectrum (texture_input.h).
    virtual Rgb eval(const TextureContext& ctx) const = 0;
    // Scalar value (roughness, index of refraction, bump height, ...): the average of the
    // colour's channels, for every texture, so that a scalar parameter reads what the
    // texture's colours say (a noise between low = 0.1 and high = 0.4 gives 0.1 .. 0.4).
    float eval_float(const TextureContext& ctx) const { return eval(ctx).average(); }
    // The pattern before colouring (procedural textures: the noise, the ring darkness, ...;
    // images: the same as eval_float). For tests and tools; materials use eval_float.
    virtual float pattern(const TextureContext& ctx) const { return eval_float(ctx); }
};

}  // namespace glint
