#include "bench/papers/bas_canyon_2d.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/time.h"
#include "bench/papers/aem_bso_worlds_generate.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/parallel_jobs.h"
#include "bench/papers/plan_once.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/map/io/map_io.h"

namespace swarmplan::bench::bas {
namespace {

constexpr char kWorldFile[] = "/aem-bso-worlds/simple-10-circles.json";
constexpr double kPaperBasStep = 4.0;  // Fig. 11: "the step size is 4"
constexpr int kPsoParticles = 20;      // the paper does not say; ACO's population of Fig. 4

struct Planner2d {
  std::string label;
  PlanSpec spec;
};

struct Runs2d {
  int runs = 0;
  std::vector<double> length;   // found paths only
  std::vector<double> fitness;  // found paths only
  int right_side = 0;           // found paths whose farthest point from the line is right of it
  std::vector<double> seconds;
  SuccessCount found() const { return {static_cast<int>(length.size()), runs}; }
  SuccessCount right() const { return {right_side, runs}; }
};

ParamValues WaypointPaperParams(int iterations) {
  return {{"iterations", int64_t{iterations}},
          {"init", std::string("paper")},
          {"waypoints", int64_t{2}},
          {"interpolation", std::string("spline")}};
}

std::vector<Planner2d> Planners(int iterations) {
  ParamValues bas = WaypointPaperParams(iterations);
  bas["reject_infeasible"] = false;
  bas["step_units"] = std::string("cells");
  bas["step0"] = kPaperBasStep;
  ParamValues bas_pso = bas;
  bas_pso["pso_mix"] = true;
  ParamValues pso = WaypointPaperParams(iterations);
  pso["population"] = int64_t{kPsoParticles};
  auto spec = [](const std::string& algorithm, ParamValues params) {
    PlanSpec s;
    s.algorithm = algorithm;
    s.params = std::move(params);
    return s;
  };
  return {{"bas", spec("bas", bas)},
          {"bas + PSO term (eq. 19)", spec("bas", bas_pso)},
          {"pso", spec("pso", pso)},
          {"apf", spec("apf", {})}};
}

// Whether the path's point farthest from the start-goal line lies to the right of it (seen
// from the start toward the goal).
bool RightOfLine(const Path& path, const Point3& start, const Point3& goal) {
  const double dx = goal.x() - start.x(), dy = goal.y() - start.y();
  double farthest = 0.0;
  for (const Point3& p : path) {
    const double cross = dx * (p.y() - start.y()) - dy * (p.x() - start.x());
    if (std::abs(cross) > std::abs(farthest)) farthest = cross;
  }
  return farthest < 0.0;
}

double PathLength(const Path& path) {
  double length = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) length += (path[i + 1] - path[i]).norm();
  return length;
}

std::string CountCell(const SuccessCount& count) {
  return absl::StrCat(count.successes, "/", count.runs);
}

struct Claim2d {
  std::string reference, other, claim;
  RankComparison length;
  std::optional<double> found_p, right_p;
};

}  // namespace

