// SPDX-License-Identifier: MIT
// The property every reader's fuzzer checks, shared with
// the corpus replay test (tests/io/reader_corpus_test.cpp): reading bytes
// either gives a value or throws hula::Error — never a crash, a hang, another
// exception type or an unbounded allocation. A value read back is used a
// little (evaluated, written and read again) so a half-checked value that
// only fails later is caught too. Any other outcome aborts (a crash for
// libFuzzer, a failure for the test). No file is opened except those a study
// names relative to a directory that does not exist.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "hula/core/error.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/points_file.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/profile_file.hpp"
#include "hula/io/study_file.hpp"
#include "hula/law/expr.hpp"

namespace hula::fuzz {

/// The readers with a fuzz target (fuzz/<name>_fuzz.cpp, corpus fuzz/corpus/<name>/).
enum class Reader { Curve, Points, Problem, Study, Profile };

[[noreturn]] inline void reader_check_failed(const char* reader, const char* what) {
  std::fprintf(stderr, "%s reader check failed: %s\n", reader, what);
  std::abort();
}

/// Where a study's relative file names resolve: a directory that does not exist.
inline const char* kNoBase = "/nonexistent-hula-fuzz-base";

/// Runs one reader on `text`; returns true when it produced a value.
inline bool check_reader_input(Reader reader, std::string_view text) {
  const char* name = "?";
  try {
    switch (reader) {
      case Reader::Curve: {
        name = "curve";
        const curve::Curve file = io::parse_curve_json(text);
        const curve::Curve back = io::parse_curve_json(io::to_file_text(io::curve_to_json(file)));
        (void)back.point(back.domain().start);
        return true;
      }
      case Reader::Points: {
        name = "points";
        const io::PointSet set = io::parse_points(text);
        if (set.dimension != 2 && set.dimension != 3) reader_check_failed(name, "dimension is not 2 or 3");
        return true;
      }
      case Reader::Problem: {
        name = "problem";
        const io::ProblemFile file = io::parse_problem_json(text);
        file.problem.validate();
        return true;
      }
      case Reader::Study: {
        name = "study";
        // The kind is the document's own; an unknown kind is an Error from the envelope check.
        const io::json::Json doc = io::json::parse_json_text(text, "study file");
        std::string kind = "match-curvature";
        if (doc.is_object() && doc.contains("study") && doc["study"].is_string())
          kind = doc["study"].get<std::string>();
        const io::StudyDocument study = io::parse_study_json(text, kind);
        if (kind == "fair-knots")
          (void)io::fair_knots_study_from_json(study);
        else if (kind == "fin-compound")
          (void)io::read_fin_compound_study(study);
        else if (kind == "edit-projection")
          (void)io::read_edit_projection_study(study);
        else if (kind == "hermite")
          (void)io::read_hermite_study(study);
        else if (kind == "match-curvature-torsion")
          (void)io::torsion_match_study_from_json(study, io::relative_to(kNoBase));
        else
          (void)io::match_study_from_json(study, io::relative_to(kNoBase));
        return true;
      }
      case Reader::Profile: {
        name = "profile";
        const io::json::Json doc = io::json::parse_json_text(text, "profile");
        law::Context context;
        const studies::Profile profile =
            io::profile_from_json(doc, io::json::root_path("target"), io::relative_to(kNoBase), context);
        for (double u : {0.0, 0.25, 1.0}) (void)profile(u);
        return true;
      }
    }
  } catch (const Error&) {
    return false;  // the documented outcome for bad input
  } catch (const std::bad_alloc&) {
    reader_check_failed(name, "std::bad_alloc: an input's size is not capped");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    reader_check_failed(name, "an exception other than hula::Error escaped");
  }
  return false;
}

}  // namespace hula::fuzz
