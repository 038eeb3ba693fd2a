#pragma once
// One image rendered by the ranks of an MPI job (`mpirun -np N glint render ...`): each rank
// renders a share of every pixel's samples, rank 0 adds the shares up and writes the outputs.
// See docs/cluster.md for why sample ranges and what is exchanged.
#include <glint/cluster/cluster.h>
#include <glint/render/render_job.h>

#include <functional>
#include <optional>
#include <utility>

namespace glint {

/// What a rank does before it renders: load the scene and make the settings. May throw.
using RenderSetup = std::function<std::pair<SceneDesc, RenderSettings>()>;

/// Samples of rank `rank` of `ranks` when each pixel takes `spp`: consecutive ranges, as
/// equal as they can be.
SampleRange rank_share(int spp, int rank, int ranks);

/// Every rank runs setup() and renders its share (rank_share) of the samples; rank 0 shows
/// the whole job's progress, adds the shares (merge_partial_renders: the image of one
/// process, bit for bit) and writes every output or none. Collective: each rank calls it.
/// When any rank fails (its setup, its render, an interruption), every rank throws
/// glint::Error naming each failing rank and its cause, and nothing is written. Returns the
/// report on rank 0 (its own render's statistics, the whole job's samples), nothing elsewhere.
std::optional<RenderReport> render_distributed(Cluster& cluster, const RenderSetup& setup,
                                               const RenderControl& control);

}  // namespace glint
