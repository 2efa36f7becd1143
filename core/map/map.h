#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"
#include "core/map/terrain.h"

namespace swarmplan {

enum class MapKind { kOccupancyGrid, kShapeWorld, kTerrain };

// "occupancy-grid", "shape-world", "terrain".
const char* MapKindName(MapKind kind);
std::string JoinMapKinds(const std::vector<MapKind>& kinds);

// Any of the three map kinds, immutable, shared by shared_ptr<const Map>.
class Map {
 public:
  using Data = std::variant<OccupancyGrid, ShapeWorld, Terrain>;

  explicit Map(Data data) : data_(std::move(data)) {}

  MapKind kind() const { return static_cast<MapKind>(data_.index()); }
  const Data& data() const { return data_; }
  // nullptr when the map is of another kind.
  const OccupancyGrid* grid() const { return std::get_if<OccupancyGrid>(&data_); }
  const ShapeWorld* world() const { return std::get_if<ShapeWorld>(&data_); }
  const Terrain* terrain() const { return std::get_if<Terrain>(&data_); }
  bool is_3d() const { return kind() == MapKind::kTerrain; }

 private:
  Data data_;
};

using MapPtr = std::shared_ptr<const Map>;

}  // namespace swarmplan
