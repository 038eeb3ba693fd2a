#pragma once
// The preview's ReSTIR state, shared by preview.cpp (which keeps and drops it) and
// preview_restir.cpp (the ReSTIR pass that fills it).
#include <glint/core/arena.h>
#include <glint/integrator/photon/preview.h>
#include <glint/integrator/realtime/restir_di.h>

#include <tbb/enumerable_thread_specific.h>

#include <vector>

namespace glint {

// What ReSTIR keeps between the two stages of a pass and from pass to pass: its buffers,
// what each pixel gathers besides direct light, and the arenas that hold the BSDFs of the
// surfaces (two sets, used in turn: the previous pass's surfaces must keep theirs for
// temporal reuse).
struct PreviewIntegrator::RestirState {
    RestirState(const RestirSettings& settings, Vec2i size, Vec2i origin)
        : restir(settings), size(size), origin(origin) {}
    RestirDi restir;
    Vec2i size, origin;          // of the film it serves
    std::vector<Spectrum> rest;  // emission, caustic photons and bounces: all but direct light
    std::vector<Spectrum> beta;  // throughput from the camera to the pixel's surface
    tbb::enumerable_thread_specific<Arena> arenas[2];
};

}  // namespace glint
