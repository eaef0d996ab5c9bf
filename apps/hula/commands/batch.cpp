// SPDX-License-Identifier: MIT
// `hula batch CAMPAIGN.json`: many study runs (study files, or seeds and
// settings of one study: a sweep, thesis 7.4 and app. 6) as one campaign
// (docs/cli.md "hula batch", docs/formats.md "Campaign files").
//
// Each item is run as a child process `hula <study kind> <study file>` with
// the item's seed and settings merged into a copy of the study file (written
// beside the original so its relative paths keep their meaning, removed
// afterwards), so a crashing item cannot take the campaign down and its
// output is exactly that of the study command. Items are handed out
// dynamically: a free slot takes the next item. Without MPI the slots are
// --jobs child processes of this process; under mpirun (HULA_MPI builds) every
// rank is one slot and rank 0 also hands out the items (workers send a result
// and get the next item's index back). Rank 0 (or the only process) writes the
// results file atomically after every finished item, so an interrupted
// campaign resumes where it stopped: items already in the results file are
// skipped; an item's "finished" line is printed once its record is in the
// file. On a terminal a progress line below those lines counts the items
// finished, ok, failed and running (study_common.hpp TerminalProgress). A failed item is recorded with its exit code
// and error and the rest go on; the exit code is 0 only when every item succeeded. The children die with the campaign
// (PR_SET_PDEATHSIG), and what a killed campaign left (its study copies, its scratch folder) is removed by the next
// one. The campaign and results files are io/campaign_file.hpp's; this file runs the items.
#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/campaign_file.hpp"
#include "hula/io/owned_files.hpp"
#include "hula/oli/process_ranks.hpp"

