#pragma once

// How the path-planning reproductions replicate a generated world: the generator that drew the
// shipped world draws kReplicatedWorlds worlds of the same kind, world 0 being the shipped one.

#include <cstdint>

namespace swarmplan::bench {

inline constexpr int kReplicatedWorlds = 10;

// World r draws from seed shipped_seed + r * kWorldSeedStride on. The generators try fewer
// than this many seeds per world, so no two worlds share a draw.
inline constexpr uint64_t kWorldSeedStride = 1000;

inline uint64_t ReplicatedWorldSeed(uint64_t shipped_seed, int index) {
  return shipped_seed + static_cast<uint64_t>(index) * kWorldSeedStride;
}

}  // namespace swarmplan::bench
