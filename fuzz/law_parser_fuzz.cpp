// SPDX-License-Identifier: MIT
// libFuzzer target for the law parser (STYLE.md fuzzing rule 7): no crash, no
// hang, and either a law that round-trips through print/parse or a
// hula::Error. Build with the `fuzz` preset (clang-14):
//   cmake --preset fuzz && cmake --build --preset fuzz --target fuzz_law_parser
//   ./build/fuzz/fuzz/fuzz_law_parser fuzz/corpus/law_parser -max_total_time=60
// Crashers go to fuzz/corpus/law_parser/ and are replayed by test_law_parser_corpus.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "law_parser_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The default max_length (64 KiB) caps the work per input; longer inputs are rejected early.
  (void)hula::fuzz::check_law_parser_input(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
