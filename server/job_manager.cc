#include "server/job_manager.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <optional>
#include <thread>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/time/clock.h"
#include "core/random.h"
#include "google/protobuf/util/message_differencer.h"
#include "server/ids.h"
#include "server/proto_convert.h"
#include "server/request_validation.h"

namespace swarmplan::server {
namespace {

// Exact optima kept for repeated queries (a few hundred bytes each).
constexpr size_t kOptimumCacheEntries = 4096;

// Whether the planner declares `name` as a population size (capped by --max-population).
bool IsPopulationSize(const PlannerInfo* planner, const std::string& name) {
  if (planner == nullptr) return false;
  for (const ParamSpec& spec : planner->params) {
    if (spec.name == name) return spec.population_size;
  }
  return false;
}

// `planner` is null for an unknown algorithm, which ValidatePlanRequest reports.
absl::Status CheckLimits(const v1::PlanRequest& request, const PlannerInfo* planner,
                         const ParamValues& params, const ServerConfig& config) {
  if (request.limits().max_iterations() < 0) {
    return absl::InvalidArgumentError("limits.max_iterations: must be >= 0");
  }
  if (request.limits().max_iterations() > config.max_iterations) {
    return absl::InvalidArgumentError(
        absl::StrCat("limits.max_iterations: ", request.limits().max_iterations(),
                     " exceeds the server's limit of ", config.max_iterations));
  }
  if (absl::Status s = CheckDuration("limits.time_budget", request.limits().time_budget());
      !s.ok()) {
    return s;
  }
  const absl::Duration budget = FromProto(request.limits().time_budget());
  if (budget > config.max_job_time) {
    return absl::InvalidArgumentError(
        absl::StrCat("limits.time_budget: ", absl::FormatDuration(budget),
                     " exceeds the server's limit of ", absl::FormatDuration(config.max_job_time)));
  }
  if (request.progress().every_iterations() < 0) {
    return absl::InvalidArgumentError("progress.every_iterations: must be >= 0");
  }
  if (absl::Status s = CheckDuration("progress.min_interval", request.progress().min_interval());
      !s.ok()) {
    return s;
  }
  for (const auto& [name, value] : params) {
    if (!IsPopulationSize(planner, name)) continue;
    const int64_t* n = std::get_if<int64_t>(&value);
    if (n != nullptr && *n > config.max_population) {
      return absl::InvalidArgumentError(absl::StrCat("parameter '", name, "': ", *n,
                                                     " exceeds the server's limit of ",
                                                     config.max_population, " (--max-population)"));
    }
  }
  return absl::OkStatus();
}

// A reused client_request_id names the same request when every field but `detached` (how the
// caller follows the job, not what it plans) is equal.
bool SameRequest(const v1::PlanRequest& a, const v1::PlanRequest& b) {
  v1::PlanRequest x = a;
  v1::PlanRequest y = b;
  x.clear_detached();
  y.clear_detached();
  return google::protobuf::util::MessageDifferencer::Equals(x, y);
}

// Where a job stands in listings.
PageKey KeyOf(const Job& job) ABSL_EXCLUSIVE_LOCKS_REQUIRED(job.mu) {
  return PageKey{absl::ToUnixMicros(FromProto(job.record.created_at())), job.id};
}

// Tokens of a listing with one filter are not accepted by a listing with another.
std::string ListScope(std::vector<v1::JobState> states) {
  std::sort(states.begin(), states.end());
  states.erase(std::unique(states.begin(), states.end()), states.end());
  return absl::StrCat("jobs:", absl::StrJoin(states, ","));
}

}  // namespace

JobManager::JobManager(const ServerConfig& config, const Registry& registry, MapCatalog& maps,
                       Store& store, Metrics& metrics)
    : config_(config),
      registry_(registry),
      maps_(maps),
      store_(store),
      metrics_(metrics),
      optima_(registry, config.optimum_budget, kOptimumCacheEntries) {
  const int workers =
      config.workers > 0 ? config.workers : std::max(1u, std::thread::hardware_concurrency());
  queue_ = std::make_unique<JobQueue>(
      workers, config.queue_capacity, [this](const JobPtr& job) { Execute(job); },
      [this](int depth, int busy) {
        metrics_.SetQueueDepth(depth);
        metrics_.SetWorkersBusy(busy);
      });
  metrics_.SetWorkers(queue_->workers());
}

JobManager::~JobManager() { queue_->Stop(); }

absl::StatusOr<PlanRequest> JobManager::Resolve(const v1::PlanRequest& request, uint64_t seed,
                                                std::string* map_name) const {
  if (request.map_id().empty()) return absl::InvalidArgumentError("map_id: required");
  if (request.algorithm().empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("algorithm: required; one of: ", absl::StrJoin(registry_.Ids(), ", ")));
  }
  absl::StatusOr<std::shared_ptr<const CatalogEntry>> map = maps_.Get(request.map_id());
  if (!map.ok()) {
    return absl::Status(map.status().code(), absl::StrCat("map_id: ", map.status().message()));
  }
  absl::StatusOr<ParamValues> params = FromProto(request.parameters());
  if (!params.ok()) return params.status();
  if (absl::Status s = CheckLimits(request, registry_.Find(request.algorithm()), *params, config_);
      !s.ok()) {
    return s;
  }

