// SPDX-License-Identifier: MIT
// The property the law-parser fuzzer checks on every input, shared with the
// corpus regression test (tests/law/parser_corpus_test.cpp): parsing either
// throws hula::Error or gives a law that prints and parses back to the same
// node, differentiates, compiles and evaluates without crashing. Any other
// outcome aborts (a crash for libFuzzer, a failure for the test).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::fuzz {

[[noreturn]] inline void fail(const char* what, std::string_view input) {
  std::fprintf(stderr, "law parser check failed: %s\ninput: %.*s\n", what, static_cast<int>(input.size()),
               input.data());
  std::abort();
}

/// Runs the check on one input; returns true when the input parsed.
inline bool check_law_parser_input(std::string_view text) {
  law::Context ctx;
  law::ParseOptions options;
  options.parameters = {"t", "u"};
  law::Law l;
  try {
    l = law::parse(text, ctx, options);
  } catch (const Error&) {
    return false;  // the documented outcome for bad input
  }
  if (!l.valid()) fail("parse returned an empty law", text);
  const std::string printed = law::print(l);
  law::ParseOptions relaxed = options;
  relaxed.max_length = std::size_t{16} << 20;
  relaxed.max_depth = 1000;
  relaxed.max_nodes = std::size_t{1} << 30;
  law::Law back;
  try {
    back = law::parse(printed, ctx, relaxed);
  } catch (const Error& e) {
    std::fprintf(stderr, "printed: %s\nerror: %s\n", printed.c_str(), e.what());
    fail("the printed law does not parse", text);
  }
  if (!(back == l)) fail("parse(print(x)) is not x", text);
  try {
    std::vector<law::Law> outs{l};
    if (law::Context::size(l) < 300) outs.push_back(law::derivative(l, "t"));
    const std::string inputs[2] = {"t", "u"};
    const law::Tape tape = law::Tape::compile(outs, inputs);
    std::vector<double> out(tape.output_count());
    for (double t : {-1.5, 0.0, 0.5, 2.0}) {
      const double in[2] = {t, 0.25};
      (void)tape.evaluate(in, out);
    }
  } catch (const Error&) {
    // limits (node count, height) are documented errors
  }
  return true;
}

}  // namespace hula::fuzz
