// SPDX-License-Identifier: MIT
// NumPy interop of the hulahoops binding: one policy for every array argument
// (docs/python.md "Arrays"). Real inputs of any float or integer dtype and any
// strides are accepted and converted to C-contiguous float64 (no copy when the
// input already is one); complex, boolean, object and string arrays are refused
// with hula::Error(Errc::InvalidArgument) naming the argument and its dtype;
// shapes are checked and a wrong one is refused naming the argument, the
// expected shape and the shape received. Outputs are fresh float64 arrays the
// C++ batch APIs write into directly.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::python {

namespace py = pybind11;

/// A C-contiguous float64 array.
using Doubles = py::array_t<double, py::array::c_style>;

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles to alias NumPy rows");

/// `value` as a C-contiguous float64 array (a view when it already is one).
/// @param name the argument's name, used in error messages.
/// @throws hula::Error(Errc::InvalidArgument) naming `name` if the dtype is not
///   a real number type (float16/32/64, signed or unsigned integers).
[[nodiscard]] Doubles as_doubles(py::handle value, const std::string& name);

/// "(4, 5)": a shape in NumPy's notation.
[[nodiscard]] std::string shape_text(const py::array& a);

/// Points given as an (n, 2) or (n, 3) array; 2-D points get z = 0.
struct Points {
  std::vector<Vec3> points;
  int dimension = 3;
};

/// @throws hula::Error(Errc::InvalidArgument) naming `name` and the shape
///   received unless it is (n, 2) or (n, 3) with n >= minimum.
[[nodiscard]] Points as_points(py::handle value, const std::string& name, std::size_t minimum = 1);

/// A point given as a sequence of 2 or 3 numbers.
[[nodiscard]] Vec3 as_point(py::handle value, const std::string& name);

/// A 1-D array of numbers (a scalar counts as one number).
[[nodiscard]] std::vector<double> as_vector(py::handle value, const std::string& name);

/// The (n, dimension) view of an (n, 3) Vec3 buffer: the whole array for 3-D,
/// its first two columns for planar curves.
[[nodiscard]] py::array vec3_rows(const Doubles& rows3, int dimension);

/// The contents of a span of Vec3 as an (n, dimension) array.
[[nodiscard]] py::array to_rows(std::span<const Vec3> points, int dimension);

/// A std::vector<double> as a 1-D array.
[[nodiscard]] py::array to_array(std::span<const double> values);

/// A JSON value as Python objects (dicts, lists, floats, ints, str, bool, None), converted value by
/// value: the one way a library JSON document (a run report, a study result) reaches Python.
[[nodiscard]] py::object to_python(const io::Json& value);

/// A Python value (dict, list, tuple, NumPy array, str, int, float, bool, None) as a JSON value,
/// converted value by value (no JSON text).
/// @throws hula::Error(Errc::InvalidArgument) naming `name` (and the path inside it) for anything else
[[nodiscard]] io::Json from_python(py::handle value, const std::string& name);

/// A curve value from what Python passes: a NurbsCurve, a curve file as a dict (converted value by
/// value) or the path of a curve file (str or os.PathLike, read by io::read_curve_file).
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for anything else; as the curve codec
[[nodiscard]] curve::Curve curve_value(py::handle value);

}  // namespace hula::python
