// SPDX-License-Identifier: MIT
// Entity states as JSON and as the store's bytes (entity_codec.hpp gives the layout).
#include "hula/oli/detail/entity_codec.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"

namespace hula::oli::detail {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the entity codec writes the host's doubles as little-endian");
constexpr char kMagic[4] = {'H', 'L', 'E', '1'};

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

Json study_to_json(const Study& study) {
  Json runs = Json::array();
  for (const StudyRun& run : study.runs) {
    Json r = Json::object();
    r["seed"] = run.seed;
    r["result"] = run.result;
    r["log"] = run.log;
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

Study study_from_json(const Json& json) {
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
    run.log = j::require_member(runs[i], at, "log");
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

Json entity_data_to_json(const EntityState& state) {
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
      return study_to_json(*state.study);
  }
  return Json::object();
}

void entity_data_from_json(EntityKind kind, const Json& data, EntityState& state) {
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
      state.study = std::make_shared<const Study>(study_from_json(data));
      return;
  }
}

Json entity_state_to_json(const EntityState& state) {
  Json out = Json::object();
  out["kind"] = entity_kind_name(state.kind);
  out["attributes"] = attributes_to_json(state.attributes);
  out["provenance"] = state.provenance ? provenance_to_json(*state.provenance) : Json(nullptr);
  out["constraints"] = constraints_to_json(state.constraints);
  out["data"] = entity_data_to_json(state);
  return out;
}

StatePtr entity_state_from_json(const Json& json) {
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
  entity_data_from_json(k, j::require_member(json, root, "data"), *state);
  return state;
}

std::string encode_state(const EntityState& state) {
  Json skeleton = entity_state_to_json(state);
  std::vector<std::vector<double>> arrays;
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
  if (std::memcmp(bytes.data(), kMagic, 4) != 0) corrupt("unknown encoding (expected \"HLE1\")");
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
  return entity_state_from_json(skeleton);
}

}  // namespace hula::oli::detail
