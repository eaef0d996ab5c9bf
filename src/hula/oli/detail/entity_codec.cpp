// SPDX-License-Identifier: MIT
// Entity states as JSON and as the store's bytes (entity_codec.hpp gives the layout).
#include "hula/oli/detail/entity_codec.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/run_report_json.hpp"

namespace hula::oli::detail {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the entity codec writes the host's doubles as little-endian");
constexpr char kMagic[4] = {'H', 'L', 'E', '2'};
constexpr char kMagicVersion1[4] = {'H', 'L', 'E', '1'};

[[noreturn]] void corrupt(const std::string& what) {
  throw Error(Errc::ParseError, "entity state: " + what, {.field = "state"});
}

Json points_to_json(const std::vector<Vec3>& points, int dimension) {
  Json out = Json::array();
  for (const Vec3& p : points) {
    Json q = Json::array({p.x, p.y});
    if (dimension == 3) q.push_back(p.z);
    out.push_back(std::move(q));
  }
  return out;
}

using Arrays = std::vector<std::vector<double>>;

// The numbers of one run log column block (entity_codec.hpp): per generation its generation, evaluations,
// dimension, objectives and individual count, then its variables, objectives, violations, fitnesses and
// failed flags (0 or 1).
std::vector<double> run_log_columns(const optim::RunLog& log) {
  std::size_t total = 0;
  for (const optim::GenerationLog& g : log.generations()) {
    const std::size_t n = g.size();
    if (g.variables.size() != n * g.dimension || g.objective_values.size() != n * g.objectives ||
        g.violation.size() != n || g.fitness.size() != n)
      throw Error(Errc::InvalidArgument,
                  "run log generation " + std::to_string(g.generation) + ": its columns disagree on its " +
                      std::to_string(n) + " individuals",
                  {.field = "log"});
    total += 5 + g.variables.size() + g.objective_values.size() + 3 * n;
  }
  std::vector<double> out;
  out.reserve(total);
  for (const optim::GenerationLog& g : log.generations()) {
    for (const std::size_t v : {g.generation, g.evaluations, g.dimension, g.objectives, g.size()})
      out.push_back(static_cast<double>(v));
    out.insert(out.end(), g.variables.begin(), g.variables.end());
    out.insert(out.end(), g.objective_values.begin(), g.objective_values.end());
    out.insert(out.end(), g.violation.begin(), g.violation.end());
    out.insert(out.end(), g.fitness.begin(), g.fitness.end());
    for (const std::uint8_t f : g.failed) out.push_back(f != 0 ? 1.0 : 0.0);
  }
  return out;
}

// run_log_columns read back; every count is checked against the numbers that remain.
optim::RunLog run_log_from_columns(const std::vector<double>& a) {
  optim::RunLog log;
  std::size_t at = 0;
  const auto count = [&]() -> std::size_t {
    if (at == a.size()) corrupt("run log truncated in a generation's header");
    const double v = a[at++];
    if (!(v >= 0.0 && v <= 9007199254740992.0 && v == std::floor(v)))
      corrupt("run log count " + format_number(v) + " is not a count");
    return static_cast<std::size_t>(v);
  };
  const auto column = [&](std::size_t n) {
    const auto first = a.begin() + static_cast<std::ptrdiff_t>(at);
    at += n;
    return std::vector<double>(first, first + static_cast<std::ptrdiff_t>(n));
  };
  while (at < a.size()) {
    optim::GenerationLog g;
    g.generation = count();
    g.evaluations = count();
    g.dimension = count();
    g.objectives = count();
    const std::size_t n = count();
    if (n != 0 && g.dimension + g.objectives + 3 > (a.size() - at) / n)
      corrupt("run log generation " + std::to_string(g.generation) + ": " + std::to_string(n) +
              " individuals exceed the numbers that remain");
    g.variables = column(n * g.dimension);
    g.objective_values = column(n * g.objectives);
    g.violation = column(n);
    g.fitness = column(n);
    g.failed.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double f = a[at++];
      if (f != 0.0 && f != 1.0) corrupt("run log failed flag " + format_number(f) + " is neither 0 nor 1");
      g.failed.push_back(f != 0.0 ? 1 : 0);
    }
    log.append(std::move(g));
  }
  return log;
}

