#pragma once
// Scenes with participating media that several integrators' tests render.
#include <fmt/format.h>

#include <string>

namespace glint::test {

// A sphere of medium that scatters everything it stops (albedo 1, a different density per
// channel, forward scattering) behind an interface, inside a closed sphere emitting Le = 2:
// radiance is 2 everywhere, so the sphere disappears whatever the hero channel.
inline std::string albedo_one_furnace(const std::string& integrator, int spp, int seed) {
    return fmt::format(R"(
        glint.camera{{ eye = {{0, 0, 1.8}}, look_at = {{0, 0, 0}}, fov = 30 }}
        glint.render{{ width = 16, height = 16, spp = {}, seed = {}, integrator = '{}' }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 3,
                      material = glint.emissive{{ radiance = 2, two_sided = true }} }}
        local fog = glint.medium{{ density = {{0.5, 2, 6}}, albedo = 1, g = 0.6 }}
        glint.sphere{{ center = {{0, 0, 0}}, radius = 1,
                      material = glint.interface{{ interior = fog }} }}
    )",
                       spp, seed, integrator);
}

// A box of medium `fog` (declared by `media`, Lua) lit by a small two-sided lamp inside it,
// in front of a wall, on a floor; the camera looks in from outside the box. `render` holds
// glint.render's settings, `objects` what stands in the fog.
inline std::string fog_room(const std::string& media, const std::string& render,
                            const std::string& objects) {
    return fmt::format(R"(
        {}
        glint.camera{{ eye = {{0, 1, 4}}, look_at = {{0, 0.9, 0}}, fov = 45 }}
        glint.render{{ {} }}
        glint.box{{ min = {{-1.5, 0.01, -1.5}}, max = {{1.5, 2.5, 1.5}},
                   material = glint.interface{{ interior = fog }} }}
        glint.quad{{ vertices = {{ {{-2, 0, -2}}, {{-2, 0, 2}}, {{2, 0, 2}}, {{2, 0, -2}} }},
                    material = glint.diffuse{{ reflectance = 0.6 }} }}
        glint.quad{{ vertices = {{ {{-3, 0, -2}}, {{3, 0, -2}}, {{3, 4, -2}}, {{-3, 4, -2}} }},
                    material = glint.diffuse{{ reflectance = 0.5 }} }}
        {}
        glint.quad{{ vertices = {{ {{-0.3, 1.9, -0.3}}, {{0.3, 1.9, -0.3}}, {{0.3, 1.9, 0.3}},
                                  {{-0.3, 1.9, 0.3}} }},
                    material = glint.emissive{{ radiance = 20, two_sided = true }} }}
    )",
                       media, render, objects);
}

// The fog room with a glass sphere below the lamp, which focuses it into the fog and onto
// the floor; chromatic fog. 24 x 24 pixels.
inline std::string fog_box(const std::string& integrator, int spp, int seed,
                           bool spectral = false) {
    return fog_room(
        "local fog = glint.medium{ sigma_a = 0.05, sigma_s = {0.5, 0.7, 0.9}, g = 0.3 }",
        fmt::format("width = 24, height = 24, spp = {}, seed = {}, integrator = '{}', "
                    "max_depth = 6, spectral = {}",
                    spp, seed, integrator, spectral ? "true" : "false"),
        "glint.sphere{ center = {0, 0.8, 0}, radius = 0.4, "
        "material = glint.dielectric{ ior = 1.5 } }");
}

}  // namespace glint::test
