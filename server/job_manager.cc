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

// Tokens of a listing with one filter are not accepted by a listing with another.
std::string ListScope(std::vector<v1::JobState> states) {
  std::sort(states.begin(), states.end());
  states.erase(std::unique(states.begin(), states.end()), states.end());
  return absl::StrCat("jobs:", absl::StrJoin(states, ","));
}

}  // namespace

JobManager::JobManager(const ServerConfig& config, const Registry& registry, MapCatalog& maps,
                       Store& store, Metrics& metrics, SharedJobs shared_jobs)
    : config_(config),
      registry_(registry),
      maps_(maps),
      store_(store),
      metrics_(metrics),
      optima_(registry, config.optimum_budget, kOptimumCacheEntries),
      shared_(std::move(shared_jobs)) {
  const int workers =
      config.workers > 0 ? config.workers : std::max(1u, std::thread::hardware_concurrency());
  queue_ = std::make_unique<JobQueue>(
      workers, config.queue_capacity, [this](const JobPtr& job) { Execute(job); },
      [this](int depth, int busy) {
        metrics_.SetQueueDepth(depth);
        metrics_.SetWorkersBusy(busy);
      });
  metrics_.SetWorkers(queue_->workers());
  if (shared()) StartShared();
}

JobManager::~JobManager() {
  StopShared();
  queue_->Stop();
}

absl::StatusOr<PlanRequest> JobManager::Resolve(const v1::PlanRequest& request, uint64_t seed,
                                                v1::MapInfo* map_info) const {
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
  plan.vehicle = FromProto(request.vehicle());
  if (request.via_points_size() > kMaxViaPoints) {
    return absl::InvalidArgumentError(
        absl::StrCat("via_points: at most ", kMaxViaPoints, ", got ", request.via_points_size()));
  }
  for (const v1::Point& p : request.via_points()) plan.via_points.push_back(FromProto(p));
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
  *map_info = (*map)->info;
  return plan;
}

void JobManager::Add(const JobPtr& job) {
  absl::MutexLock lock(&mu_);
  jobs_[job->id] = job;
}

absl::StatusOr<JobPtr> JobManager::FromStored(const StoredJob& stored) {
  v1::Job record;
  if (!record.ParseFromString(stored.record)) {
    return absl::DataLossError(absl::StrCat("job ", stored.id, ": stored record is corrupt"));
  }
  auto job = std::make_shared<Job>(stored.id, record.request().detached());
  job->plan.algorithm = record.request().algorithm();
  absl::MutexLock lock(&job->mu);
  job->record = std::move(record);
  // Nobody watches a stored job's Plan call any more.
  job->owner_gone = true;
  if (IsFinal(job->record.state())) job->events.Publish(FinishedEvent(job->record));
  return job;
}

void JobManager::CacheFinished(const JobPtr& job) {
  if (auto it = cache_pos_.find(job->id); it != cache_pos_.end()) {
    cache_order_.splice(cache_order_.begin(), cache_order_, it->second);
  } else {
    jobs_[job->id] = job;
    cache_order_.push_front(job->id);
    cache_pos_[job->id] = cache_order_.begin();
  }
  while (cache_order_.size() > static_cast<size_t>(config_.job_cache_entries)) {
    jobs_.erase(cache_order_.back());
    cache_pos_.erase(cache_order_.back());
    cache_order_.pop_back();
  }
  metrics_.SetJobCacheEntries(static_cast<int>(cache_order_.size()));
}

void JobManager::Forget(const std::vector<std::string>& ids) {
  for (const std::string& id : ids) {
    if (auto it = cache_pos_.find(id); it != cache_pos_.end()) {
      cache_order_.erase(it->second);
      cache_pos_.erase(it);
      jobs_.erase(id);
    }
  }
  metrics_.SetJobCacheEntries(static_cast<int>(cache_order_.size()));
}

int JobManager::cached_finished_jobs() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(cache_order_.size());
}