// A study as JSON. With `arrays`, each run log goes there as one column block, referenced as
// {"$log": i} (the store's form); without, as run_log_to_json writes it.
Json study_to_json(const Study& study, Arrays* arrays) {
  Json runs = Json::array();
  for (const StudyRun& run : study.runs) {
    Json r = Json::object();
    r["seed"] = run.seed;
    r["result"] = run.result;
    if (!run.log) {
      r["log"] = Json::array();
    } else if (arrays != nullptr) {
      r["log"] = Json::object({{"$log", arrays->size()}});
      arrays->push_back(run_log_columns(*run.log));
    } else {
      r["log"] = io::run_log_to_json(*run.log);
    }
    Json curves = Json::array();
    for (Label l : run.result_curves) curves.push_back(l.value);
    r["result_curves"] = std::move(curves);
    runs.push_back(std::move(r));
  }
  Json out = Json::object();
  out["kind"] = "study";
  out["setup"] = study.setup;
  out["runs"] = std::move(runs);
  return out;
}

// A stored run log: [] (a study without generations), run_log_to_json's form, or, with `arrays` (the
// store), a reference {"$log": i} to its column block.
std::shared_ptr<const optim::RunLog> run_log_from(const Json& log, const Arrays* arrays) {
  if (log.is_array() && log.empty()) return nullptr;
  if (arrays != nullptr && log.is_object() && log.size() == 1 && log.contains("$log")) {
    const Json& i = log["$log"];
    if (!i.is_number_unsigned() || i.get<std::size_t>() >= arrays->size()) corrupt("run log reference out of range");
    return std::make_shared<const optim::RunLog>(run_log_from_columns((*arrays)[i.get<std::size_t>()]));
  }
  return std::make_shared<const optim::RunLog>(io::run_log_from_json(log));
}

Study study_from_json(const Json& json, const Arrays* arrays) {
  namespace j = io::json;
  const j::JsonPath root = j::root_path("");
  Study study;
  study.setup = j::require_member(json, root, "setup");
  if (!study.setup.is_object()) j::type_error(study.setup, root.member("setup"), "an object");
  const Json& runs = j::get_array(j::require_member(json, root, "runs"), root.member("runs"));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const j::JsonPath at = root.member("runs").element(i);
    StudyRun run;
    run.seed = static_cast<std::uint64_t>(
        j::get_integer(j::require_member(runs[i], at, "seed"), at.member("seed"), 0, INT64_MAX));
    run.result = j::require_member(runs[i], at, "result");
    run.log = run_log_from(j::require_member(runs[i], at, "log"), arrays);
    const Json& curves = j::get_array(j::require_member(runs[i], at, "result_curves"), at.member("result_curves"));
    for (std::size_t k = 0; k < curves.size(); ++k)
      run.result_curves.push_back(Label{
          static_cast<std::uint64_t>(j::get_integer(curves[k], at.member("result_curves").element(k), 1, INT64_MAX))});
    study.runs.push_back(std::move(run));
  }
  return study;
}

// --- packing of floating-point arrays -------------------------------------

bool all_floats(const Json& array) {
  if (array.empty()) return false;
  for (const Json& v : array)
    if (!v.is_number_float()) return false;
  return true;
}

// Columns when `array` is a non-empty array of equal-length (≥ 1) float arrays, else 0.
std::size_t point_columns(const Json& array) {
  if (array.empty() || !array[0].is_array()) return 0;
  const std::size_t k = array[0].size();
  if (k == 0) return 0;
  for (const Json& row : array)
    if (!row.is_array() || row.size() != k || !all_floats(row)) return 0;
  return k;
}

void pack(Json& value, std::vector<std::vector<double>>& arrays) {
  if (value.is_object()) {
    if (value.contains("$f64")) corrupt("the member name \"$f64\" is reserved");
    for (auto& [key, member] : value.items()) pack(member, arrays);
    return;
  }
  if (!value.is_array()) return;
  if (all_floats(value)) {
    std::vector<double> flat;
    flat.reserve(value.size());
    for (const Json& v : value) flat.push_back(v.get<double>());
    value = Json::object({{"$f64", arrays.size()}});
    arrays.push_back(std::move(flat));
    return;
  }
  if (const std::size_t k = point_columns(value); k != 0) {
    std::vector<double> flat;
    flat.reserve(value.size() * k);
    for (const Json& row : value)
      for (const Json& v : row) flat.push_back(v.get<double>());
    value = Json::object({{"$f64", arrays.size()}, {"$cols", k}});
    arrays.push_back(std::move(flat));
    return;
  }
  for (Json& element : value) pack(element, arrays);
}

