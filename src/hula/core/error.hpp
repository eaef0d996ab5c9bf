// SPDX-License-Identifier: MIT
// hula::Error: the single exception type for invalid input across HulaHoops
// (STYLE.md "Error-handling policy"). Every error carries a stable code
// (documented in docs/errors.md and switched on by the CLI, the HTTP API and
// the web UI), a message that names the input at fault with its value, and a
// machine-readable location so a client can highlight the offending point,
// knot or character. hula::InternalError and HULA_ASSERT report our own bugs.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hula {

/// Stable error codes. Never renumber or rename: clients switch on the names
/// returned by `errc_name`. New codes are appended.
enum class Errc : std::uint8_t {
  InvalidArgument,   ///< an argument is outside its documented range
  NonFiniteInput,    ///< NaN or infinity in a number that must be finite
  TooFewPoints,      ///< fewer points than the operation needs
  CoincidentPoints,  ///< consecutive points coincide where a distance is needed
  InvalidKnots,      ///< knot vector malformed (order, size, multiplicity)
  InvalidDegree,     ///< degree < 1 or degree ≥ number of control points
  InvalidWeight,     ///< rational weight ≤ 0 or non-finite
  OutOfDomain,       ///< parameter outside the curve's domain
  InvalidOption,     ///< an Options struct field is out of range
  ParseError,        ///< text input (JSON, CSV, expression) cannot be parsed
  IoError,           ///< a file cannot be read or written
  NumericalFailure,  ///< the computation overflowed or did not converge
  ScaleOutOfRange,   ///< model coordinates too large or too small to handle
  Unsupported,       ///< the selected kernel backend has no such operation (where.field names it)
  HelperFailure,     ///< an isolated helper process (STEP/IGES exchange) crashed, hung or ran out of memory
  DocumentLocked,    ///< a document is held by another writer, or SQLite stayed busy/locked past its timeout
  DocumentCorrupt,   ///< a document file is corrupt or truncated
  StorageFull,       ///< the disk is full or a file-size limit was reached while writing
};

/// The last Errc value (for iterating over every code).
inline constexpr Errc kLastErrc = Errc::StorageFull;

/// The stable name of a code, e.g. "InvalidKnots".
[[nodiscard]] std::string_view errc_name(Errc code) noexcept;

/// Machine-readable location of the input at fault. Unused members are empty.
/// `field` names the argument or JSON member ("knots", "points"), `index` the
/// element, `component` the coordinate (0 = x), `line`/`column` a position in
/// text input (1-based).
struct ErrorWhere {
  std::string field{};
  std::optional<std::size_t> index{};
  std::optional<std::size_t> component{};
  std::optional<std::size_t> line{};
  std::optional<std::size_t> column{};

  [[nodiscard]] bool empty() const noexcept { return field.empty() && !index && !component && !line && !column; }
};

/// Invalid input. The message names the input at fault and its value.
class Error : public std::runtime_error {
 public:
  Error(Errc code, const std::string& message, ErrorWhere where = {});

  [[nodiscard]] Errc code() const noexcept { return code_; }
  [[nodiscard]] const ErrorWhere& where() const noexcept { return where_; }
  /// The message without the "Code: " prefix that what() carries.
  [[nodiscard]] const std::string& message() const noexcept { return message_; }

 private:
  Errc code_;
  ErrorWhere where_;
  std::string message_;
};

/// A broken internal invariant: a bug in HulaHoops, never the caller's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Formats a double for error messages with enough digits to be recognised
/// (%.17g, so the value in the message is the value that was passed).
[[nodiscard]] std::string format_number(double value);

namespace detail {
[[noreturn]] void assertion_failed(const char* condition, const char* message, const char* file, int line);
}  // namespace detail

}  // namespace hula

/// Checks an internal invariant. Throws hula::InternalError when it fails; in
/// release builds without HULA_ENABLE_ASSERTS it compiles to nothing.
#if !defined(NDEBUG) || defined(HULA_ENABLE_ASSERTS)
#define HULA_ASSERT(cond, msg)                                                     \
  do {                                                                             \
    if (!(cond)) ::hula::detail::assertion_failed(#cond, msg, __FILE__, __LINE__); \
  } while (false)
#else
#define HULA_ASSERT(cond, msg) \
  do {                         \
  } while (false)
#endif
