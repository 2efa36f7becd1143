#include "server/sqlite_store.h"

#include <sqlite3.h>

#include <filesystem>
#include <system_error>

#include "absl/strings/str_cat.h"

namespace swarmplan::server {
namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS maps (
  id TEXT PRIMARY KEY,
  name TEXT NOT NULL,
  format TEXT NOT NULL,
  content_hash TEXT NOT NULL,
  source BLOB NOT NULL,
  created_us INTEGER NOT NULL
);
CREATE TABLE IF NOT EXISTS jobs (
  id TEXT PRIMARY KEY,
  state INTEGER NOT NULL,
  record BLOB NOT NULL,
  created_us INTEGER NOT NULL,
  finished_us INTEGER
);
CREATE TABLE IF NOT EXISTS map_names (
  name TEXT PRIMARY KEY,
  last_version INTEGER NOT NULL
);
CREATE INDEX IF NOT EXISTS maps_created ON maps(created_us, id);
CREATE INDEX IF NOT EXISTS jobs_finished ON jobs(finished_us);
CREATE INDEX IF NOT EXISTS jobs_created ON jobs(created_us, id);
)sql";

// A map without its source; maps keep their MapInfo in a column (NULL: stored before there was
// one) and their version (0: stored before maps had versions).
constexpr const char* kMapInfoColumns = "id, name, format, content_hash, created_us, info, version";

// Jobs also keep their client_request_id in a column (NULL: recorded before there was one).
constexpr const char* kJobColumns = "id, state, record, created_us, finished_us, client_request_id";

// A prepared statement, finalized when it goes out of scope.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    rc_ = sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr);
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  absl::Status status() const { return rc_ == SQLITE_OK ? absl::OkStatus() : Error("prepare"); }
  void Bind(int i, const std::string& text) {
    sqlite3_bind_blob(stmt_, i, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
  }
  void BindText(int i, const std::string& text) {
    sqlite3_bind_text(stmt_, i, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
  }
  void Bind(int i, int64_t v) { sqlite3_bind_int64(stmt_, i, v); }
  void BindNull(int i) { sqlite3_bind_null(stmt_, i); }
  // SQLITE_ROW, SQLITE_DONE or an error code.
  int Step() { return sqlite3_step(stmt_); }
  std::string Text(int col) const {
    const void* p = sqlite3_column_blob(stmt_, col);
    const int n = sqlite3_column_bytes(stmt_, col);
    return p == nullptr ? std::string() : std::string(static_cast<const char*>(p), n);
  }
  int64_t Int(int col) const { return sqlite3_column_int64(stmt_, col); }
  bool IsNull(int col) const { return sqlite3_column_type(stmt_, col) == SQLITE_NULL; }
  absl::Status Error(const char* what) const {
    return absl::InternalError(absl::StrCat("sqlite ", what, ": ", sqlite3_errmsg(db_)));
  }
  absl::Status Done() { return Step() == SQLITE_DONE ? absl::OkStatus() : Error("step"); }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  int rc_ = SQLITE_OK;
};

int64_t ToMicros(absl::Time t) { return absl::ToUnixMicros(t); }
absl::Time FromMicros(int64_t us) { return absl::FromUnixMicros(us); }

// A row of "id, name, format, content_hash, source, created_us, info, version".
StoredMap ReadMap(const Statement& s) {
  return StoredMap{s.Text(0), s.Text(1), s.Text(2), s.Text(3), s.Text(4), FromMicros(s.Int(5)),
                   s.Text(6), s.Int(7)};
}

// A row of kMapInfoColumns.
StoredMap ReadMapInfo(const Statement& s) {
  return StoredMap{s.Text(0), s.Text(1), s.Text(2), s.Text(3), "", FromMicros(s.Int(4)),
                   s.Text(5), s.Int(6)};
}

// Every row `s` yields, read by `read`.
template <typename T>
absl::StatusOr<std::vector<T>> ReadAll(Statement& s, T (*read)(const Statement&)) {
  std::vector<T> rows;
  int rc;
  while ((rc = s.Step()) == SQLITE_ROW) rows.push_back(read(s));
  if (rc != SQLITE_DONE) return s.Error("step");
  return rows;
}

// A row of kJobColumns.
StoredJob ReadJob(const Statement& s) {
  StoredJob job;
  job.id = s.Text(0);
  job.state = static_cast<int>(s.Int(1));
  job.record = s.Text(2);
  job.created_at = FromMicros(s.Int(3));
  if (!s.IsNull(4)) job.finished_at = FromMicros(s.Int(4));
  job.client_request_id_known = !s.IsNull(5);
  job.client_request_id = s.Text(5);
  return job;
}

absl::StatusOr<std::vector<StoredJob>> ReadJobs(Statement& s) { return ReadAll(s, ReadJob); }

}  // namespace

