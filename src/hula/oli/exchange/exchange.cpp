// SPDX-License-Identifier: MIT
// The caller's side of the exchange: format names, the request/answer files in
// a private temporary directory, and the translation of how the helper ended
// into an answer or a hula::Error naming the file.
#include "hula/oli/exchange/exchange.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/iges_counts.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/owned_files.hpp"
#include "hula/oli/exchange/detail/helper_process.hpp"
#include "hula/oli/exchange/detail/protocol.hpp"

namespace hula::oli {
namespace {

namespace fs = std::filesystem;

// A directory private to one exchange, removed with its contents.
class ScratchDir {
 public:
  // `hula-exchange-<pid>-XXXXXX`: the folders of exchanges whose process was killed (its pid is gone) are
  // removed by the next one.
  ScratchDir() {
    const fs::path temp = fs::temp_directory_path();
    io::remove_orphaned(temp, kPrefix);
    std::string tmpl = (temp / (io::owned_name(kPrefix) + "-XXXXXX")).string();
    if (::mkdtemp(tmpl.data()) == nullptr)
      throw Error(Errc::IoError, std::string("cannot create a temporary directory: ") + std::strerror(errno),
                  {.field = "path"});
    path_ = tmpl;
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  static constexpr std::string_view kPrefix = "hula-exchange-";
  fs::path path_;
};

// A short human rendering of a limit in seconds ("0.3", "60").
std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", seconds);
  return buffer;
}

std::string signal_text(int signal) {
  const char* name = sigabbrev_np(signal);
  return std::to_string(signal) + (name ? std::string(" (SIG") + name + ")" : std::string());
}

// Runs the helper on `request` and returns its "ok" member, or throws what it reported or how it died.
io::Json exchange(const detail::Request& request, const fs::path& file, std::string_view what,
                  const ExchangeOptions& options, const ScratchDir& scratch) {
  options.validate();
  const fs::path helper = options.helper.empty() ? default_exchange_helper() : options.helper;
  const fs::path request_path = scratch.path() / "request.json";
  const fs::path answer_path = scratch.path() / "answer.json";
  io::write_file_atomically(request_path, detail::request_to_json(request).dump());
  const auto outcome = detail::run_helper(helper, {request_path.string(), answer_path.string()}, options.time_limit,
                                          options.memory_limit, scratch.path() / "helper.log");
  const std::string subject = std::string(what) + " '" + file.string() + "'";
  const ErrorWhere where{.field = "path"};
  switch (outcome.kind) {
    case detail::HelperOutcome::Kind::TimedOut:
      throw Error(Errc::HelperFailure,
                  subject + ": the exchange helper did not finish within " + seconds_text(options.time_limit) +
                      " s and was killed",
                  where);
    case detail::HelperOutcome::Kind::Signalled:
      throw Error(
          Errc::HelperFailure,
          subject + ": the exchange helper (Open CASCADE) crashed with signal " + signal_text(outcome.status) +
              (outcome.status == SIGKILL || outcome.status == SIGSEGV
                   ? " (a reader fault or the memory limit of " + std::to_string(options.memory_limit >> 20) + " MiB)"
                   : std::string()),
          where);
    case detail::HelperOutcome::Kind::Exited:
      break;
  }
  if (outcome.status != 0 || !fs::exists(answer_path)) {
    std::string log = outcome.log;
    while (!log.empty() && std::isspace(static_cast<unsigned char>(log.back()))) log.pop_back();
    const bool out_of_memory = outcome.status == detail::kHelperOutOfMemoryStatus ||
                               log.find("std::bad_alloc") != std::string::npos ||
                               log.find("Standard_OutOfMemory") != std::string::npos;
    if (out_of_memory)
      throw ExchangeOutOfMemory(subject + ": the exchange helper ran out of memory (its limit is " +
                                std::to_string(options.memory_limit >> 20) + " MiB)");
    throw Error(Errc::HelperFailure,
                subject + ": the exchange helper '" + helper.string() + "' exited with status " +
                    std::to_string(outcome.status) + " without answering" +
                    (log.empty() ? std::string() : ": " + log.substr(log.size() > 400 ? log.size() - 400 : 0)),
                where);
  }
  io::Json answer;
  try {
    answer = io::json::parse_json_text(io::read_text_file(answer_path), "exchange helper answer");
  } catch (const Error& e) {
    throw Error(Errc::HelperFailure, subject + ": " + e.message(), where);
  }
  return detail::answer_ok(answer);
}

}  // namespace

std::string_view exchange_format_name(ExchangeFormat format) noexcept {
  switch (format) {
    case ExchangeFormat::StepAp214:
      return "step-ap214";
    case ExchangeFormat::StepAp242:
      return "step-ap242";
    case ExchangeFormat::Iges:
      return "iges";
  }
  return "unknown";
}

ExchangeFormat exchange_format_from_name(std::string_view name) {
  if (name == "step" || name == "step-ap214") return ExchangeFormat::StepAp214;
  if (name == "step-ap242") return ExchangeFormat::StepAp242;
  if (name == "iges") return ExchangeFormat::Iges;
  throw Error(Errc::InvalidArgument,
              "unknown exchange format '" + std::string(name) + "' (step | step-ap214 | step-ap242 | iges)",
              {.field = "format"});
}

ExchangeFormat exchange_format_for_path(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".step" || ext == ".stp") return ExchangeFormat::StepAp214;
  if (ext == ".iges" || ext == ".igs") return ExchangeFormat::Iges;
  throw Error(Errc::InvalidArgument,
              "cannot tell the format of '" + path.string() + "' from its extension (.step, .stp, .iges, .igs)",
              {.field = "path"});
}