  PlanRequest plan;
  plan.algorithm = request.algorithm();
  plan.params = std::move(*params);
  plan.smoothing = request.smoothing().empty() ? "none" : request.smoothing();
  plan.problem.map = (*map)->map;
  plan.problem.start = FromProto(request.start());
  plan.problem.goal = FromProto(request.goal());
  plan.problem.clearance = request.clearance();
  plan.problem.fleet = FromProto(request.preferences());
  plan.problem.alternatives = request.alternatives();
  plan.problem.limits.max_iterations = request.limits().max_iterations() > 0
                                           ? request.limits().max_iterations()
                                           : config_.max_iterations;
  const absl::Duration budget = FromProto(request.limits().time_budget());
  plan.problem.limits.time_budget = budget > absl::ZeroDuration() ? budget : config_.max_job_time;
  plan.problem.seed = seed;
  if (absl::Status s = ValidatePlanRequest(registry_, plan); !s.ok()) return s;
  *map_name = (*map)->info.name();
  return plan;
}

void JobManager::Add(const JobPtr& job) {
  absl::MutexLock lock(&mu_);
  jobs_[job->id] = job;
  absl::MutexLock job_lock(&job->mu);
  order_[KeyOf(*job)] = job->id;
  if (!job->record.request().client_request_id().empty()) {
    by_client_request_id_[job->record.request().client_request_id()] = job->id;
  }
}

absl::StatusOr<JobManager::Submitted> JobManager::Submit(const v1::PlanRequest& request,
                                                         bool detached) {
  if (absl::Status s = CheckRequestBounds(request); !s.ok()) return s;
  absl::MutexLock submit_lock(&submit_mu_);
  if (!request.client_request_id().empty()) {
    absl::MutexLock lock(&mu_);
    if (auto it = by_client_request_id_.find(request.client_request_id());
        it != by_client_request_id_.end()) {
      JobPtr first = jobs_.at(it->second);
      absl::MutexLock job_lock(&first->mu);
      if (!SameRequest(first->record.request(), request)) {
        return absl::AlreadyExistsError(
            absl::StrCat("client_request_id: already used by job ", first->id,
                         " for a different request; a new request needs a new client_request_id"));
      }
      return Submitted{first, true};
    }
  }
  const uint64_t seed = request.seed() != 0 ? request.seed() : PickSeed();
  std::string map_name;
  absl::StatusOr<PlanRequest> plan = Resolve(request, seed, &map_name);
  if (!plan.ok()) return plan.status();

  auto job = std::make_shared<Job>(NewId("job-"), detached);
  job->plan = std::move(*plan);
  job->map_name = map_name;
  {
    absl::MutexLock job_lock(&job->mu);
    const absl::Time now = absl::Now();
    job->queued_at = now;
    job->record.set_id(job->id);
    job->record.set_state(v1::JOB_STATE_QUEUED);
    *job->record.mutable_request() = request;
    job->record.mutable_request()->set_detached(detached);
    job->record.set_seed(seed);
    *job->record.mutable_created_at() = ToProto(now);
    // Queue, record and announce under the job's lock: a worker cannot start it before.
    absl::StatusOr<int> position = queue_->Push(job);
    if (!position.ok()) return position.status();
    job->record.set_queue_position(*position);
    Persist(*job);
    spdlog::info("job {} queued algorithm={} map={} seed={} position={}", job->id,
                 job->plan.algorithm, request.map_id(), seed, *position);
    v1::JobEvent accepted;
    accepted.mutable_accepted()->set_queue_position(*position);
    accepted.mutable_accepted()->set_seed(seed);
    job->events.Publish(std::move(accepted));
  }
  Add(job);
  return Submitted{job, false};
}