absl::StatusOr<std::unique_ptr<SqliteStore>> SqliteStore::Open(const std::string& data_dir) {
  std::error_code ec;
  std::filesystem::create_directories(data_dir, ec);
  if (ec) {
    return absl::FailedPreconditionError(
        absl::StrCat("--data-dir ", data_dir, ": cannot create: ", ec.message()));
  }
  const std::string path = (std::filesystem::path(data_dir) / "swarmplan.db").string();
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    absl::Status s = absl::FailedPreconditionError(
        absl::StrCat("--data-dir ", data_dir, ": cannot open ", path, ": ", sqlite3_errmsg(db)));
    sqlite3_close(db);
    return s;
  }
  sqlite3_busy_timeout(db, 5000);
  std::unique_ptr<SqliteStore> store(new SqliteStore(db));
  absl::MutexLock lock(&store->mu_);
  for (const char* sql : {"PRAGMA journal_mode=WAL;", "PRAGMA synchronous=FULL;", kSchema}) {
    if (absl::Status s = store->Exec(sql); !s.ok()) return s;
  }
  if (absl::Status s = store->Migrate(); !s.ok()) return s;
  return store;
}

SqliteStore::~SqliteStore() {
  absl::MutexLock lock(&mu_);
  sqlite3_close(db_);
}

absl::Status SqliteStore::Exec(const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    absl::Status s = absl::InternalError(absl::StrCat("sqlite: ", error ? error : "error"));
    sqlite3_free(error);
    return s;
  }
  return absl::OkStatus();
}

absl::Status SqliteStore::AddColumn(const char* table, const char* column, const char* type) {
  Statement columns(db_, absl::StrCat("SELECT 1 FROM pragma_table_info('", table,
                                      "') WHERE name = '", column, "'")
                             .c_str());
  if (absl::Status st = columns.status(); !st.ok()) return st;
  const int rc = columns.Step();
  if (rc == SQLITE_ROW) return absl::OkStatus();
  if (rc != SQLITE_DONE) return columns.Error("step");
  return Exec(absl::StrCat("ALTER TABLE ", table, " ADD COLUMN ", column, " ", type, ";").c_str());
}

absl::Status SqliteStore::Migrate() {
  if (absl::Status s = AddColumn("jobs", "client_request_id", "TEXT"); !s.ok()) return s;
  if (absl::Status s = AddColumn("maps", "info", "BLOB"); !s.ok()) return s;
  if (absl::Status s = AddColumn("maps", "version", "INTEGER NOT NULL DEFAULT 0"); !s.ok()) {
    return s;
  }
  return Exec(
      "CREATE INDEX IF NOT EXISTS jobs_client_request_id ON jobs(client_request_id);"
      "DROP INDEX IF EXISTS maps_name_hash;"
      "CREATE INDEX IF NOT EXISTS maps_name_version ON maps(name, version);");
}

absl::StatusOr<int64_t> SqliteStore::VersionFor(const StoredMap& map) {
  if (map.version != 0) return map.version;
  Statement stored(db_, "SELECT version FROM maps WHERE id = ? AND version > 0");
  if (absl::Status st = stored.status(); !st.ok()) return st;
  stored.BindText(1, map.id);
  const int rc = stored.Step();
  if (rc == SQLITE_ROW) return stored.Int(0);
  if (rc != SQLITE_DONE) return stored.Error("step");
  Statement next(db_,
                 "INSERT INTO map_names(name, last_version) VALUES (?, 1) ON CONFLICT(name) DO "
                 "UPDATE SET last_version = last_version + 1 RETURNING last_version");
  if (absl::Status st = next.status(); !st.ok()) return st;
  next.BindText(1, map.name);
  if (next.Step() != SQLITE_ROW) return next.Error("step");
  const int64_t version = next.Int(0);
  if (next.Step() != SQLITE_DONE) return next.Error("step");
  return version;
}

absl::StatusOr<int64_t> SqliteStore::PutMap(const StoredMap& map) {
  absl::MutexLock lock(&mu_);
  // One transaction: the version is taken and used, or neither (also against other processes).
  if (absl::Status st = Exec("BEGIN IMMEDIATE;"); !st.ok()) return st;
  absl::StatusOr<int64_t> version = PutMapLocked(map);
  if (absl::Status st = Exec(version.ok() ? "COMMIT;" : "ROLLBACK;"); !st.ok()) return st;
  return version;
}

