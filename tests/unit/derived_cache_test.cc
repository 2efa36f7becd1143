#include "core/map/derived_cache.h"

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/map.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

Map SmallGridMap() {
  absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(4, 3, std::vector<int8_t>(12, 0));
  EXPECT_TRUE(grid.ok()) << grid.status();
  return Map(Map::Data(*std::move(grid)));
}

struct Widget {
  int value;
};

TEST(DerivedCacheTest, SameKeyReturnsTheSameObjectBuiltOnce) {
  const Map map = SmallGridMap();
  int builds = 0;
  const auto build = [&] {
    ++builds;
    return Widget{7};
  };
  const std::shared_ptr<const Widget> a = map.Derived<Widget>("w", build);
  const std::shared_ptr<const Widget> b = map.Derived<Widget>("w", build);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(a->value, 7);
  EXPECT_EQ(builds, 1);
  const std::shared_ptr<const Widget> c = map.Derived<Widget>("other", build);
  EXPECT_NE(a.get(), c.get());
  EXPECT_EQ(builds, 2);
  // Keys are per type: the same key of another type is another entry.
  const std::shared_ptr<const int> i = map.Derived<int>("w", [] { return 3; });
  EXPECT_EQ(*i, 3);
  EXPECT_EQ(map.derived_cache().size(), 3u);
}

TEST(DerivedCacheTest, BoundedWithLeastRecentlyUsedEvicted) {
  DerivedCache cache(4);
  std::vector<std::shared_ptr<const void>> held;
  const auto get = [&](const std::string& key) {
    return cache.GetOrBuild(key, [&] { return std::make_shared<const std::string>(key); });
  };
  held.push_back(get("keep"));
  for (int i = 0; i < 10; ++i) {
    held.push_back(get("k" + std::to_string(i)));
    get("keep");  // recently used: never the one evicted
    EXPECT_LE(cache.size(), 4u);
  }
  EXPECT_EQ(cache.size(), 4u);
  const int64_t builds = cache.builds();
  EXPECT_EQ(get("keep").get(), held[0].get());
  EXPECT_EQ(cache.builds(), builds);
  // k0 was evicted: asking again builds a new value; the old one lives on with its holder.
  const std::shared_ptr<const void> again = get("k0");
  EXPECT_EQ(cache.builds(), builds + 1);
  EXPECT_NE(again.get(), held[1].get());
  EXPECT_EQ(*static_cast<const std::string*>(held[1].get()), "k0");
}

TEST(DerivedCacheTest, ConcurrentCallersShareOneBuildPerKey) {
  const Map map = SmallGridMap();
  constexpr int kThreads = 8;
  constexpr int kKeys = 4;
  std::atomic<int> builds{0};
  std::vector<std::vector<const Widget*>> seen(kThreads, std::vector<const Widget*>(kKeys));
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < 50; ++round) {
        for (int k = 0; k < kKeys; ++k) {
          const int key = (k + t) % kKeys;
          const std::shared_ptr<const Widget> w =
              map.Derived<Widget>("key" + std::to_string(key), [&] {
                builds.fetch_add(1);
                std::this_thread::yield();
                return Widget{key};
              });
          EXPECT_EQ(w->value, key);
          if (round == 0) seen[t][key] = w.get();
          EXPECT_EQ(seen[t][key], w.get());
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(builds.load(), kKeys);
  for (int t = 1; t < kThreads; ++t) EXPECT_EQ(seen[t], seen[0]);
}

TEST(DerivedCacheTest, CopiesOfAMapStartWithAnEmptyCache) {
  const Map map = SmallGridMap();
  map.Derived<int>("n", [] { return 1; });
  const Map copy = map;
  EXPECT_EQ(copy.derived_cache().size(), 0u);
  EXPECT_EQ(map.derived_cache().size(), 1u);
  EXPECT_EQ(copy.grid()->width(), 4);
}

}  // namespace
}  // namespace swarmplan
