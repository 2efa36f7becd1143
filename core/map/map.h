#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>
#include <variant>
#include <vector>

#include "absl/functional/function_ref.h"
#include "core/map/derived_cache.h"
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
  // How a grid map was made from another: `base` with the `blocked` cells blocked too (the seed
  // search's corridor walls). Structures derived from such a map may be derived from the base's
  // (AnyAngleGridFor) instead of from scratch.
  struct GridPatch {
    std::shared_ptr<const Map> base;
    std::vector<Cell> blocked;
  };

  explicit Map(Data data) : data_(std::move(data)) {}
  // `data` must be the grid of `patch.base` with `patch.blocked` blocked.
  Map(Data data, GridPatch patch)
      : data_(std::move(data)), patch_(std::make_shared<const GridPatch>(std::move(patch))) {}
  // Copies and moves start with an empty derived cache: cached structures may refer into the
  // data of the map they were built from.
  Map(const Map& other) : data_(other.data_), patch_(other.patch_) {}
  Map(Map&& other) noexcept : data_(std::move(other.data_)), patch_(std::move(other.patch_)) {}
  Map& operator=(const Map& other) {
    data_ = other.data_;
    patch_ = other.patch_;
    cache_ = std::make_unique<DerivedCache>();
    return *this;
  }
  Map& operator=(Map&& other) noexcept {
    data_ = std::move(other.data_);
    patch_ = std::move(other.patch_);
    cache_ = std::make_unique<DerivedCache>();
    return *this;
  }

  MapKind kind() const { return static_cast<MapKind>(data_.index()); }
  const Data& data() const { return data_; }
  // nullptr when the map is of another kind.
  const OccupancyGrid* grid() const { return std::get_if<OccupancyGrid>(&data_); }
  const ShapeWorld* world() const { return std::get_if<ShapeWorld>(&data_); }
  const Terrain* terrain() const { return std::get_if<Terrain>(&data_); }
  bool is_3d() const { return kind() == MapKind::kTerrain; }

  // A structure derived from this map, built by `build` on first use and shared by every
  // caller until evicted (DerivedCache: at most 16 keys per map, least recently used out).
  // The key must name everything the structure depends on besides the map (e.g. the
  // clearance); keys are per type T. The structure may keep pointers into this map's data.
  template <class T>
  std::shared_ptr<const T> Derived(const std::string& key, absl::FunctionRef<T()> build) const {
    std::shared_ptr<const void> value = cache_->GetOrBuild(
        std::string(typeid(T).name()) + '\n' + key,
        [&]() -> std::shared_ptr<const void> { return std::make_shared<const T>(build()); });
    return std::static_pointer_cast<const T>(value);
  }
  const DerivedCache& derived_cache() const { return *cache_; }
  // The map this one was made from by blocking more cells; nullptr for a map of its own.
  const GridPatch* patch() const { return patch_.get(); }

 private:
  Data data_;
  std::shared_ptr<const GridPatch> patch_;
  std::unique_ptr<DerivedCache> cache_ = std::make_unique<DerivedCache>();
};

using MapPtr = std::shared_ptr<const Map>;

}  // namespace swarmplan