void JobManager::Persist(Job& job) {
  StoredJob stored;
  stored.id = job.id;
  stored.state = job.record.state();
  job.record.SerializeToString(&stored.record);
  stored.created_at = FromProto(job.record.created_at());
  if (IsFinal(job.record.state())) stored.finished_at = FromProto(job.record.finished_at());
  if (absl::Status s = store_.PutJob(stored); !s.ok()) {
    spdlog::error("job {}: cannot record state {}: {}", job.id, StateLabel(job.record.state()),
                  s.ToString());
  }
}

absl::StatusOr<JobPtr> JobManager::Find(const std::string& id) const {
  if (id.empty()) return absl::InvalidArgumentError("id: required");
  absl::MutexLock lock(&mu_);
  auto it = jobs_.find(id);
  if (it == jobs_.end()) return absl::NotFoundError(absl::StrCat("job '", id, "' not found"));
  return it->second;
}

v1::Job JobManager::Snapshot(Job& job, bool with_result) const {
  v1::Job out;
  {
    absl::MutexLock lock(&job.mu);
    out = job.record;
  }
  if (out.state() == v1::JOB_STATE_QUEUED) {
    const int position = queue_->Position(job.id);
    if (position >= 0) out.set_queue_position(position);
  } else {
    out.clear_queue_position();
  }
  if (!with_result) out.clear_result();
  return out;
}

absl::StatusOr<JobManager::Page> JobManager::List(const std::vector<v1::JobState>& states,
                                                  int page_size, size_t max_bytes,
                                                  const std::string& page_token) const {
  const std::string scope = ListScope(states);
  std::optional<PageKey> before;
  if (!page_token.empty()) {
    absl::StatusOr<PageKey> key = DecodePageToken(page_token, scope);
    if (!key.ok()) return key.status();
    before = std::move(*key);
  }
  std::vector<JobPtr> candidates;
  {
    absl::MutexLock lock(&mu_);
    auto end = before.has_value() ? order_.lower_bound(*before) : order_.end();
    for (auto it = std::make_reverse_iterator(end); it != order_.rend(); ++it) {
      candidates.push_back(jobs_.at(it->second));
    }
  }
  Page page;
  size_t bytes = 0;
  PageKey last;
  for (const JobPtr& job : candidates) {
    v1::Job snapshot = Snapshot(*job, /*with_result=*/false);
    if (!states.empty() &&
        std::find(states.begin(), states.end(), snapshot.state()) == states.end()) {
      continue;
    }
    if (static_cast<int>(page.jobs.size()) == page_size ||
        !FitsPage(bytes, snapshot.ByteSizeLong(), max_bytes)) {
      page.next_page_token = EncodePageToken(last, scope);
      break;
    }
    bytes += snapshot.ByteSizeLong();
    last = PageKey{absl::ToUnixMicros(FromProto(snapshot.created_at())), snapshot.id()};
    page.jobs.push_back(std::move(snapshot));
  }
  return page;
}

