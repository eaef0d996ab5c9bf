// SPDX-License-Identifier: MIT
// libFuzzer target for the problem reader: no crash, no hang,
// and either a value or a hula::Error (reader_checks.hpp). Run by scripts/fuzz.sh;
// its corpus fuzz/corpus/problem_reader/ is replayed by test_io_reader_corpus.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "reader_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)hula::fuzz::check_reader_input(hula::fuzz::Reader::Problem,
                                       std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