absl::StatusOr<int64_t> SqliteStore::PutMapLocked(const StoredMap& map) {
  absl::StatusOr<int64_t> version = VersionFor(map);
  if (!version.ok()) return version.status();
  Statement s(db_,
              "INSERT OR REPLACE INTO maps(id, name, format, content_hash, source, created_us, "
              "info, version) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, map.id);
  s.BindText(2, map.name);
  s.BindText(3, map.format);
  s.BindText(4, map.content_hash);
  s.Bind(5, map.source);
  s.Bind(6, ToMicros(map.created_at));
  if (map.info.empty()) {
    s.BindNull(7);
  } else {
    s.Bind(7, map.info);
  }
  s.Bind(8, *version);
  if (absl::Status st = s.Done(); !st.ok()) return st;
  return *version;
}

absl::StatusOr<StoredMap> SqliteStore::GetMap(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Statement s(db_,
              "SELECT id, name, format, content_hash, source, created_us, info, version FROM maps "
              "WHERE id = ?");
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, id);
  const int rc = s.Step();
  if (rc == SQLITE_ROW) return ReadMap(s);
  if (rc == SQLITE_DONE) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return s.Error("step");
}

absl::StatusOr<StoredMap> SqliteStore::GetMapInfo(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kMapInfoColumns, " FROM maps WHERE id = ?").c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, id);
  const int rc = s.Step();
  if (rc == SQLITE_ROW) return ReadMapInfo(s);
  if (rc == SQLITE_DONE) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return s.Error("step");
}

absl::StatusOr<std::vector<StoredMap>> SqliteStore::ListMaps(const MapCursor* after, int limit) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kMapInfoColumns, " FROM maps",
                                after != nullptr ? " WHERE (created_us, id) > (?, ?)" : "",
                                " ORDER BY created_us, id LIMIT ?")
                       .c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  int i = 1;
  if (after != nullptr) {
    s.Bind(i++, after->created_us);
    s.BindText(i++, after->id);
  }
  s.Bind(i, static_cast<int64_t>(limit));
  return ReadAll(s, ReadMapInfo);
}

absl::StatusOr<StoredMap> SqliteStore::FindMapVersion(const std::string& name, int64_t version) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kMapInfoColumns, " FROM maps WHERE name = ?",
                                version > 0 ? " AND version = ?" : "",
                                " ORDER BY version DESC, created_us DESC, id DESC LIMIT 1")
                       .c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, name);
  if (version > 0) s.Bind(2, version);
  const int rc = s.Step();
  if (rc == SQLITE_ROW) return ReadMapInfo(s);
  if (rc == SQLITE_DONE) return NoSuchMapVersion(name, version);
  return s.Error("step");
}

absl::StatusOr<std::vector<StoredMap>> SqliteStore::ListMapVersions(const std::string& name,
                                                                    int64_t after_version,
                                                                    int limit) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kMapInfoColumns,
                                " FROM maps WHERE name = ? AND version > ? ORDER BY version, id "
                                "LIMIT ?")
                       .c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, name);
  s.Bind(2, after_version);
  s.Bind(3, static_cast<int64_t>(limit));
  return ReadAll(s, ReadMapInfo);
}

absl::StatusOr<int64_t> SqliteStore::CountMaps() {
  absl::MutexLock lock(&mu_);
  Statement s(db_, "SELECT COUNT(*) FROM maps");
  if (absl::Status st = s.status(); !st.ok()) return st;
  if (s.Step() != SQLITE_ROW) return s.Error("step");
  return s.Int(0);
}

absl::Status SqliteStore::DeleteMap(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, "DELETE FROM maps WHERE id = ?");
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, id);
  if (absl::Status st = s.Done(); !st.ok()) return st;
  if (sqlite3_changes(db_) == 0)
    return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  return absl::OkStatus();
}

absl::Status SqliteStore::PutJob(const StoredJob& job) {
  absl::MutexLock lock(&mu_);
  Statement s(db_,
              "INSERT OR REPLACE INTO jobs(id, state, record, created_us, finished_us, "
              "client_request_id) VALUES (?, ?, ?, ?, ?, ?)");
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, job.id);
  s.Bind(2, static_cast<int64_t>(job.state));
  s.Bind(3, job.record);
  s.Bind(4, ToMicros(job.created_at));
  if (job.finished_at == absl::InfiniteFuture()) {
    s.BindNull(5);
  } else {
    s.Bind(5, ToMicros(job.finished_at));
  }
  s.BindText(6, job.client_request_id);
  return s.Done();
}

