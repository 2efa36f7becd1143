#include "bench/papers/bpso_vertices_figures.h"

#include <algorithm>
#include <iterator>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/bpso_vertices_paper.h"

namespace swarmplan::bench::bpso {

std::vector<ConvergenceSpec> ConvergenceVariants(int iterations) {
  return {
      {"bpso, double structure + mutation 0.1 (the paper's)",
       BpsoSpec(iterations, kPaperSwarmFactor, kPaperMutation, true)},
      {"bpso, double structure, no mutation", BpsoSpec(iterations, kPaperSwarmFactor, 0.0, true)},
      {"plain BPSO (eqs 1-2, no mutation)", BpsoSpec(iterations, kPaperSwarmFactor, 0.0, false)},
      {"ga (8-connected grid, resolution 4)", GaSpec(iterations)},
  };
}

absl::StatusOr<FigureRuns> RunFigures(const ExperimentOptions& options, int runs, int iterations) {
  FigureRuns out;
  out.runs = runs;
  out.iterations = iterations;
  for (int vertices : kVertexCounts) {
    absl::StatusOr<World> world = LoadShippedWorld(options, vertices);
    if (!world.ok()) return world.status();
    out.worlds.push_back(*std::move(world));
  }
  for (const World& world : out.worlds) {
    std::vector<Runs>& row = out.swarm_sizes.emplace_back();
    for (double factor : kSwarmFactors) {
      absl::StatusOr<Runs> result =
          RunMany(BpsoSpec(iterations, factor, kPaperMutation, true), world, runs, options.seed,
                  absl::StrCat("bpso N = ", SwarmLabel(factor)), options.log);
      if (!result.ok()) return result.status();
      row.push_back(*std::move(result));
    }
  }
  for (const World& world : out.worlds) {
    std::vector<Runs>& row = out.mutations.emplace_back();
    for (double mutation : kMutationProbabilities) {
      absl::StatusOr<Runs> result =
          RunMany(BpsoSpec(iterations, kPaperSwarmFactor, mutation, true), world, runs,
                  options.seed, absl::StrFormat("bpso mutation %g", mutation), options.log);
      if (!result.ok()) return result.status();
      row.push_back(*std::move(result));
    }
  }
  const std::vector<ConvergenceSpec> variants = ConvergenceVariants(iterations);
  for (size_t w = 0; w < out.worlds.size(); ++w) {
    const World& world = out.worlds[w];
    if (std::find(std::begin(kConvergenceVertices), std::end(kConvergenceVertices),
                  world.vertices) == std::end(kConvergenceVertices)) {
      continue;
    }
    ConvergenceWorld& convergence = out.convergence.emplace_back();
    convergence.world = w;
    for (const ConvergenceSpec& variant : variants) {
      absl::StatusOr<Runs> result =
          RunMany(variant.spec, world, runs, options.seed, variant.label, options.log);
      if (!result.ok()) return result.status();
      convergence.variants.push_back(*std::move(result));
    }
  }
  return out;
}

}  // namespace swarmplan::bench::bpso