absl::StatusOr<std::string> TwoDSection(const ExperimentOptions& options, int runs,
                                        int iterations) {
  absl::StatusOr<Map> loaded = LoadMapFile(options.worlds_dir + kWorldFile);
  if (!loaded.ok()) return loaded.status();
  const MapPtr map = std::make_shared<const Map>(std::move(*loaded));
  const Point3 start(aem_bso::AemBsoStart().x(), aem_bso::AemBsoStart().y(), 0.0);
  const Point3 goal(aem_bso::AemBsoGoal().x(), aem_bso::AemBsoGoal().y(), 0.0);
  const std::vector<Planner2d> planners = Planners(iterations);

  struct Outcome {
    bool found = false, right = false;
    double length = 0.0, fitness = 0.0, seconds = 0.0;
  };
  std::vector<Outcome> outcomes(planners.size() * runs);
  if (absl::Status s = RunJobs(
          static_cast<int>(outcomes.size()), options.jobs,
          [&](int job) -> absl::Status {
            const Planner2d& planner = planners[job / runs];
            const uint64_t seed = options.seed + static_cast<uint64_t>(job % runs);
            const std::string what = absl::StrCat("bas-canyon 2D: ", planner.label, " seed ", seed);
            absl::StatusOr<PlanResult> result = PlanOnce(planner.spec, map, start, goal, seed);
            if (!result.ok()) {
              return absl::Status(result.status().code(),
                                  absl::StrCat(what, ": ", result.status().message()));
            }
            if (absl::Status c = CheckFoundPath(*result, start, goal, what); !c.ok()) return c;
            Outcome& out = outcomes[job];
            out.seconds = absl::ToDoubleSeconds(result->wall_time);
            out.found = result->found;
            if (!out.found) return absl::OkStatus();
            out.length = PathLength(result->raw_path);
            out.fitness = result->fitness;
            out.right = RightOfLine(result->raw_path, start, goal);
            return absl::OkStatus();
          });
      !s.ok()) {
    return s;
  }
  std::vector<Runs2d> results(planners.size());
  for (size_t job = 0; job < outcomes.size(); ++job) {
    Runs2d& r = results[job / runs];
    const Outcome& o = outcomes[job];
    ++r.runs;
    r.seconds.push_back(o.seconds);
    if (!o.found) continue;
    r.length.push_back(o.length);
    r.fitness.push_back(o.fitness);
    if (o.right) ++r.right_side;
  }

  MarkdownTable table({"planner", "found (collision-free)", "median length [95 % CI]",
                       "median fitness [95 % CI]", "right of the start-goal line"});
  for (size_t p = 0; p < planners.size(); ++p) {
    const Runs2d& r = results[p];
    table.AddRow({planners[p].label, CountCell(r.found()), MedianWithInterval(r.length),
                  planners[p].spec.algorithm == "apf" ? "–" : MedianWithInterval(r.fitness),
                  CountCell(r.right())});
  }
  // The paper's claims: BAS (alone or with eq. 19) explores both sides where PSO keeps to one
  // (Fig. 10), and finds shorter, collision-free paths where APF's are longer and may cut
  // obstacles (Fig. 11).
  const std::vector<Claim2d> claims_spec = {
      {"pso", "bas", "Fig. 10: BAS beats PSO", {}, {}, {}},
      {"pso", "bas + PSO term (eq. 19)", "Fig. 10: BAS with eq. 19 beats PSO", {}, {}, {}},
      {"apf", "bas", "Fig. 11: BAS's path shorter and collision-free, APF's not", {}, {}, {}}};
  auto index = [&](const std::string& label) {
    for (size_t p = 0; p < planners.size(); ++p) {
      if (planners[p].label == label) return p;
    }
    return size_t{0};
  };
  MarkdownTable tests({"reference", "other", "claim", "rank-sum p (length)", "Fisher p (found)",
                       "Fisher p (right side)", "length verdict"});
  std::string findings;
  for (Claim2d claim : claims_spec) {
    const Runs2d& ref = results[index(claim.reference)];
    const Runs2d& other = results[index(claim.other)];
    claim.length = CompareRanks(ref.length, other.length);
    claim.found_p = SuccessP(ref.found(), other.found());
    claim.right_p = SuccessP(ref.right(), other.right());
    const std::string verdict = !Significant(claim.length.p) ? "not significant"
                                : claim.length.other_higher  ? "contradicted"
                                                             : "supported";
    tests.AddRow({claim.reference, claim.other, claim.claim, PValueCell(claim.length.p),
                  PValueCell(claim.found_p), PValueCell(claim.right_p), verdict});
    std::string differences;
    AppendListItem(&differences, ValueDifference(claim.other, "length", ref.length, other.length,
                                                 claim.length.p));
    AppendListItem(&differences,
                   SuccessDifference(claim.other, ref.found(), other.found(), claim.found_p));
    AppendListItem(&differences,
                   Significant(claim.right_p)
                       ? absl::StrCat(claim.other, " right of the line in ", other.right_side, "/",
                                      other.runs, " against ", ref.right_side, "/", ref.runs)
                       : "");
    absl::StrAppend(&findings, "- ", claim.claim, ": ",
                    differences.empty() ? "no difference is significant" : differences, ".\n");
  }
  MarkdownTable times({"planner", "mean time (s)"});
  for (size_t p = 0; p < planners.size(); ++p) {
    times.AddRow({planners[p].label, NumberCell(Mean(results[p].seconds))});
  }
  return absl::StrCat(
      "## Figs. 10-11: 2D (BAS against PSO and APF)\n\n"
      "The generated 10-circle world of aem-bso-worlds (bench/worlds",
      kWorldFile,
      ", 100 x 100, start (10, 10), goal (90, 90)), standing in for the paper's unpublished "
      "map with circular obstacles. BAS with the paper's 2D model: `init=paper`, two path points "
      "joined by a cubic spline, fitness L (1 + M ξ), ",
      iterations, " iterations, step ", kPaperBasStep,
      " (Fig. 11), every move taken; `bas + PSO term` adds eq. 19 (m = 1, c1 = 1.5). PSO: the "
      "same model and iterations, ",
      kPsoParticles,
      " particles (the paper gives neither). APF: the planner's defaults (its path is not a "
      "spline, so only its length and collisions compare). ",
      runs, " runs each, seeds ", options.seed,
      " + i. `right of the start-goal line`: found paths "
      "whose farthest point from the line lies right of it.\n\n",
      table.ToString(), "\n", tests.ToString(), "\nFindings (tests at p < ", kSignificanceLevel,
      "):\n\n", findings, "\n## Time per run, 2D\n\n", times.ToString(), "\n");
}

}  // namespace swarmplan::bench::bas