absl::StatusOr<v1::Job> JobManager::Cancel(const std::string& id) {
  absl::StatusOr<JobPtr> job = Find(id);
  if (!job.ok()) return job.status();
  {
    absl::MutexLock lock(&(*job)->mu);
    if (!IsFinal((*job)->record.state())) {
      (*job)->cancel_cause = CancelCause::kClient;
      if (queue_->Remove(id)) {
        Finish(**job, v1::JOB_STATE_CANCELLED, nullptr, "cancelled before it started");
      } else {
        (*job)->stop.Cancel();
      }
    }
  }
  return Snapshot(**job, /*with_result=*/true);
}

absl::Status JobManager::DeleteMap(const std::string& id) {
  // Submit resolves and queues under submit_mu_: no job can take the map meanwhile.
  absl::MutexLock submit_lock(&submit_mu_);
  std::vector<std::string> holding;
  {
    absl::MutexLock lock(&mu_);
    for (const auto& [job_id, job] : jobs_) {
      absl::MutexLock job_lock(&job->mu);
      if (!IsFinal(job->record.state()) && job->record.request().map_id() == id) {
        holding.push_back(job_id);
      }
    }
  }
  if (!holding.empty()) {
    constexpr size_t kNamed = 10;
    const size_t named = std::min(holding.size(), kNamed);
    return absl::FailedPreconditionError(absl::StrCat(
        "id: map '", id, "' is used by ", holding.size(), " queued or running jobs (",
        absl::StrJoin(holding.begin(), holding.begin() + named, ", "),
        holding.size() > named ? ", ..." : "", "); cancel them or wait until they finish"));
  }
  return maps_.Delete(id);
}

void JobManager::WatcherLeft(const JobPtr& job, bool owner, int remaining) {
  bool cancel = false;
  {
    absl::MutexLock lock(&job->mu);
    if (owner) job->owner_gone = true;
    cancel = !job->detached && job->owner_gone && remaining == 0 && !IsFinal(job->record.state()) &&
             !shutting_down_.load();
  }
  if (cancel) {
    spdlog::info("job {}: its Plan caller went away; cancelling", job->id);
    (void)Cancel(job->id);
  }
}

void JobManager::Finish(Job& job, v1::JobState state, const PlanResult* result,
                        const std::string& reason) {
  const absl::Time now = absl::Now();
  job.record.set_state(state);
  *job.record.mutable_finished_at() = ToProto(now);
  job.record.clear_queue_position();
  if (result != nullptr) *job.record.mutable_result() = ToProto(*result);
  job.record.set_failure_reason(reason);
  Persist(job);

  v1::JobEvent finished;
  finished.mutable_finished()->set_state(state);
  if (result != nullptr) *finished.mutable_finished()->mutable_result() = job.record.result();
  finished.mutable_finished()->set_failure_reason(reason);
  job.events.Publish(std::move(finished));

  const absl::Time started = job.record.has_started_at() ? FromProto(job.record.started_at()) : now;
  const double seconds = absl::ToDoubleSeconds(now - started);
  metrics_.JobFinished(job.plan.algorithm, StateLabel(state), seconds,
                       result != nullptr ? result->evaluations : 0);
  spdlog::info("job {} {} algorithm={} map={} duration={:.3f}s{}{}", job.id, StateLabel(state),
               job.plan.algorithm, job.record.request().map_id(), seconds,
               reason.empty() ? "" : " reason=", reason);
}

void JobManager::SweepExpired() {
  const absl::Time now = absl::Now();
  const absl::Time cutoff = now - config_.job_retention;
  std::vector<JobPtr> all;
  {
    absl::MutexLock lock(&mu_);
    if (now - last_sweep_ < absl::Minutes(1)) return;
    last_sweep_ = now;
    for (const auto& [id, job] : jobs_) all.push_back(job);
  }
  std::vector<std::string> expired;
  for (const JobPtr& job : all) {
    absl::MutexLock lock(&job->mu);
    if (IsFinal(job->record.state()) && FromProto(job->record.finished_at()) < cutoff) {
      expired.push_back(job->id);
    }
  }
  if (absl::StatusOr<int> n = store_.DeleteJobsFinishedBefore(cutoff); !n.ok()) {
    spdlog::warn("cannot delete expired jobs: {}", n.status().ToString());
  }
  absl::MutexLock lock(&mu_);
  for (const std::string& id : expired) jobs_.erase(id);
  for (auto it = order_.begin(); it != order_.end();) {
    it = jobs_.count(it->second) ? std::next(it) : order_.erase(it);
  }
  for (auto it = by_client_request_id_.begin(); it != by_client_request_id_.end();) {
    it = jobs_.count(it->second) ? std::next(it) : by_client_request_id_.erase(it);
  }
}