void unpack(Json& value, const std::vector<std::vector<double>>& arrays) {
  if (value.is_object()) {
    if (const auto it = value.find("$f64"); it != value.end()) {
      if (!it->is_number_unsigned() || it->get<std::size_t>() >= arrays.size()) corrupt("array reference out of range");
      const std::vector<double>& flat = arrays[it->get<std::size_t>()];
      std::size_t cols = 0;
      if (const auto c = value.find("$cols"); c != value.end()) {
        if (!c->is_number_unsigned() || c->get<std::size_t>() == 0) corrupt("bad column count");
        cols = c->get<std::size_t>();
        if (flat.size() % cols != 0) corrupt("array size is not a multiple of its column count");
      }
      Json out = Json::array();
      if (cols == 0) {
        for (double v : flat) out.push_back(v);
      } else {
        for (std::size_t i = 0; i < flat.size(); i += cols) {
          Json row = Json::array();
          for (std::size_t k = 0; k < cols; ++k) row.push_back(flat[i + k]);
          out.push_back(std::move(row));
        }
      }
      value = std::move(out);
      return;
    }
    for (auto& [key, member] : value.items()) unpack(member, arrays);
    return;
  }
  if (value.is_array())
    for (Json& element : value) unpack(element, arrays);
}

void put_u32(std::string& out, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}
void put_u64(std::string& out, std::uint64_t v) {
  char b[8];
  std::memcpy(b, &v, 8);
  out.append(b, 8);
}

// A bounds-checked reader over the bytes.
struct Reader {
  std::string_view bytes;
  std::size_t at = 0;
  void need(std::size_t n) const {
    if (bytes.size() - at < n) corrupt("truncated (" + std::to_string(bytes.size()) + " bytes)");
  }
  std::uint32_t u32() {
    need(4);
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    at += 4;
    return v;
  }
  std::uint64_t u64() {
    need(8);
    std::uint64_t v = 0;
    std::memcpy(&v, bytes.data() + at, 8);
    at += 8;
    return v;
  }
};

}  // namespace

void validate_point_set(const PointSet& set) {
  if (set.dimension != 2 && set.dimension != 3)
    throw Error(Errc::InvalidArgument, "point set dimension " + std::to_string(set.dimension) + " must be 2 or 3",
                {.field = "dimension"});
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    const Vec3& p = set.points[i];
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(p[c]))
        throw Error(
            Errc::NonFiniteInput,
            "points[" + std::to_string(i) + "][" + std::to_string(c) + "] = " + format_number(p[c]) + " is not finite",
            {.field = "points", .index = i, .component = c});
    if (set.dimension == 2 && p.z != 0.0)
      throw Error(Errc::InvalidArgument,
                  "points[" + std::to_string(i) + "] has z = " + format_number(p.z) + " in a planar (2-D) point set",
                  {.field = "points", .index = i, .component = 2});
  }
}

namespace {

// The forms below with `arrays`: the store's skeleton, run logs as column blocks (study_to_json).
Json data_to_json(const EntityState& state, Arrays* arrays) {
  switch (state.kind) {
    case EntityKind::Curve:
      return io::curve_to_json(*state.curve);
    case EntityKind::PointSet: {
      Json out = Json::object();
      out["kind"] = "point-set";
      out["dimension"] = state.points->dimension;
      out["points"] = points_to_json(state.points->points, state.points->dimension);
      return out;
    }
    case EntityKind::Study:
      return study_to_json(*state.study, arrays);
  }
  return Json::object();
}

void data_from_json(EntityKind kind, const Json& data, EntityState& state, const Arrays* arrays) {
  namespace j = io::json;
  state.kind = kind;
  switch (kind) {
    case EntityKind::Curve:
      state.curve = std::make_shared<const curve::Curve>(io::curve_from_json(data));
      return;
    case EntityKind::PointSet: {
      PointSet set;
      const j::JsonPath root = j::root_path("");
      set.dimension =
          static_cast<int>(j::get_integer(j::require_member(data, root, "dimension"), root.member("dimension"), 2, 3));
      set.points = j::get_points(j::require_member(data, root, "points"), j::root_path("points")).points;
      validate_point_set(set);
      state.points = std::make_shared<const PointSet>(std::move(set));
      return;
    }
    case EntityKind::Study:
      state.study = std::make_shared<const Study>(study_from_json(data, arrays));
      return;
  }
}

Json state_to_json(const EntityState& state, Arrays* arrays) {
  Json out = Json::object();
  out["kind"] = entity_kind_name(state.kind);
  out["attributes"] = attributes_to_json(state.attributes);
  out["provenance"] = state.provenance ? provenance_to_json(*state.provenance) : Json(nullptr);
  out["constraints"] = constraints_to_json(state.constraints);
  out["data"] = data_to_json(state, arrays);
  return out;
}

StatePtr state_from_json(const Json& json, const Arrays* arrays) {
  namespace j = io::json;
  const j::JsonPath root = j::root_path("");
  auto state = std::make_shared<EntityState>();
  const std::string kind = j::get_string(j::require_member(json, root, "kind"), root.member("kind"));
  EntityKind k = EntityKind::Curve;
  if (kind == "curve")
    k = EntityKind::Curve;
  else if (kind == "point-set")
    k = EntityKind::PointSet;
  else if (kind == "study")
    k = EntityKind::Study;
  else
    corrupt("unknown entity kind \"" + kind + "\"");
  state->attributes = attributes_from_json(j::require_member(json, root, "attributes"));
  if (const Json* p = j::optional_member(json, "provenance")) state->provenance = provenance_from_json(*p);
  if (const Json* c = j::optional_member(json, "constraints")) state->constraints = constraints_from_json(*c);
  data_from_json(k, j::require_member(json, root, "data"), *state, arrays);
  return state;
}

}  // namespace