void JobManager::Retire(Job& job) {
  {
    absl::MutexLock lock(&retention_mu_);
    // Replicas sharing a store count what all of them finished.
    absl::StatusOr<int64_t> finished =
        shared() ? store_.CountFinishedJobs() : absl::StatusOr<int64_t>(finished_in_store_ + 1);
    if (finished.ok()) finished_in_store_ = *finished;
  }
  {
    absl::MutexLock lock(&mu_);
    if (auto it = jobs_.find(job.id); it != jobs_.end()) CacheFinished(it->second);
  }
  EnforceRetainedCap();
}

void JobManager::EnforceRetainedCap() {
  absl::MutexLock retention_lock(&retention_mu_);
  const int64_t excess = finished_in_store_ - config_.max_retained_jobs;
  if (excess <= 0) return;
  absl::StatusOr<std::vector<std::string>> deleted = store_.DeleteOldestFinishedJobs(excess);
  if (!deleted.ok()) {
    spdlog::warn("cannot delete the finished jobs beyond --max-retained-jobs {}: {}",
                 config_.max_retained_jobs, deleted.status().ToString());
    return;
  }
  finished_in_store_ -= static_cast<int64_t>(deleted->size());
  absl::MutexLock lock(&mu_);
  Forget(*deleted);
}

