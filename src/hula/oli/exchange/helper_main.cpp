// SPDX-License-Identifier: MIT
// hula-exchange REQUEST.json ANSWER.json: the isolated STEP/IGES helper
// process (see exchange.hpp). Reads one request, runs Open CASCADE, writes one
// answer ({"ok": …} or {"error": …}) and exits 0, or exits 6 (no answer) when
// memory runs out. If Open CASCADE crashes or
// hangs, no answer is written and the caller reports it, naming the file.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/error_json.hpp"
#include "hula/io/json_read.hpp"
#include "hula/oli/exchange/detail/protocol.hpp"
#include "hula/oli/exchange/occt_exchange.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: hula-exchange REQUEST.json ANSWER.json\n");
    return 2;
  }
  using namespace hula;
  io::Json answer;
  try {
    const auto request =
        oli::detail::request_from_json(io::json::parse_json_text(io::read_text_file(argv[1]), "exchange request"));
    if (const auto* e = std::get_if<oli::detail::ExportRequest>(&request))
      answer = oli::detail::export_answer_to_json(oli::detail::write_exchange_file(*e));
    else
      answer = oli::detail::import_answer_to_json(
          oli::detail::read_exchange_file(std::get<oli::detail::ImportRequest>(request).path));
  } catch (const Error& e) {
    answer = io::error_to_json(e);
  } catch (const std::bad_alloc&) {
    // No answer (writing one may need memory too): the status tells the caller.
    std::fputs("hula-exchange: out of memory (std::bad_alloc)\n", stderr);
    return oli::detail::kHelperOutOfMemoryStatus;
  } catch (const std::exception& e) {
    answer =
        io::error_to_json(Error(Errc::HelperFailure, std::string("internal error: ") + e.what(), {.field = "path"}));
  }
  try {
    io::write_file_atomically(argv[2], answer.dump());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hula-exchange: cannot write the answer: %s\n", e.what());
    return 1;
  }
  return 0;
}