Json entity_data_to_json(const EntityState& state) { return data_to_json(state, nullptr); }

void entity_data_from_json(EntityKind kind, const Json& data, EntityState& state) {
  data_from_json(kind, data, state, nullptr);
}

Json entity_state_to_json(const EntityState& state) { return state_to_json(state, nullptr); }

StatePtr entity_state_from_json(const Json& json) { return state_from_json(json, nullptr); }

std::string encode_state(const EntityState& state) {
  Arrays arrays;
  Json skeleton = state_to_json(state, &arrays);
  pack(skeleton["data"], arrays);
  const std::string text = skeleton.dump();
  std::string out;
  std::size_t total = 12 + text.size();
  for (const auto& a : arrays) total += 8 + a.size() * sizeof(double);
  out.reserve(total);
  out.append(kMagic, 4);
  put_u32(out, static_cast<std::uint32_t>(text.size()));
  out += text;
  put_u32(out, static_cast<std::uint32_t>(arrays.size()));
  for (const auto& a : arrays) {
    put_u64(out, a.size());
    out.append(reinterpret_cast<const char*>(a.data()), a.size() * sizeof(double));
  }
  return out;
}

StatePtr decode_state(std::string_view bytes) {
  Reader r{bytes};
  r.need(4);
  // Version 1 (before run logs were column blocks) still loads: its logs are JSON in the skeleton.
  const bool version1 = std::memcmp(bytes.data(), kMagicVersion1, 4) == 0;
  if (!version1 && std::memcmp(bytes.data(), kMagic, 4) != 0)
    corrupt("unknown encoding (expected \"HLE2\" or \"HLE1\")");
  r.at = 4;
  const std::uint32_t text_size = r.u32();
  r.need(text_size);
  const std::string_view text = bytes.substr(r.at, text_size);
  r.at += text_size;
  const std::uint32_t count = r.u32();
  // Every array takes at least its 8-byte length: a count the remaining bytes cannot hold is refused
  // before anything is allocated (a 278-byte blob claiming 150,000,000 arrays allocated 3.5 GB).
  if (count > (bytes.size() - r.at) / sizeof(std::uint64_t))
    corrupt("array count " + std::to_string(count) + " exceeds what the " + std::to_string(bytes.size() - r.at) +
            " remaining bytes can hold");
  std::vector<std::vector<double>> arrays(count);
  for (auto& a : arrays) {
    const std::uint64_t n = r.u64();
    if (n > (bytes.size() - r.at) / sizeof(double)) corrupt("truncated array");
    a.resize(n);
    std::memcpy(a.data(), bytes.data() + r.at, n * sizeof(double));
    r.at += n * sizeof(double);
  }
  if (r.at != bytes.size()) corrupt("trailing bytes");
  Json skeleton = io::json::parse_json_text(text, "entity state");
  if (!skeleton.is_object() || !skeleton.contains("data")) corrupt("no data");
  unpack(skeleton["data"], arrays);
  return state_from_json(skeleton, version1 ? nullptr : &arrays);
}

}  // namespace hula::oli::detail
