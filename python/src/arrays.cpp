// SPDX-License-Identifier: MIT
// NumPy interop policy of the binding; see arrays.hpp.
#include "arrays.hpp"

#include <algorithm>

#include "hula/core/error.hpp"

namespace hula::python {

Doubles as_doubles(py::handle value, const std::string& name) {
  const py::array a = py::module_::import("numpy").attr("asarray")(value);
  const char kind = a.dtype().kind();
  // 'f' float, 'i' signed, 'u' unsigned integers convert exactly (up to 2^53) or by rounding of float16/32
  // widening, which is exact. Booleans, complex numbers, objects and strings are not coordinates.
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw Error(Errc::InvalidArgument,
                name + " has dtype " + py::str(a.dtype()).cast<std::string>() +
                    ": expected real numbers (float64, float32 or integers)",
                {.field = name});
  }
  return Doubles::ensure(a);
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(a.shape(i));
  }
  if (a.ndim() == 1) s += ",";
  return s + ")";
}

Points as_points(py::handle value, const std::string& name, std::size_t minimum) {
  const Doubles a = as_doubles(value, name);
  if (a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3) || static_cast<std::size_t>(a.shape(0)) < minimum) {
    throw Error(
        Errc::InvalidArgument,
        name + " has shape " + shape_text(a) + ": expected (n, 2) or (n, 3) with n >= " + std::to_string(minimum),
        {.field = name});
  }
  Points out;
  out.dimension = static_cast<int>(a.shape(1));
  const auto n = static_cast<std::size_t>(a.shape(0));
  out.points.resize(n);
  const double* p = a.data();
  for (std::size_t i = 0; i < n; ++i) {
    const double* row = p + i * static_cast<std::size_t>(out.dimension);
    out.points[i] = Vec3{row[0], row[1], out.dimension == 3 ? row[2] : 0.0};
  }
  return out;
}

Vec3 as_point(py::handle value, const std::string& name) {
  const Doubles a = as_doubles(value, name);
  if (a.ndim() != 1 || (a.shape(0) != 2 && a.shape(0) != 3)) {
    throw Error(Errc::InvalidArgument, name + " has shape " + shape_text(a) + ": expected (2,) or (3,)",
                {.field = name});
  }
  return Vec3{a.data()[0], a.data()[1], a.shape(0) == 3 ? a.data()[2] : 0.0};
}

std::vector<double> as_vector(py::handle value, const std::string& name) {
  const Doubles a = as_doubles(value, name);
  if (a.ndim() > 1) {
    throw Error(Errc::InvalidArgument, name + " has shape " + shape_text(a) + ": expected a 1-D array (n,)",
                {.field = name});
  }
  return {a.data(), a.data() + a.size()};
}

py::array vec3_rows(const Doubles& rows3, int dimension) {
  if (dimension == 3) return rows3;
  // Planar curves: a strided view of the x, y columns (no copy).
  const py::object view = rows3[py::make_tuple(py::ellipsis(), py::slice(0, dimension, 1))];
  return py::reinterpret_borrow<py::array>(view);
}

py::array to_rows(std::span<const Vec3> points, int dimension) {
  Doubles out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  std::copy_n(reinterpret_cast<const double*>(points.data()), 3 * points.size(), out.mutable_data());
  return vec3_rows(out, dimension);
}

py::array to_array(std::span<const double> values) {
  Doubles out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::object to_python(const io::Json& value) {
  switch (value.type()) {
    case io::Json::value_t::null:
    case io::Json::value_t::discarded:
      return py::none();
    case io::Json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case io::Json::value_t::number_integer:
      return py::int_(value.get<long long>());
    case io::Json::value_t::number_unsigned:
      return py::int_(value.get<unsigned long long>());
    case io::Json::value_t::number_float:
      return py::float_(value.get<double>());
    case io::Json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case io::Json::value_t::array: {
      py::list out;
      for (const io::Json& e : value) out.append(to_python(e));
      return out;
    }
    case io::Json::value_t::object: {
      py::dict out;
      for (const auto& [k, v] : value.items()) out[py::str(k)] = to_python(v);
      return out;
    }
    case io::Json::value_t::binary:
      break;
  }
  throw Error(Errc::Unsupported, "a binary JSON value has no Python form", {.field = "value"});
}

io::Json from_python(py::handle value, const std::string& name) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    // As the JSON parser reads integers: non-negative ones unsigned (a label, a seed), negative ones signed.
    if (value.cast<py::int_>() >= py::int_(0)) return value.cast<unsigned long long>();
    return value.cast<long long>();
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    io::Json out = io::Json::object();
    for (const auto& [k, v] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw Error(Errc::InvalidArgument, name + " has a key that is not a string", {.field = name});
      const std::string key = k.cast<std::string>();
      out[key] = from_python(v, name + "." + key);
    }
    return out;
  }
  if (py::isinstance<py::array>(value)) return from_python(value.attr("tolist")(), name);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    io::Json out = io::Json::array();
    std::size_t i = 0;
    for (const py::handle e : value) out.push_back(from_python(e, name + "[" + std::to_string(i++) + "]"));
    return out;
  }
  // NumPy scalars and other numbers.
  if (py::hasattr(value, "__float__")) return value.cast<double>();
  throw Error(Errc::InvalidArgument,
              name + " is a " + py::str(py::type::of(value).attr("__name__")).cast<std::string>() +
                  ", not a JSON value (dict, list, str, number, bool or None)",
              {.field = name});
}

curve::Curve curve_value(py::handle value) {
  if (py::isinstance<nurbs::NurbsCurve>(value)) return curve::Curve(value.cast<nurbs::NurbsCurve>());
  if (py::isinstance<py::dict>(value)) return io::curve_from_json(from_python(value, "curve"));
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return io::read_curve_file(py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>());
  throw Error(Errc::InvalidArgument,
              "curve must be a NurbsCurve, a curve file as a dict or a curve file's path, not a " +
                  py::str(py::type::of(value).attr("__name__")).cast<std::string>(),
              {.field = "curve"});
}

}  // namespace hula::python
