// SPDX-License-Identifier: MIT
// Implementation of hula::Error and the assertion helper.
#include "hula/core/error.hpp"

#include <cstdio>

namespace hula {

std::string_view errc_name(Errc code) noexcept {
  switch (code) {
    case Errc::InvalidArgument:
      return "InvalidArgument";
    case Errc::NonFiniteInput:
      return "NonFiniteInput";
    case Errc::TooFewPoints:
      return "TooFewPoints";
    case Errc::CoincidentPoints:
      return "CoincidentPoints";
    case Errc::InvalidKnots:
      return "InvalidKnots";
    case Errc::InvalidDegree:
      return "InvalidDegree";
    case Errc::InvalidWeight:
      return "InvalidWeight";
    case Errc::OutOfDomain:
      return "OutOfDomain";
    case Errc::InvalidOption:
      return "InvalidOption";
    case Errc::ParseError:
      return "ParseError";
    case Errc::IoError:
      return "IoError";
    case Errc::NumericalFailure:
      return "NumericalFailure";
    case Errc::ScaleOutOfRange:
      return "ScaleOutOfRange";
    case Errc::Unsupported:
      return "Unsupported";
    case Errc::HelperFailure:
      return "HelperFailure";
    case Errc::DocumentLocked:
      return "DocumentLocked";
    case Errc::DocumentCorrupt:
      return "DocumentCorrupt";
    case Errc::StorageFull:
      return "StorageFull";
  }
  return "Unknown";
}

Error::Error(Errc code, const std::string& message, ErrorWhere where)
    : std::runtime_error(std::string(errc_name(code)) + ": " + message),
      code_(code),
      where_(std::move(where)),
      message_(message) {}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

namespace detail {
void assertion_failed(const char* condition, const char* message, const char* file, int line) {
  throw InternalError(std::string("internal error: ") + message + " (" + condition + ") at " + file + ":" +
                      std::to_string(line));
}
}  // namespace detail

}  // namespace hula
