// SPDX-License-Identifier: MIT
// Islands over MPI; see islands_mpi.hpp. Messages, all on MPI_COMM_WORLD:
//   kTagMigrants  [epoch, count, dimension, values, (variables, values) x count]
//   kTagDone      [0]: the sender exchanges no more (it finished)
//   kTagFailed    [0]: the sender's island failed: the run stops
//   kTagReport    the serialised IslandReport (or error), to rank 0 at the end
// Sends are non-blocking (MPI_Isend) with their buffers kept until complete,
// so two neighbours sending to each other never wait on one another. Messages
// from one sender arrive in order (MPI's non-overtaking rule), so after its
// Done no message of that sender is in flight: finishing ranks drain their
// in-neighbours until Done, which also lets every send complete before
// MPI_Finalize.
#include "hula/optim/islands_mpi.hpp"

#include <mpi.h>

#include <chrono>
#include <cstring>
#include <list>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::optim {

namespace {

constexpr int kTagMigrants = 1;
constexpr int kTagDone = 2;
constexpr int kTagFailed = 3;
constexpr int kTagReport = 4;

class PeerFailedMpi : public Error {
 public:
  PeerFailedMpi() : Error(Errc::NumericalFailure, "another island failed: the run stopped", {.field = "islands"}) {}
};

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw Error(Errc::IoError, std::string("MPI call failed: ") + what, {.field = "mpi"});
}

// MPI_Init on construction, MPI_Finalize on destruction (once per process).
class MpiSession {
 public:
  MpiSession() { check(MPI_Init(nullptr, nullptr), "MPI_Init"); }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

// Byte buffer writer / reader for reports.
struct Writer {
  std::vector<char> bytes;
  template <class T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void put_doubles(const std::vector<double>& v) {
    put<std::uint64_t>(v.size());
    for (const double x : v) put(x);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
  void put_solution(const Solution& s) {
    put_doubles(s.variables);
    put_doubles(s.objectives);
    put(s.violation);
  }
};

struct Reader {
  const std::vector<char>& bytes;
  std::size_t at = 0;
  [[noreturn]] static void truncated(const std::string& why) {
    throw Error(Errc::IoError, "truncated island report: " + why, {.field = "mpi"});
  }
  template <class T>
  T get() {
    if (sizeof(T) > bytes.size() - at) truncated("it ends at byte " + std::to_string(bytes.size()));
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  // A count of elements of at least `each` bytes, bounded by the bytes that remain (before anything is allocated).
  std::size_t count(std::size_t each) {
    const auto n = get<std::uint64_t>();
    if (n > (bytes.size() - at) / each)
      truncated("it states " + std::to_string(n) + " elements of at least " + std::to_string(each) + " bytes at byte " +
                std::to_string(at) + ", but " + std::to_string(bytes.size() - at) + " bytes remain");
    return static_cast<std::size_t>(n);
  }
  std::vector<double> get_doubles() {
    std::vector<double> v(count(sizeof(double)));
    for (double& x : v) x = get<double>();
    return v;
  }
  std::string get_string() {
    const std::size_t n = count(1);
    std::string s(bytes.data() + at, n);
    at += n;
    return s;
  }
  Solution get_solution() {
    Solution s;
    s.variables = get_doubles();
    s.objectives = get_doubles();
    s.violation = get<double>();
    return s;
  }
};

}  // namespace

std::vector<char> write_island_report(const IslandReport& r) {
  Writer w;
  w.put<std::uint8_t>(0);  // 0 = a report, 1 = an error
  w.put<std::uint64_t>(r.island);
  w.put<std::uint64_t>(r.seed);
  w.put_solution(r.best);
  w.put<std::uint64_t>(r.population.size());
  for (const Solution& s : r.population) w.put_solution(s);
  w.put<std::uint64_t>(r.archive.size());
  for (const Solution& s : r.archive) w.put_solution(s);
  w.put<std::uint8_t>(static_cast<std::uint8_t>(r.report.termination));
  w.put_string(r.report.message);
  w.put<std::uint64_t>(r.report.generations);
  w.put<std::uint64_t>(r.report.evaluations);
  w.put<std::uint64_t>(r.report.failed_evaluations);
  w.put(r.report.seconds);
  w.put<std::uint64_t>(r.sent);
  w.put<std::uint64_t>(r.received);
  w.put<std::uint64_t>(r.accepted);
  w.put<std::uint64_t>(r.migrations.size());
  for (const MigrationEvent& e : r.migrations) {
    w.put<std::uint64_t>(e.generation);
    w.put<std::uint64_t>(e.from);
    w.put<std::uint64_t>(e.to);
    w.put<std::uint64_t>(e.received);
    w.put<std::uint64_t>(e.accepted);
  }
  return std::move(w.bytes);
}

namespace {

std::vector<char> serialise_error(const Error& e, bool peer) {
  Writer w;
  w.put<std::uint8_t>(1);
  w.put<std::uint8_t>(peer ? 1 : 0);
  w.put<std::uint8_t>(static_cast<std::uint8_t>(e.code()));
  w.put_string(e.message());
  w.put_string(e.where().field);
  return std::move(w.bytes);
}

}  // namespace

IslandReport read_island_report(const std::vector<char>& bytes) {
  Reader r{bytes};
  (void)r.get<std::uint8_t>();
  IslandReport out;
  out.island = r.get<std::uint64_t>();
  out.seed = r.get<std::uint64_t>();
  out.best = r.get_solution();
  // A solution is at least its two counts and its violation; a migration event five numbers.
  constexpr std::size_t kSolutionBytes = 3 * 8, kMigrationBytes = 5 * 8;
  out.population.resize(r.count(kSolutionBytes));
  for (Solution& s : out.population) s = r.get_solution();
  out.archive.resize(r.count(kSolutionBytes));
  for (Solution& s : out.archive) s = r.get_solution();
  out.report.termination = static_cast<Termination>(r.get<std::uint8_t>());
  out.report.message = r.get_string();
  out.report.generations = r.get<std::uint64_t>();
  out.report.evaluations = r.get<std::uint64_t>();
  out.report.failed_evaluations = r.get<std::uint64_t>();
  out.report.seconds = r.get<double>();
  out.sent = r.get<std::uint64_t>();
  out.received = r.get<std::uint64_t>();
  out.accepted = r.get<std::uint64_t>();
  out.migrations.resize(r.count(kMigrationBytes));
  for (MigrationEvent& e : out.migrations) {
    e.generation = r.get<std::uint64_t>();
    e.from = r.get<std::uint64_t>();
    e.to = r.get<std::uint64_t>();
    e.received = r.get<std::uint64_t>();
    e.accepted = r.get<std::uint64_t>();
  }
  return out;
}

namespace {

// The exchange of one rank.
class MpiExchange final : public Exchange {
 public:
  MpiExchange(int ranks, bool asynchronous, std::vector<std::size_t> to, std::vector<std::size_t> from)
      : done_(static_cast<std::size_t>(ranks), false),
        asynchronous_(asynchronous),
        to_(std::move(to)),
        from_(std::move(from)) {}