namespace hula::cli {

namespace {

namespace fs = std::filesystem;

struct BatchArgs {
  std::string campaign;
  std::optional<std::string> results;
  std::size_t jobs = 1;
};

// The names of what a campaign's process owns: `.hula-batch-<pid>-<item>.json` study copies beside the
// study files and the `hula-batch-<pid>` scratch folder in the temporary directory (io::owned_name).
constexpr std::string_view kStudyCopyPrefix = ".hula-batch-";
constexpr std::string_view kScratchPrefix = "hula-batch-";

// A child process running one item, its output going to two temporary files.
struct Running {
  std::size_t item = 0;
  pid_t pid = -1;
  fs::path study_copy, out, err;
  std::chrono::steady_clock::time_point start;
};

std::string self_exe() { return fs::read_symlink("/proc/self/exe").string(); }

Running start_item(const std::vector<io::CampaignItem>& items, std::size_t index, const fs::path& scratch) {
  const io::CampaignItem& item = items[index];
  const Json study = io::campaign_item_study(item);
  const std::string tag = io::owned_name("") + "-" + std::to_string(index);
  Running r;
  r.item = index;
  r.study_copy = item.study.parent_path() / (io::owned_name(kStudyCopyPrefix) + "-" + std::to_string(index) + ".json");
  r.out = scratch / (tag + ".out");
  r.err = scratch / (tag + ".err");
  io::write_file_atomically(r.study_copy, study.dump());
  const std::string exe = self_exe();
  const std::string kind = study.at("study").get_ref<const std::string&>();
  r.start = std::chrono::steady_clock::now();
  const pid_t parent = ::getpid();
  r.pid = ::fork();
  if (r.pid < 0) throw Error(Errc::IoError, "fork failed for item " + item.id, {.field = "jobs"});
  if (r.pid == 0) {
    // The item dies with the campaign: a killed campaign leaves no study running on (it is rerun on resume).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int out = ::open(r.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(r.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(127);
    ::dup2(out, 1);
    ::dup2(err, 2);
    // The launcher's environment must not make the child think it is a rank of the campaign's job (main.cpp
    // refuses a command that does not use MPI under a launcher).
    for (const char* v :
         {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
      ::unsetenv(v);
    ::execl(exe.c_str(), exe.c_str(), kind.c_str(), r.study_copy.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return r;
}

// The result record of a finished child.
Json finish_item(const std::vector<io::CampaignItem>& items, const Running& r, int status, int rank) {
  const io::CampaignItem& item = items[r.item];
  std::error_code ec;
  fs::remove(r.study_copy, ec);
  const auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  const std::string out = slurp(r.out), err = slurp(r.err);
  fs::remove(r.out, ec);
  fs::remove(r.err, ec);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return io::campaign_item_record(
      item, rank, std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count(), code, out, err);
}

// The campaign's bookkeeping on the process that writes the results.
class Results {
 public:
  Results(fs::path path, const std::vector<io::CampaignItem>& items, std::string campaign, TerminalProgress& terminal)
      : path_(std::move(path)), items_(items), campaign_(std::move(campaign)), terminal_(&terminal) {
    done_ = io::read_campaign_results(path_);
  }
  [[nodiscard]] bool done(const std::string& id) const { return done_.contains(id); }
  [[nodiscard]] std::size_t skipped() const { return skipped_; }
  void skip() { ++skipped_; }
  void record(const Json& j) {
    done_[j["id"].get_ref<const std::string&>()] = j;
    if (j["status"] != "ok") ++failed_;
    ++finished_;
    write();  // before the line: a kill right after "finished" must not lose the item's record
    terminal_->print(Json{
        {"finished", finished_},
        {"id", j["id"]},
        {"status", j["status"]},
        {"rank", j["rank"]},
        {"seconds",
         j["seconds"]}}.dump());
  }
  void write() const { io::write_file_atomically(path_, io::campaign_results_text(campaign_, items_, done_)); }
  [[nodiscard]] Json summary(double seconds, int ranks) const {
    std::size_t ok = 0;
    for (const auto& [id, j] : done_) ok += j["status"] == "ok" ? 1 : 0;
    return Json{{"items", items_.size()},
                {"ok", ok},
                {"failed", items_.size() - ok},
                {"skipped", skipped_},
                {"ran", finished_},
                {"seconds", seconds},
                {"ranks", ranks},
                {"results", path_.string()}};
  }
  [[nodiscard]] std::size_t failed() const { return failed_; }
  [[nodiscard]] std::size_t finished() const { return finished_; }

 private:
  fs::path path_;
  const std::vector<io::CampaignItem>& items_;
  std::string campaign_;
  std::map<std::string, Json> done_;
  std::size_t finished_ = 0, failed_ = 0, skipped_ = 0;
  TerminalProgress* terminal_;
};

// The terminal's progress line of a campaign: "finished 3 of 8  ok 2  failed 1  running 2  seconds 12.4"
// (of the items this run makes; skipped ones are not counted).
std::string campaign_line(const Results& results, std::size_t to_run, std::size_t running,
                          std::chrono::steady_clock::time_point start) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f", seconds);
  return "finished " + std::to_string(results.finished()) + " of " + std::to_string(to_run) + "  ok " +
         std::to_string(results.finished() - results.failed()) + "  failed " + std::to_string(results.failed()) +
         "  running " + std::to_string(running) + "  seconds " + elapsed;
}

// Waits a little for any of `running` to end; returns its index in `running` and status, if one did.
std::optional<std::pair<std::size_t, int>> reap(const std::vector<Running>& running) {
  for (std::size_t i = 0; i < running.size(); ++i) {
    int status = 0;
    if (::waitpid(running[i].pid, &status, WNOHANG) == running[i].pid) return std::pair{i, status};
  }
  return std::nullopt;
}

}  // namespace

int run_batch(const BatchArgs& a) {
  const fs::path campaign = a.campaign;
  const std::vector<io::CampaignItem> items = io::read_campaign_file(campaign);
  const fs::path results_path =
      a.results ? fs::path(*a.results) : fs::path(campaign).replace_extension(".results.json");
  if (a.jobs == 0) throw Error(Errc::InvalidOption, "jobs = 0 must be >= 1", {.field = "jobs"});
  io::check_output_path(results_path, a.results ? "--results" : "path");  // before any item runs
  // What killed campaigns left: their scratch folders, and their study copies beside this one's studies.
  const fs::path temp = fs::temp_directory_path();
  io::remove_orphaned(temp, kScratchPrefix);
  std::set<fs::path> study_dirs;
  for (const io::CampaignItem& item : items) study_dirs.insert(item.study.parent_path());
  // A copy is written atomically: a kill during that write leaves its temporary, `.` + the copy's name +
  // `.tmp-<pid>-XXXXXX`, which carries the same owner's pid.
  for (const fs::path& dir : study_dirs) {
    io::remove_orphaned(dir.empty() ? fs::path(".") : dir, kStudyCopyPrefix);
    io::remove_orphaned(dir.empty() ? fs::path(".") : dir, "." + std::string(kStudyCopyPrefix));
  }
  const fs::path scratch = temp / io::owned_name(kScratchPrefix);
  fs::create_directories(scratch);
  const auto start = std::chrono::steady_clock::now();
  // Under mpirun every rank is a slot (oli::CampaignRanks); otherwise this process is the only rank.
  std::optional<oli::CampaignRanks> job;
  job.emplace();
  const int rank = job->rank(), ranks = job->ranks();
  if (rank != 0) {
    // A worker: ask for an item, run it, send its record with the next request.
    std::string record;
    while (const std::optional<std::size_t> index = job->next_item(record)) {
      try {
        const Running r = start_item(items, *index, scratch);
        int status = 0;
        ::waitpid(r.pid, &status, 0);
        record = finish_item(items, r, status, rank).dump();
      } catch (const Error& e) {
        record = io::campaign_failed_record(items[*index], e, rank, kExitInvalidInput).dump();
      }
    }
    job.reset();  // leaves the MPI job
    std::error_code ec;
    fs::remove_all(scratch, ec);
    return kExitOk;
  }
  TerminalProgress terminal;
  Results results(results_path, items, campaign.string(), terminal);
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (results.done(items[i].id))
      results.skip();
    else
      todo.push_back(i);
  }
  std::size_t next = 0;
  std::vector<Running> running;
  const std::size_t local_slots = a.jobs;
  int remote_active = ranks - 1;   // workers still to be told to stop
  std::size_t remote_running = 0;  // items handed to workers whose record has not come back
  while (next < todo.size() || !running.empty() || remote_active > 0) {
    bool busy = false;
    while (running.size() < local_slots && next < todo.size()) {
      const std::size_t index = todo[next++];
      try {
        running.push_back(start_item(items, index, scratch));
      } catch (const Error& e) {
        results.record(io::campaign_failed_record(items[index], e, rank, kExitInvalidInput));
      }
      busy = true;
    }
    if (const auto ended = reap(running)) {
      results.record(finish_item(items, running[ended->first], ended->second, rank));
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(ended->first));
      busy = true;
    }
    if (remote_active > 0) {
      if (const std::optional<oli::CampaignRanks::Request> request = job->poll()) {
        if (!request->record.empty()) {
          results.record(Json::parse(request->record));
          --remote_running;
        }
        std::optional<std::size_t> index;
        if (next < todo.size()) {
          index = todo[next++];
          ++remote_running;
        } else {
          --remote_active;
        }
        job->reply(request->worker, index);
        busy = true;
      }
    }
    if (terminal.active()) terminal.show(campaign_line(results, todo.size(), running.size() + remote_running, start));
    if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (terminal.active()) terminal.show(campaign_line(results, todo.size(), 0, start));
  terminal.finish();
  results.write();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  job.reset();  // leaves the MPI job
  std::error_code ec;
  fs::remove_all(scratch, ec);
  print_json(results.summary(seconds, ranks));
  return results.failed() == 0 ? kExitOk : kExitInvalidInput;
}

Command add_batch(CLI::App& app) {
  auto a = std::make_shared<BatchArgs>();
  CLI::App* sub = app.add_subcommand(
      "batch", "Run a campaign of study runs (files, seeds, settings); resumable; one slot per MPI rank under mpirun");
  sub->add_option("campaign", a->campaign, "Campaign file (JSON, docs/formats.md \"Campaign files\")")->required();
  sub->add_option("--results", a->results,
                  "Results file, written atomically after each item (default CAMPAIGN.results.json)");
  sub->add_option("--jobs", a->jobs, "Items run at once by this process (default 1)");
  return {sub, [a] { return run_batch(*a); }};
}

}  // namespace hula::cli
