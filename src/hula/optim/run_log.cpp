// SPDX-License-Identifier: MIT
#include "hula/optim/run_log.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>

namespace hula::optim {
namespace {
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) noexcept {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Shortest representation that reads back to the same double (to_chars).
void put(std::ostream& out, double v, bool json) {
  if (!std::isfinite(v)) {
    if (json) {
      out << "null";
    } else {
      out << (std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf"));
    }
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out.write(buf, r.ptr - buf);
}
}  // namespace

bool operator==(const GenerationLog& a, const GenerationLog& b) noexcept {
  return a.generation == b.generation && a.evaluations == b.evaluations && a.dimension == b.dimension &&
         a.objectives == b.objectives && same_bits(a.variables, b.variables) &&
         same_bits(a.objective_values, b.objective_values) && same_bits(a.violation, b.violation) &&
         same_bits(a.fitness, b.fitness) && a.failed == b.failed;
}

GenerationStatistics statistics(const GenerationLog& g) noexcept {
  GenerationStatistics s;
  s.generation = g.generation;
  s.best = std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  double sum2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (g.failed[i] != 0) continue;
    const double f = g.objective_values[i * g.objectives];
    ++n;
    sum += f;
    sum2 += f * f;
    if (g.violation[i] == 0.0) {
      ++s.feasible;
      if (std::isnan(s.best) || f < s.best) s.best = f;
    }
  }
  if (n > 0) {
    s.mean = sum / static_cast<double>(n);
    s.spread = std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - s.mean * s.mean));
  } else {
    s.mean = s.spread = std::numeric_limits<double>::quiet_NaN();
  }
  return s;
}

RunLogWriter::RunLogWriter(std::ostream& out, RunLogFormat format) : out_(&out), format_(format) {}

void RunLogWriter::append(const GenerationLog& g) {
  std::ostream& out = *out_;
  if (format_ == RunLogFormat::Csv) {
    if (count_ == 0) {
      out << "generation,evaluations,individual";
      for (std::size_t j = 0; j < g.dimension; ++j) out << ",x" << j;
      for (std::size_t j = 0; j < g.objectives; ++j) out << ",f" << j;
      out << ",violation,fitness,failed\n";
    }
    for (std::size_t i = 0; i < g.size(); ++i) {
      out << g.generation << ',' << g.evaluations << ',' << i;
      for (std::size_t j = 0; j < g.dimension; ++j) {
        out << ',';
        put(out, g.variables[i * g.dimension + j], false);
      }
      for (std::size_t j = 0; j < g.objectives; ++j) {
        out << ',';
        put(out, g.objective_values[i * g.objectives + j], false);
      }
      out << ',';
      put(out, g.violation[i], false);
      out << ',';
      put(out, g.fitness[i], false);
      out << ',' << static_cast<int>(g.failed[i]) << '\n';
    }
  } else {
    out << (count_ == 0 ? "{\"generations\":[" : ",") << "{\"generation\":" << g.generation
        << ",\"evaluations\":" << g.evaluations << ",\"individuals\":[";
    for (std::size_t i = 0; i < g.size(); ++i) {
      out << (i ? "," : "") << "{\"variables\":[";
      for (std::size_t j = 0; j < g.dimension; ++j) {
        if (j) out << ',';
        put(out, g.variables[i * g.dimension + j], true);
      }
      out << "],\"objectives\":[";
      for (std::size_t j = 0; j < g.objectives; ++j) {
        if (j) out << ',';
        put(out, g.objective_values[i * g.objectives + j], true);
      }
      out << "],\"violation\":";
      put(out, g.violation[i], true);
      out << ",\"fitness\":";
      put(out, g.fitness[i], true);
      out << ",\"failed\":" << (g.failed[i] ? "true" : "false") << '}';
    }
    out << "]}";
  }
  ++count_;
}

void RunLogWriter::finish() {
  if (format_ == RunLogFormat::Json) *out_ << (count_ == 0 ? "{\"generations\":[" : "") << "]}\n";
}

void RunLog::write_csv(std::ostream& out) const {
  RunLogWriter writer(out, RunLogFormat::Csv);
  for (const auto& g : generations_) writer.append(g);
  writer.finish();
}

void RunLog::write_json(std::ostream& out) const {
  RunLogWriter writer(out, RunLogFormat::Json);
  for (const auto& g : generations_) writer.append(g);
  writer.finish();
}

}  // namespace hula::optim
