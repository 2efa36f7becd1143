#pragma once

#include <optional>
#include <vector>

#include "core/grid_ops/grid_space.h"
#include "core/map/distance_field.h"
#include "core/map/point.h"

namespace swarmplan {

// Any-angle shortening by line of sight, shared by every grid planner.

// Greedy string pulling: from each kept point, the path goes straight to the last later point
// it sees (the segment keeps the problem's clearance on its own map, exact checker); then each
// kept interior point moves to the corner of its grid cell that shortens the path most where
// both its segments stay free (grid paths bend at cell corners, not at centres), the string is
// pulled again and collinear points are dropped (PruneCollinear). Never longer than `path`;
// start and goal are kept. nullopt when a segment of `path` itself is not collision-free.
std::optional<Path> ShortcutPath(const GridSpace& space, const Path& path);

// The shortening for a fleet objective with a preferred clearance: the same string pulling, but
// a straight segment replaces a stretch of `path` only when it stays, by the field's bilinear
// distance, at least as far from the obstacles as the nearer of `preferred_clearance` and the
// closest vertex of the stretch. So a path that keeps away from the walls is straightened
// without being pulled back against them. Then each kept interior point moves to a corner or an
// edge's midpoint of its cell, or stays at its centre, whichever makes its two segments' length
// plus `clearance_weight` times their shortfall below `preferred_clearance`
// (DistanceField::ShortfallAlong) least, the segments kept free: a bend may trade a little
// clearance for length, as the objective prices it. nullopt as ShortcutPath.
std::optional<Path> ShortcutKeepingClearance(const GridSpace& space, const Path& path,
                                             const DistanceField& field, double preferred_clearance,
                                             double clearance_weight);

// ShortcutPath of the cell path's world path (GridSpace::WorldPath); consecutive cells need not
// be neighbours (a line-of-sight move joins two cell centres). nullopt when `cells` is empty or
// its world path is not collision-free.
std::optional<Path> AnyAnglePath(const GridSpace& space, const std::vector<Cell>& cells);

}  // namespace swarmplan
