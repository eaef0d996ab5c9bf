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

py::object to_python(const io::Json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

}  // namespace hula::python
