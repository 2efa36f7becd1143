#pragma once

// What the binary PSO paper (Zhang & Gu, seed 004) publishes and the bpso-vertices reproduction
// compares against: its settings, Table 1 and the figures its text quotes from Fig. 5.

#include <optional>

namespace swarmplan::bench::bpso {

// The paper's settings (its section IV).
inline constexpr double kPaperSwarmFactor = 1.5;  // swarm = 1.5 x the vertex count
inline constexpr double kPaperMutation = 0.1;
inline constexpr int kPaperIterations = 100;

// Fig. 5's text: with mutation BPSO "converges near the 80th generation and it converges near
// the 40th generation without mutation".
inline constexpr int kPaperConvergenceWithMutation = 80;
inline constexpr int kPaperConvergenceWithoutMutation = 40;

// Table 1: average fitness and time per (D, N = factor x D).
struct PaperTable1Cell {
  int vertices;
  double swarm_factor;
  double fitness;
  double seconds;
};
inline constexpr PaperTable1Cell kPaperTable1[] = {
    {8, 1.0, 362.615, 0.062},  {8, 1.5, 362.615, 0.094},  {8, 2.0, 360.652, 0.1250},
    {16, 1.0, 446.136, 0.312}, {16, 1.5, 420.847, 0.436}, {16, 2.0, 415.104, 0.625},
    {24, 1.0, 436.234, 0.797}, {24, 1.5, 429.251, 1.187}, {24, 2.0, 412.406, 1.578},
    {32, 1.0, 337.640, 1.593}, {32, 1.5, 329.207, 2.468}, {32, 2.0, 321.113, 3.202},
};

inline std::optional<PaperTable1Cell> FindPaperTable1Cell(int vertices, double swarm_factor) {
  for (const PaperTable1Cell& cell : kPaperTable1) {
    if (cell.vertices == vertices && cell.swarm_factor == swarm_factor) return cell;
  }
  return std::nullopt;
}

}  // namespace swarmplan::bench::bpso
