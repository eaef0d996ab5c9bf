// SPDX-License-Identifier: MIT
// hulahoops.Law: parse, evaluate (vectorised over NumPy arrays through the
// compiled tape, the GIL released), derive, integrate and find roots of a
// law expression (grammar in docs/formats.md). Undefined values (log of a
// negative number, a division by zero) come out as NaN, as documented.
#include "laws.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/law/antiderivative.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/integrate.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/roots.hpp"
#include "hula/law/tape.hpp"

namespace hula::python {

namespace py = pybind11;

PyLaw parse_law(const std::string& text, const std::vector<std::string>& parameters, const law::Context& context) {
  law::ParseOptions o;
  o.parameters = parameters;
  return PyLaw{law::parse(text, context, o), parameters, {}};
}

law::Law law_argument(py::handle value, const std::string& parameter, const law::Context& context,
                      const std::string& name) {
  if (py::isinstance<PyLaw>(value)) {
    const auto& l = value.cast<const PyLaw&>();
    if (l.parameters != std::vector<std::string>{parameter}) {
      throw Error(Errc::InvalidArgument, name + " must be a law of the single parameter \"" + parameter + "\"",
                  {.field = name});
    }
    return parse_law(law::print(l.law), {parameter}, context).law;
  }
  if (py::isinstance<py::str>(value)) return parse_law(value.cast<std::string>(), {parameter}, context).law;
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
    return context.constant(value.cast<double>());
  }
  throw Error(Errc::InvalidArgument,
              name + " must be a hulahoops.Law, an expression string or a number, not " +
                  py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>(),
              {.field = name});
}

const law::Tape& PyLaw::compiled() {
  if (!tape) {
    const law::Law outputs[1] = {law};
    tape = std::make_shared<const law::Tape>(law::Tape::compile(outputs, parameters));
  }
  return *tape;
}

namespace {

const std::string& parameter_or_only(const PyLaw& l, const std::optional<std::string>& parameter) {
  if (parameter) return *parameter;
  if (l.parameters.size() != 1) {
    throw Error(Errc::InvalidArgument, "the law has several parameters: name the one to use", {.field = "parameter"});
  }
  return l.parameters.front();
}

py::object call(PyLaw& l, const py::args& args, const py::kwargs& kwargs) {
  const std::size_t p = l.parameters.size();
  std::vector<py::object> inputs(p);
  if (args.size() > p) {
    throw Error(Errc::InvalidArgument,
                std::to_string(args.size()) + " arguments given to a law of " + std::to_string(p) + " parameter(s)",
                {.field = "args"});
  }
  for (std::size_t i = 0; i < args.size(); ++i) inputs[i] = args[i];
  for (const auto& [key, value] : kwargs) {
    const auto name = key.cast<std::string>();
    std::size_t i = 0;
    while (i < p && l.parameters[i] != name) ++i;
    if (i == p) throw Error(Errc::InvalidArgument, "the law has no parameter \"" + name + "\"", {.field = name});
    if (inputs[i]) throw Error(Errc::InvalidArgument, "parameter \"" + name + "\" given twice", {.field = name});
    inputs[i] = py::reinterpret_borrow<py::object>(value);
  }
  py::list arrays;
  for (std::size_t i = 0; i < p; ++i) {
    if (!inputs[i]) {
      throw Error(Errc::InvalidArgument, "parameter \"" + l.parameters[i] + "\" is missing",
                  {.field = l.parameters[i]});
    }
    arrays.append(as_doubles(inputs[i], l.parameters[i]));
  }
  const py::module_ np = py::module_::import("numpy");
  std::vector<py::ssize_t> shape;
  Doubles packed;
  if (p == 0) {
    packed = Doubles(py::ssize_t{0});
  } else {
    const py::sequence b = np.attr("broadcast_arrays")(*arrays);
    const auto first = b[0].cast<py::array>();
    shape.assign(first.shape(), first.shape() + first.ndim());
    packed = Doubles::ensure(np.attr("stack")(b, py::arg("axis") = -1));
  }
  const law::Tape& tape = l.compiled();
  std::size_t n = 1;
  for (const py::ssize_t s : shape) n *= static_cast<std::size_t>(s);
  const std::size_t k = tape.output_count();
  std::vector<py::ssize_t> out_shape = shape;
  if (k > 1) out_shape.push_back(static_cast<py::ssize_t>(k));
  Doubles out(out_shape);
  {
    const py::gil_scoped_release release;
    std::vector<std::uint8_t> defined(n);
    tape.evaluate(std::span<const double>(packed.data(), n * p), std::span<double>(out.mutable_data(), n * k), defined);
    for (std::size_t i = 0; i < n; ++i)
      if (defined[i] == 0)
        for (std::size_t j = 0; j < k; ++j) out.mutable_data()[i * k + j] = std::numeric_limits<double>::quiet_NaN();
  }
  if (out_shape.empty()) return py::float_(out.data()[0]);
  py::object result = std::move(out);
  return result;
}

}  // namespace

