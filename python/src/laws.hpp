// SPDX-License-Identifier: MIT
// The Python-side law value: a hula::law::Law with the names of its
// parameters (the order positional arguments bind in) and a text form that
// parses back to the same law, so laws from separate contexts can be combined
// (reconstruct's κ and τ must share one law::Context).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "hula/law/expr.hpp"
#include "hula/law/tape.hpp"

namespace hula::python {

/// A parsed law with its parameter names and its compiled tape (built on
/// first evaluation, under the GIL).
struct PyLaw {
  law::Law law;
  std::vector<std::string> parameters;
  std::shared_ptr<const law::Tape> tape{};

  [[nodiscard]] const law::Tape& compiled();
};

/// Parses `text` with the given parameter names in `context`.
/// @throws hula::Error(Errc::ParseError) with the line and column of the fault.
[[nodiscard]] PyLaw parse_law(const std::string& text, const std::vector<std::string>& parameters,
                              const law::Context& context);

/// A scalar law of `parameter` from a hulahoops.Law, a string or a number,
/// re-parsed in `context`.
/// @throws hula::Error(Errc::InvalidArgument) naming `name` for any other type.
[[nodiscard]] law::Law law_argument(pybind11::handle value, const std::string& parameter, const law::Context& context,
                                    const std::string& name);

}  // namespace hula::python