absl::Status JobManager::Recover() {
  absl::StatusOr<std::vector<StoredJob>> stored = store_.LoadJobs();
  if (!stored.ok()) return stored.status();
  const absl::Time cutoff = absl::Now() - config_.job_retention;
  int requeued = 0;
  for (const StoredJob& s : *stored) {
    if (s.finished_at != absl::InfiniteFuture() && s.finished_at < cutoff) continue;
    v1::Job record;
    if (!record.ParseFromString(s.record)) {
      spdlog::warn("job {}: stored record is corrupt; skipped", s.id);
      continue;
    }
    auto job = std::make_shared<Job>(s.id, record.request().detached());
    std::string map_name;
    absl::StatusOr<PlanRequest> plan = Resolve(record.request(), record.seed(), &map_name);
    if (plan.ok()) {
      job->plan = std::move(*plan);
      job->map_name = map_name;
    } else {
      job->plan.algorithm = record.request().algorithm();
    }
    {
      absl::MutexLock lock(&job->mu);
      job->record = std::move(record);
      // Nobody watches a recovered job's Plan call any more.
      job->owner_gone = true;
      if (IsFinal(job->record.state())) {
        v1::JobEvent finished;
        finished.mutable_finished()->set_state(job->record.state());
        if (job->record.has_result()) {
          *finished.mutable_finished()->mutable_result() = job->record.result();
        }
        finished.mutable_finished()->set_failure_reason(job->record.failure_reason());
        job->events.Publish(std::move(finished));
      } else if (!plan.ok()) {
        Finish(*job, v1::JOB_STATE_FAILED, nullptr,
               absl::StrCat("cannot run again after a restart: ", plan.status().message()));
      } else {
        job->record.set_state(v1::JOB_STATE_QUEUED);
        job->record.clear_started_at();
        job->record.clear_progress();
        job->queued_at = absl::Now();
        absl::StatusOr<int> position = queue_->Push(job, /*ignore_capacity=*/true);
        if (!position.ok()) return position.status();
        Persist(*job);
        v1::JobEvent accepted;
        accepted.mutable_accepted()->set_queue_position(*position);
        accepted.mutable_accepted()->set_seed(job->record.seed());
        job->events.Publish(std::move(accepted));
        ++requeued;
      }
    }
    Add(job);
  }
  if (requeued > 0) spdlog::info("recovered {} unfinished jobs; queued again", requeued);
  return absl::OkStatus();
}

void JobManager::Shutdown(absl::Duration grace) {
  shutting_down_.store(true);
  queue_->StopAccepting();
  if (!queue_->WaitIdle(grace)) {
    std::vector<JobPtr> all;
    {
      absl::MutexLock lock(&mu_);
      for (const auto& [id, job] : jobs_) all.push_back(job);
    }
    for (const JobPtr& job : all) {
      absl::MutexLock lock(&job->mu);
      if (job->record.state() == v1::JOB_STATE_RUNNING) {
        job->cancel_cause = CancelCause::kShutdown;
        job->stop.Cancel();
      }
    }
    queue_->WaitIdle(absl::InfiniteDuration());
  }
  queue_->Stop();
  std::vector<JobPtr> all;
  {
    absl::MutexLock lock(&mu_);
    for (const auto& [id, job] : jobs_) all.push_back(job);
  }
  for (const JobPtr& job : all) {
    absl::MutexLock lock(&job->mu);
    if (IsFinal(job->record.state())) continue;
    v1::JobEvent requeued;
    requeued.mutable_requeued()->set_reason(
        absl::StrCat("the server is shutting down; job ", job->id,
                     " is queued again and runs, with its seed, when the server is back"));
    job->events.Publish(std::move(requeued));
  }
}

}  // namespace swarmplan::server