absl::StatusOr<StoredJob> SqliteStore::GetJob(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kJobColumns, " FROM jobs WHERE id = ?").c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, id);
  const int rc = s.Step();
  if (rc == SQLITE_ROW) return ReadJob(s);
  if (rc == SQLITE_DONE) return absl::NotFoundError(absl::StrCat("job '", id, "' not found"));
  return s.Error("step");
}

absl::StatusOr<StoredJob> SqliteStore::FindJobByClientRequestId(const std::string& id) {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kJobColumns,
                                " FROM jobs WHERE client_request_id = ? "
                                "ORDER BY created_us DESC, id DESC LIMIT 1")
                       .c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  s.BindText(1, id);
  const int rc = s.Step();
  if (rc == SQLITE_ROW) return ReadJob(s);
  if (rc == SQLITE_DONE) {
    return absl::NotFoundError(absl::StrCat("no job with client_request_id '", id, "'"));
  }
  return s.Error("step");
}

absl::StatusOr<std::vector<StoredJob>> SqliteStore::LoadJobsToRecover() {
  absl::MutexLock lock(&mu_);
  Statement s(db_, absl::StrCat("SELECT ", kJobColumns,
                                " FROM jobs WHERE finished_us IS NULL OR client_request_id IS NULL "
                                "ORDER BY created_us, id")
                       .c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  return ReadJobs(s);
}

absl::StatusOr<std::vector<StoredJob>> SqliteStore::ListJobs(const JobCursor* before,
                                                             const std::vector<int>& states,
                                                             int limit) {
  std::string sql = absl::StrCat("SELECT ", kJobColumns, " FROM jobs WHERE 1");
  if (before != nullptr) absl::StrAppend(&sql, " AND (created_us, id) < (?, ?)");
  if (!states.empty()) {
    absl::StrAppend(&sql, " AND state IN (?");
    for (size_t i = 1; i < states.size(); ++i) absl::StrAppend(&sql, ", ?");
    absl::StrAppend(&sql, ")");
  }
  absl::StrAppend(&sql, " ORDER BY created_us DESC, id DESC LIMIT ?");
  absl::MutexLock lock(&mu_);
  Statement s(db_, sql.c_str());
  if (absl::Status st = s.status(); !st.ok()) return st;
  int i = 1;
  if (before != nullptr) {
    s.Bind(i++, before->created_us);
    s.BindText(i++, before->id);
  }
  for (int state : states) s.Bind(i++, static_cast<int64_t>(state));
  s.Bind(i, static_cast<int64_t>(limit));
  return ReadJobs(s);
}

absl::StatusOr<int64_t> SqliteStore::CountFinishedJobs() {
  absl::MutexLock lock(&mu_);
  Statement s(db_, "SELECT COUNT(*) FROM jobs WHERE finished_us IS NOT NULL");
  if (absl::Status st = s.status(); !st.ok()) return st;
  if (s.Step() != SQLITE_ROW) return s.Error("step");
  return s.Int(0);
}

absl::StatusOr<std::vector<std::string>> SqliteStore::DeleteSelected(const char* select,
                                                                     int64_t value) {
  std::vector<std::string> ids;
  {
    Statement s(db_, select);
    if (absl::Status st = s.status(); !st.ok()) return st;
    s.Bind(1, value);
    int rc;
    while ((rc = s.Step()) == SQLITE_ROW) ids.push_back(s.Text(0));
    if (rc != SQLITE_DONE) return s.Error("step");
  }
  if (ids.empty()) return ids;
  if (absl::Status st = Exec("BEGIN"); !st.ok()) return st;
  for (const std::string& id : ids) {
    Statement s(db_, "DELETE FROM jobs WHERE id = ?");
    if (absl::Status st = s.status(); !st.ok()) {
      (void)Exec("ROLLBACK");
      return st;
    }
    s.BindText(1, id);
    if (absl::Status st = s.Done(); !st.ok()) {
      (void)Exec("ROLLBACK");
      return st;
    }
  }
  if (absl::Status st = Exec("COMMIT"); !st.ok()) return st;
  return ids;
}

absl::StatusOr<std::vector<std::string>> SqliteStore::DeleteJobsFinishedBefore(absl::Time cutoff) {
  absl::MutexLock lock(&mu_);
  return DeleteSelected("SELECT id FROM jobs WHERE finished_us IS NOT NULL AND finished_us < ?",
                        ToMicros(cutoff));
}

absl::StatusOr<std::vector<std::string>> SqliteStore::DeleteOldestFinishedJobs(int64_t n) {
  absl::MutexLock lock(&mu_);
  return DeleteSelected(
      "SELECT id FROM jobs WHERE finished_us IS NOT NULL ORDER BY finished_us, id LIMIT ?", n);
}

}  // namespace swarmplan::server