ExportCurve export_curve(std::string name, const curve::Curve& curve) {
  return {std::move(name), curve.nurbs(), curve.approximation_deviation()};
}

void ExchangeOptions::validate() const {
  if (!(time_limit > 0.0) || !std::isfinite(time_limit))
    throw Error(Errc::InvalidOption, "time_limit = " + format_number(time_limit) + " must be a finite number > 0",
                {.field = "time_limit"});
  if (memory_limit < (std::size_t{256} << 20))
    throw Error(Errc::InvalidOption,
                "memory_limit = " + std::to_string(memory_limit) + " bytes is below 256 MiB (Open CASCADE needs more)",
                {.field = "memory_limit"});
}

std::filesystem::path default_exchange_helper() {
  if (const char* env = std::getenv("HULA_EXCHANGE_HELPER"); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  // Beside the binary this code was loaded from: the Python extension module of an installed wheel
  // (which ships the helper in its package directory), or a shared library installed beside it.
  Dl_info image{};
  if (dladdr(reinterpret_cast<const void*>(&default_exchange_helper), &image) != 0 && image.dli_fname != nullptr &&
      *image.dli_fname == '/') {
    const auto sibling = fs::path(image.dli_fname).parent_path() / "hula-exchange";
    if (fs::exists(sibling, ec)) return sibling;
  }
  const auto self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto sibling = self.parent_path() / "hula-exchange";
    if (fs::exists(sibling, ec)) return sibling;
  }
  return HULA_EXCHANGE_BUILD_HELPER;
}

ExportReport export_curves(const std::filesystem::path& path, std::span<const ExportCurve> curves,
                           ExchangeFormat format, const ExchangeOptions& options) {
  if (curves.empty())
    throw Error(Errc::InvalidArgument, "nothing to export to '" + path.string() + "': no curves", {.field = "curves"});
  ExportReport report{io::is_std_stream(path) ? path : fs::absolute(path), format, curves.size(), 0.0};
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const double d = curves[i].deviation;
    if (!std::isfinite(d) || d < 0.0)
      throw Error(Errc::InvalidArgument,
                  "curves[" + std::to_string(i) + "].deviation = " + format_number(d) + " must be finite and ≥ 0",
                  {.field = "curves", .index = i});
    report.max_deviation = std::max(report.max_deviation, d);
  }
  // The output-path policy is checked here, before the helper starts (which checks it again when it
  // writes): a link, FIFO, device or directory at `path` is refused by name.
  io::check_output_path(path, "path");
  ScratchDir scratch;
  // `-`: the helper writes into the scratch directory and the file goes to standard output from here.
  const bool to_stdout = io::is_std_stream(path);
  const fs::path target =
      to_stdout ? scratch.path() / (format == ExchangeFormat::Iges ? "out.igs" : "out.step") : report.path;
  const detail::ExportRequest request{format, target, {curves.begin(), curves.end()}};
  (void)exchange(request, path, "exporting to", options, scratch);
  if (to_stdout) io::write_stdout(io::read_text_file(target, std::numeric_limits<std::size_t>::max()));
  return report;
}

ImportReport import_curves(const std::filesystem::path& path, const ExchangeOptions& options) {
  // Refuse an unknown extension, and an IGES file whose counts exceed its data, before starting a process.
  if (exchange_format_for_path(path) == ExchangeFormat::Iges) io::check_iges_file_counts(path);
  const detail::ImportRequest request{fs::absolute(path)};
  const ScratchDir scratch;
  return detail::import_answer_from_json(exchange(request, path, "importing", options, scratch));
}

ImportReport import_curves_from_stdin(ExchangeFormat format, const ExchangeOptions& options) {
  const fs::path stdin_path("-");
  const std::string bytes = io::read_text_file(stdin_path, io::kMaxGeometryInputBytes);
  const ScratchDir scratch;
  // The helper reads files by their extension: the copy is named for the format given.
  const fs::path copy = scratch.path() / (format == ExchangeFormat::Iges ? "stdin.igs" : "stdin.step");
  if (format == ExchangeFormat::Iges) {
    std::istringstream in(bytes);
    io::check_iges_counts(in, "-");
  }
  io::write_file_atomically(copy, bytes);
  const detail::ImportRequest request{copy};
  return detail::import_answer_from_json(exchange(request, stdin_path, "importing", options, scratch));
}

}  // namespace hula::oli