absl::StatusOr<JobManager::Submitted> JobManager::Submit(const v1::PlanRequest& request,
                                                         bool detached) {
  if (absl::Status s = CheckRequestBounds(request); !s.ok()) return s;
  absl::MutexLock submit_lock(&submit_mu_);
  if (!request.client_request_id().empty()) {
    // Every job is in the store before Submit returns, so the store knows every id in use.
    absl::StatusOr<StoredJob> stored = store_.FindJobByClientRequestId(request.client_request_id());
    if (!stored.ok() && !absl::IsNotFound(stored.status())) return stored.status();
    absl::StatusOr<JobPtr> found =
        stored.ok() ? Find(stored->id) : absl::StatusOr<JobPtr>(stored.status());
    if (found.ok()) {
      JobPtr first = *found;
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
  v1::MapInfo map;
  absl::StatusOr<PlanRequest> plan = Resolve(request, seed, &map);
  if (!plan.ok()) return plan.status();

  auto job = std::make_shared<Job>(NewId("job-"), detached);
  job->plan = std::move(*plan);
  // Known before a worker can take it, so that it finishes (and is cached) as a known job.
  Add(job);
  {
    absl::MutexLock job_lock(&job->mu);
    const absl::Time now = absl::Now();
    job->queued_at = now;
    job->record.set_id(job->id);
    job->record.set_state(v1::JOB_STATE_QUEUED);
    *job->record.mutable_request() = request;
    job->record.mutable_request()->set_detached(detached);
    job->record.set_seed(seed);
    job->record.set_map_name(map.name());
    job->record.set_map_version(map.version());
    *job->record.mutable_created_at() = ToProto(now);
    // Queue, record and announce under the job's lock: a worker cannot start it before.
    absl::StatusOr<int64_t> position = shared()
                                           ? shared_.queue->Push(ToStored(job->id, job->record))
                                           : absl::StatusOr<int64_t>(queue_->Push(job));
    if (!position.ok()) {
      absl::MutexLock lock(&mu_);
      jobs_.erase(job->id);
      return position.status();
    }
    job->record.set_queue_position(static_cast<int32_t>(*position));
    if (!shared()) Persist(*job, job->record);  // the shared queue recorded it with its place
    spdlog::info("job {} queued algorithm={} map={} seed={} position={}", job->id,
                 job->plan.algorithm, request.map_id(), seed, *position);
    v1::JobEvent accepted;
    accepted.mutable_accepted()->set_queue_position(static_cast<int32_t>(*position));
    accepted.mutable_accepted()->set_seed(seed);
    Announce(*job, std::move(accepted));
  }
  // Until a worker here takes it, another replica may run it.
  if (shared()) Follow(job);
  return Submitted{job, false};
}

bool JobManager::Persist(Job& job, const v1::Job& record) {
  const StoredJob stored = ToStored(job.id, record);
  if (job.lease.has_value()) {
    absl::StatusOr<bool> held = shared_.queue->Record(*job.lease, stored);
    // Redis unreachable for a moment (a failover, a restart): try again before the attempt is
    // given up, well within the lease.
    for (absl::Duration pause = absl::Milliseconds(100);
         !held.ok() && pause < shared_.queue->options().lease / 4; pause *= 2) {
      absl::SleepFor(pause);
      held = shared_.queue->Record(*job.lease, stored);
    }
    if (held.ok() && *held) return true;
    spdlog::warn("job {}: attempt {} is no longer this replica's ({}); it stops here", job.id,
                 job.lease->attempt,
                 held.ok() ? "another replica took it over" : held.status().ToString());
    LoseLease(job);
    return false;
  }
  if (absl::Status s = store_.PutJob(stored); !s.ok()) {
    spdlog::error("job {}: cannot record state {}: {}", job.id, StateLabel(record.state()),
                  s.ToString());
  }
  return true;
}

void JobManager::Requeue(Job& job) {
  if (!job.lease.has_value()) {
    Persist(job, job.record);
    return;
  }
  absl::StatusOr<bool> released = shared_.queue->Release(*job.lease, ToStored(job.id, job.record));
  if (!released.ok() || !*released) {
    spdlog::warn("job {}: cannot put it back in the shared queue ({}); its lease runs out instead",
                 job.id,
                 released.ok() ? "another replica took it over" : released.status().ToString());
  }
  job.lease.reset();
  absl::MutexLock lock(&mu_);
  leased_.erase(job.id);
}

void JobManager::Announce(Job& job, v1::JobEvent event) {
  const bool share = shared() && !event.has_requeued();
  EventPtr published = job.events.Publish(std::move(event));
  if (share && published != nullptr) ShareEvent(job, published);
}

absl::StatusOr<JobPtr> JobManager::Find(const std::string& id) {
  if (id.empty()) return absl::InvalidArgumentError("id: required");
  {
    absl::MutexLock lock(&mu_);
    if (auto it = jobs_.find(id); it != jobs_.end()) {
      JobPtr job = it->second;
      if (cache_pos_.count(id) != 0) CacheFinished(job);  // most recently used now
      return job;
    }
  }
  absl::StatusOr<StoredJob> stored = store_.GetJob(id);
  if (absl::IsNotFound(stored.status()) ||
      (stored.ok() && stored->finished_at < absl::Now() - config_.job_retention)) {
    return absl::NotFoundError(absl::StrCat("job '", id, "' not found"));
  }
  if (!stored.ok()) return stored.status();
  absl::StatusOr<JobPtr> job = FromStored(*stored);
  if (!job.ok()) return job.status();
  {
    absl::MutexLock lock(&mu_);
    if (auto it = jobs_.find(id); it != jobs_.end()) return it->second;  // loaded meanwhile
    if (stored->finished_at != absl::InfiniteFuture()) {
      CacheFinished(*job);
      return *job;
    }
    // Unfinished and not held here: another replica submitted it (with SharedJobs only; without,
    // every unfinished job is in memory).
    jobs_[id] = *job;
  }
  if (shared()) Follow(*job);
  return *job;
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
                                                  const std::string& page_token) {
  const std::string scope = ListScope(states);
  std::optional<JobCursor> before;
  if (!page_token.empty()) {
    absl::StatusOr<PageKey> key = DecodePageToken(page_token, scope);
    if (!key.ok()) return key.status();
    before = JobCursor{key->created_us, key->id};
  }
  // The store lists every job; one more row than the page says whether another page follows.
  const std::vector<int> stored_states(states.begin(), states.end());
  absl::StatusOr<std::vector<StoredJob>> rows =
      store_.ListJobs(before.has_value() ? &*before : nullptr, stored_states, page_size + 1);
  if (!rows.ok()) return rows.status();
  Page page;
  size_t bytes = 0;
  PageKey last_listed, last_seen;
  bool stopped = false;
  for (const StoredJob& row : *rows) {
    JobPtr live;
    {
      absl::MutexLock lock(&mu_);
      if (auto it = jobs_.find(row.id); it != jobs_.end()) live = it->second;
    }
    v1::Job snapshot;
    if (live != nullptr) {
      snapshot = Snapshot(*live, /*with_result=*/false);
    } else if (!snapshot.ParseFromString(row.record)) {
      spdlog::warn("job {}: stored record is corrupt; not listed", row.id);
      continue;
    }
    snapshot.clear_result();
    last_seen = PageKey{absl::ToUnixMicros(row.created_at), row.id};
    // A job that changed state since the store answered may no longer match the filter.
    if (!states.empty() &&
        std::find(states.begin(), states.end(), snapshot.state()) == states.end()) {
      continue;
    }
    if (static_cast<int>(page.jobs.size()) == page_size ||
        !FitsPage(bytes, snapshot.ByteSizeLong(), max_bytes)) {
      page.next_page_token = EncodePageToken(last_listed, scope);
      stopped = true;
      break;
    }
    bytes += snapshot.ByteSizeLong();
    last_listed = last_seen;
    page.jobs.push_back(std::move(snapshot));
  }
  if (!stopped && static_cast<int>(rows->size()) > page_size) {
    page.next_page_token = EncodePageToken(last_seen, scope);
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
      } else if (shared() && !(*job)->lease.has_value()) {
        if (absl::Status s = CancelShared(**job); !s.ok()) return s;
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
  std::vector<JobPtr> all;
  {
    absl::MutexLock lock(&mu_);
    for (const auto& [job_id, job] : jobs_) all.push_back(job);
  }
  std::vector<std::string> holding;
  if (shared()) {
    absl::StatusOr<std::vector<std::string>> jobs = SharedJobsOnMap(id);
    if (!jobs.ok()) return jobs.status();
    holding = std::move(*jobs);
  }
  for (const JobPtr& job : all) {
    absl::MutexLock job_lock(&job->mu);
    if (!IsFinal(job->record.state()) && job->record.request().map_id() == id &&
        std::find(holding.begin(), holding.end(), job->id) == holding.end()) {
      holding.push_back(job->id);
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

v1::Job JobManager::FinalRecord(Job& job, v1::JobState state, const PlanResult* result,
                                const std::string& reason) {
  v1::Job record = job.record;
  record.set_state(state);
  *record.mutable_finished_at() = ToProto(absl::Now());
  record.clear_queue_position();
  if (result != nullptr) *record.mutable_result() = ToProto(*result);
  record.set_failure_reason(reason);
  return record;
}

void JobManager::Finish(Job& job, v1::JobState state, const PlanResult* result,
                        const std::string& reason) {
  v1::Job record = FinalRecord(job, state, result, reason);
  if (!Persist(job, record)) return;
  if (job.lease.has_value()) {
    job.lease.reset();
    absl::MutexLock lock(&mu_);
    leased_.erase(job.id);
  }
  Conclude(job, std::move(record));
}

void JobManager::Conclude(Job& job, v1::Job record) {
  job.record = std::move(record);
  const v1::JobState state = job.record.state();
  Announce(job, FinishedEvent(job.record));

  const absl::Time now = FromProto(job.record.finished_at());
  const absl::Time started = job.record.has_started_at() ? FromProto(job.record.started_at()) : now;
  const double seconds = absl::ToDoubleSeconds(now - started);
  metrics_.JobFinished(job.plan.algorithm, StateLabel(state), seconds,
                       job.record.result().evaluations());
  const std::string& reason = job.record.failure_reason();
  spdlog::info("job {} {} algorithm={} map={} duration={:.3f}s{}{}", job.id, StateLabel(state),
               job.plan.algorithm, job.record.request().map_id(), seconds,
               reason.empty() ? "" : " reason=", reason);
  // Before anyone can see the final state and list: the cap holds whenever a job is final.
  Retire(job);
}

void JobManager::SweepExpired(bool now) {
  const absl::Time t = absl::Now();
  {
    absl::MutexLock lock(&mu_);
    if (!now && t - last_sweep_ < absl::Minutes(1)) return;
    last_sweep_ = t;
  }
  absl::MutexLock retention_lock(&retention_mu_);
  absl::StatusOr<std::vector<std::string>> deleted =
      store_.DeleteJobsFinishedBefore(t - config_.job_retention);
  if (!deleted.ok()) {
    spdlog::warn("cannot delete expired jobs: {}", deleted.status().ToString());
    return;
  }
  finished_in_store_ -= static_cast<int64_t>(deleted->size());
  absl::MutexLock lock(&mu_);
  Forget(*deleted);
}

absl::Status JobManager::Recover() {
  // Unfinished jobs wait in the shared queue, where any replica takes them.
  absl::StatusOr<std::vector<StoredJob>> stored =
      shared() ? absl::StatusOr<std::vector<StoredJob>>(std::vector<StoredJob>{})
               : store_.LoadJobsToRecover();
  if (!stored.ok()) return stored.status();
  int requeued = 0;
  std::vector<JobPtr> failed;
  for (const StoredJob& s : *stored) {
    absl::StatusOr<JobPtr> loaded = FromStored(s);
    if (!loaded.ok()) {
      spdlog::warn("{}; skipped", loaded.status().ToString());
      continue;
    }
    JobPtr job = *loaded;
    absl::ReleasableMutexLock lock(&job->mu);
    if (IsFinal(job->record.state())) {
      // Recorded before the store kept client_request_id in a column: record it there now.
      if (!s.client_request_id_known) Persist(*job, job->record);
      continue;
    }
    v1::MapInfo map;
    absl::StatusOr<PlanRequest> plan = Resolve(job->record.request(), job->record.seed(), &map);
    if (!plan.ok()) {
      Finish(*job, v1::JOB_STATE_FAILED, nullptr,
             absl::StrCat("cannot run again after a restart: ", plan.status().message()));
      failed.push_back(job);
      continue;
    }
    job->plan = std::move(*plan);
    job->record.set_state(v1::JOB_STATE_QUEUED);
    job->record.clear_started_at();
    job->record.clear_progress();
    job->queued_at = absl::Now();
    absl::StatusOr<int> position = queue_->Push(job, /*ignore_capacity=*/true);
    if (!position.ok()) return position.status();
    Persist(*job, job->record);
    v1::JobEvent accepted;
    accepted.mutable_accepted()->set_queue_position(*position);
    accepted.mutable_accepted()->set_seed(job->record.seed());
    job->events.Publish(std::move(accepted));
    ++requeued;
    lock.Release();
    Add(job);
  }
  absl::StatusOr<int64_t> finished = store_.CountFinishedJobs();
  if (!finished.ok()) return finished.status();
  {
    absl::MutexLock lock(&retention_mu_);
    finished_in_store_ = *finished;  // the failed ones included
  }
  {
    absl::MutexLock lock(&mu_);
    for (const JobPtr& job : failed) CacheFinished(job);
  }
  SweepExpired(/*now=*/true);
  EnforceRetainedCap();
  if (requeued > 0) spdlog::info("recovered {} unfinished jobs; queued again", requeued);
  return absl::OkStatus();
}

void JobManager::Shutdown(absl::Duration grace) {
  shutting_down_.store(true);
  StopFeeding();
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
  if (shared()) ReleaseWaiting();
  StopShared();
  std::vector<JobPtr> all;
  {
    absl::MutexLock lock(&mu_);
    for (const auto& [id, job] : jobs_) all.push_back(job);
  }
  for (const JobPtr& job : all) {
    absl::MutexLock lock(&job->mu);
    if (IsFinal(job->record.state())) continue;
    v1::JobEvent requeued;
    requeued.mutable_requeued()->set_reason(absl::StrCat(
        "the server is shutting down; job ", job->id, " is queued again and runs, with its seed, ",
        shared() ? "on another replica" : "when the server is back"));
    job->events.Publish(std::move(requeued));
  }
}

}  // namespace swarmplan::server