  std::vector<std::vector<Migrant>> exchange(std::size_t /*island*/, std::size_t epoch,
                                             const std::vector<std::size_t>& to, const std::vector<std::size_t>& from,
                                             const std::vector<Migrant>& outgoing) override {
    std::vector<double> message{static_cast<double>(epoch), static_cast<double>(outgoing.size()), 0.0, 0.0};
    if (!outgoing.empty()) {
      message[2] = static_cast<double>(outgoing.front().variables.size());
      message[3] = static_cast<double>(outgoing.front().values.size());
    }
    for (const Migrant& m : outgoing) {
      message.insert(message.end(), m.variables.begin(), m.variables.end());
      message.insert(message.end(), m.values.begin(), m.values.end());
    }
    for (const std::size_t t : to) send(t, kTagMigrants, message);
    std::vector<std::vector<Migrant>> incoming(from.size());
    for (std::size_t s = 0; s < from.size(); ++s) {
      const std::size_t f = from[s];
      while (!done_[f]) {
        MPI_Status status;
        int flag = 1;
        if (asynchronous_)
          check(MPI_Iprobe(static_cast<int>(f), MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
        else
          check(MPI_Probe(static_cast<int>(f), MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
        if (flag == 0) break;  // asynchronous: nothing more has arrived
        const std::vector<double> body = receive(status);
        if (status.MPI_TAG == kTagFailed) throw PeerFailedMpi();
        if (status.MPI_TAG == kTagDone) {
          done_[f] = true;
          break;
        }
        const auto e = static_cast<std::size_t>(body[0]);
        if (asynchronous_) {
          incoming[s] = parse(body);  // the newest so far; keep probing for newer ones
          continue;
        }
        if (e == epoch) {
          incoming[s] = parse(body);
          break;
        }
        // e < epoch cannot happen in synchronous mode (each epoch's message is taken at its epoch).
      }
    }
    reap();
    return incoming;
  }

  void finish(std::size_t /*island*/, bool failed) override {
    for (const std::size_t t : to_) send(t, failed ? kTagFailed : kTagDone, {0.0});
  }

  // After finish: take every in-neighbour's remaining messages up to its Done or Failed, then wait for
  // every send of ours to complete (our out-neighbours drain us likewise).
  void drain() {
    for (const std::size_t f : from_) {
      while (!done_[f]) {
        MPI_Status status;
        check(MPI_Probe(static_cast<int>(f), MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
        (void)receive(status);
        if (status.MPI_TAG == kTagDone || status.MPI_TAG == kTagFailed) done_[f] = true;
      }
    }
    for (Pending& p : pending_) check(MPI_Wait(&p.request, MPI_STATUS_IGNORE), "MPI_Wait");
    pending_.clear();
  }

 private:
  struct Pending {
    std::vector<double> buffer;
    MPI_Request request = MPI_REQUEST_NULL;
  };

  void send(std::size_t to, int tag, std::vector<double> body) {
    pending_.push_back(Pending{std::move(body), MPI_REQUEST_NULL});
    Pending& p = pending_.back();
    check(MPI_Isend(p.buffer.data(), static_cast<int>(p.buffer.size()), MPI_DOUBLE, static_cast<int>(to), tag,
                    MPI_COMM_WORLD, &p.request),
          "MPI_Isend");
  }

  static std::vector<double> receive(const MPI_Status& status) {
    int count = 0;
    check(MPI_Get_count(&status, MPI_DOUBLE, &count), "MPI_Get_count");
    std::vector<double> body(static_cast<std::size_t>(count));
    check(
        MPI_Recv(body.data(), count, MPI_DOUBLE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
    return body;
  }

  static std::vector<Migrant> parse(const std::vector<double>& body) {
    const auto n = static_cast<std::size_t>(body[1]);
    const auto d = static_cast<std::size_t>(body[2]);
    const auto k = static_cast<std::size_t>(body[3]);
    std::vector<Migrant> out(n);
    const double* p = body.data() + 4;
    for (Migrant& m : out) {
      m.variables.assign(p, p + d);
      m.values.assign(p + d, p + d + k);
      p += d + k;
    }
    return out;
  }

  // Frees the buffers of completed sends.
  void reap() {
    for (auto it = pending_.begin(); it != pending_.end();) {
      int flag = 0;
      check(MPI_Test(&it->request, &flag, MPI_STATUS_IGNORE), "MPI_Test");
      it = flag != 0 ? pending_.erase(it) : std::next(it);
    }
  }

  std::vector<bool> done_;
  bool asynchronous_;
  std::vector<std::size_t> to_, from_;
  std::list<Pending> pending_;
};

}  // namespace

std::optional<IslandsResult> solve_islands_mpi(const Problem& problem, const IslandAlgorithm& algorithm,
                                               IslandOptions options) {
  const MpiSession session;
  int rank = 0, size = 1;
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
  if (options.islands == 0) options.islands = static_cast<std::size_t>(size);
  if (options.islands != static_cast<std::size_t>(size)) {
    throw Error(Errc::InvalidOption,
                "islands = " + std::to_string(options.islands) + " but mpirun started " + std::to_string(size) +
                    " ranks: run one island per rank (mpirun -np K ... --islands K)",
                {.field = "islands"});
  }
  options.validate();
  problem.validate();
  const auto start = std::chrono::steady_clock::now();
  const auto me = static_cast<std::size_t>(rank);
  MpiExchange exchange(size, options.asynchronous, out_neighbours(options, me), in_neighbours(options, me));
  std::vector<char> mine;
  try {
    mine = write_island_report(run_island(problem, algorithm, options, me, exchange));
  } catch (const PeerFailedMpi& e) {
    mine = serialise_error(e, true);
  } catch (const Error& e) {
    mine = serialise_error(e, false);
  } catch (const std::exception& e) {
    mine = serialise_error(Error(Errc::NumericalFailure, e.what(), {.field = "islands"}), false);
  }
  exchange.drain();

  if (rank != 0) {
    check(MPI_Send(mine.data(), static_cast<int>(mine.size()), MPI_CHAR, 0, kTagReport, MPI_COMM_WORLD), "MPI_Send");
    return std::nullopt;
  }
  std::vector<std::vector<char>> all{std::move(mine)};
  for (int r = 1; r < size; ++r) {
    MPI_Status status;
    check(MPI_Probe(r, kTagReport, MPI_COMM_WORLD, &status), "MPI_Probe");
    int count = 0;
    check(MPI_Get_count(&status, MPI_CHAR, &count), "MPI_Get_count");
    std::vector<char> bytes(static_cast<std::size_t>(count));
    check(MPI_Recv(bytes.data(), count, MPI_CHAR, r, kTagReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    all.push_back(std::move(bytes));
  }
  // The failing island's own error first, then "another island failed".
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t r = 0; r < all.size(); ++r) {
      if (all[r].empty() || all[r][0] != 1) continue;
      Reader in{all[r]};
      (void)in.get<std::uint8_t>();
      const bool peer = in.get<std::uint8_t>() != 0;
      if (peer != (pass == 1)) continue;
      const auto code = static_cast<Errc>(in.get<std::uint8_t>());
      const std::string message = in.get_string();
      const std::string field = in.get_string();
      throw Error(code, "island " + std::to_string(r) + ": " + message, {.field = field});
    }
  }
  std::vector<IslandReport> reports;
  for (const std::vector<char>& bytes : all) reports.push_back(read_island_report(bytes));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return merge_islands(problem, std::move(reports), seconds);
}

}  // namespace hula::optim