void register_laws(py::module_& m) {
  py::class_<PyLaw>(m, "Law", "A law expression (docs/formats.md \"Law expressions\") of named parameters.")
      .def(py::init([](const std::string& text, std::vector<std::string> parameters) {
             return parse_law(text, parameters, law::Context());
           }),
           py::arg("text"), py::arg("parameters") = std::vector<std::string>{"t"},
           "Parses `text` with the given parameter names. Raises ParseError with where = {\"line\", \"column\"} of "
           "the fault.")
      .def_property_readonly(
          "parameters", [](const PyLaw& l) { return l.parameters; }, "The parameter names.")
      .def_property_readonly(
          "dimension", [](const PyLaw& l) { return l.law.dimension(); }, "1 for scalar laws, 2 or 3 for vector laws.")
      .def_property_readonly(
          "text", [](const PyLaw& l) { return law::print(l.law); }, "The law printed back (parses to the same law).")
      .def("__str__", [](const PyLaw& l) { return law::print(l.law); })
      .def("__repr__", [](const PyLaw& l) { return "Law(\"" + law::print(l.law) + "\")"; })
      .def("__call__", &call,
           "Values at broadcast parameter arrays (positional in the order of `parameters`, or by name): a float\n"
           "for scalar inputs, else an array of the broadcast shape (+ (dimension,) for vector laws). Undefined\n"
           "values (log of a negative number...) are NaN.")
      .def(
          "derive",
          [](const PyLaw& l, const std::optional<std::string>& parameter, int order) {
            return PyLaw{law::derivative(l.law, parameter_or_only(l, parameter), order), l.parameters, {}};
          },
          py::arg("parameter") = py::none(), py::arg("order") = 1,
          "The exact symbolic derivative of the given order (parameter: the only one by default).")
      .def(
          "integrate",
          [](const PyLaw& l, double a, double b, const std::optional<std::string>& parameter,
             double relative_tolerance) {
            const std::string& name = parameter_or_only(l, parameter);
            const py::gil_scoped_release release;
            return law::integrate(l.law, name, a, b, {.relative_tolerance = relative_tolerance}).value;
          },
          py::arg("a"), py::arg("b"), py::kw_only(), py::arg("parameter") = py::none(),
          py::arg("relative_tolerance") = 1e-12,
          "The integral from a to b of a scalar law (adaptive Gauss-Kronrod, split at singularities; tanh-sinh at\n"
          "an integrable singular end, exp-sinh / sinh-sinh for a or b = +-inf); nan when divergent.")
      .def(
          "antiderivative",
          [](const PyLaw& l, const std::optional<std::string>& parameter) -> std::optional<PyLaw> {
            std::optional<law::Law> F = law::antiderivative(l.law, parameter_or_only(l, parameter));
            if (!F) return std::nullopt;
            return PyLaw{*F, l.parameters, {}};
          },
          py::arg("parameter") = py::none(),
          "A closed-form F with F' = self (substitution, by parts, rational, atan/asin forms, trigonometric\n"
          "powers; docs/modules/law.md), or None when no rule applies.")
      .def(
          "roots",
          [](const PyLaw& l, double a, double b, const std::optional<std::string>& parameter) {
            const std::string& name = parameter_or_only(l, parameter);
            std::vector<double> r;
            {
              const py::gil_scoped_release release;
              r = law::roots(l.law, name, a, b);
            }
            return to_array(r);
          },
          py::arg("a"), py::arg("b"), py::kw_only(), py::arg("parameter") = py::none(),
          "All roots of a scalar law in [a, b], increasing.")
      .def(py::pickle([](const PyLaw& l) { return py::make_tuple(law::print(l.law), l.parameters); },
                      [](const py::tuple& t) {
                        return parse_law(t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>(),
                                         law::Context());
                      }));
}

}  // namespace hula::python
