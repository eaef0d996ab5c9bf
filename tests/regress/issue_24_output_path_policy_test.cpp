// SPDX-License-Identifier: MIT
// Issue 24, items 1 and 11: one output-path policy for every writer (a regular
// file or `-`; never replace or write through a symbolic link, FIFO, device or
// dangling link; a directory is refused by name). Was: `doc export --format
// step|iges` replaced a symlink, a FIFO or a dangling link and reported success
// (its helper renamed its own temporary file over the target), a directory
// target said "cannot write '…': Success", `-o -` made a file named "-", and
// `--svg DIR` member files were checked only after the whole computation.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

#include "cli.hpp"

namespace hula::regress {
namespace {

std::vector<std::string> export_formats() {
#ifdef HULA_WITH_OCCT
  return {"json", "step", "iges"};
#else
  return {"json"};
#endif
}

// The sorted names in `dir`.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// A document holding one curve (label 1).
fs::path document_with_curve(const TempDir& dir) {
  write(dir / "points.csv", kPointsCsv);
  EXPECT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const fs::path doc = dir / "d.hula";
  EXPECT_EQ(hula({"doc", "new", doc.string()}).exit_code, 0);
  EXPECT_EQ(hula({"doc", "add", doc.string(), "--curve", (dir / "c.json").string()}).exit_code, 0);
  return doc;
}

// checks: doc export in every format refuses a symlink, a dangling symlink, a FIFO and a directory by name
// (IoError naming --output, exit 3) and leaves each as it was; the dangling link's target is not created.
TEST(Issue24OutputPathPolicy, DocExportRefusesLinksFifosAndDirectories) {
  TempDir dir;
  const fs::path doc = document_with_curve(dir);
  write(dir / "precious.txt", "precious");
  fs::create_symlink(dir / "precious.txt", dir / "link.out");
  fs::create_symlink(dir / "nowhere.txt", dir / "dangling.out");
  ASSERT_EQ(::mkfifo((dir / "fifo.out").c_str(), 0600), 0);
  fs::create_directory(dir / "emptydir.out");
  const std::vector<std::pair<std::string, std::string>> targets = {{"link.out", "symbolic link"},
                                                                    {"dangling.out", "symbolic link"},
                                                                    {"fifo.out", "FIFO"},
                                                                    {"emptydir.out", "directory"}};
  for (const std::string& format : export_formats()) {
    for (const auto& [name, kind] : targets) {
      const ProcessResult r =
          hula({"doc", "export", doc.string(), "1", "--format", format, "-o", (dir / name).string()});
      EXPECT_EQ(r.exit_code, 3) << format << " " << name << ": " << r.err;
      const std::string m = message_of(r);
      EXPECT_NE(m.find(kind), std::string::npos) << format << " " << name << ": " << m;
      EXPECT_NE(m.find("--output"), std::string::npos) << m;
      EXPECT_EQ(m.find("Success"), std::string::npos) << m;
      EXPECT_EQ(error_of(r)["error"]["code"], "IoError") << r.err;
    }
    EXPECT_TRUE(fs::is_symlink(dir / "link.out")) << format;
    EXPECT_EQ(io::read_text_file(dir / "precious.txt"), "precious") << format;
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.out")) << format;
    EXPECT_FALSE(fs::exists(dir / "nowhere.txt")) << format;
    EXPECT_TRUE(fs::is_fifo(dir / "fifo.out")) << format;
    EXPECT_TRUE(fs::is_directory(dir / "emptydir.out")) << format;
    EXPECT_TRUE(fs::is_empty(dir / "emptydir.out")) << format;
  }
  EXPECT_TRUE(temporaries(dir.path()).empty());
}

// checks: doc export -o - writes the file on stdout alone in every format (was: a file named "-" for STEP
// and IGES, and the JSON summary after the JSON file).
TEST(Issue24OutputPathPolicy, DocExportToStdoutWritesTheFileAlone) {
  TempDir dir;
  const fs::path doc = document_with_curve(dir);
  for (const std::string& format : export_formats()) {
    const ProcessResult r = hula({"doc", "export", doc.string(), "1", "--format", format, "-o", "-"});
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    if (format == "json") {
      // The exported curve file, byte for byte the one a regular file receives.
      ASSERT_EQ(hula({"doc", "export", doc.string(), "1", "-o", (dir / "e.json").string()}).exit_code, 0);
      EXPECT_EQ(r.out, io::read_text_file(dir / "e.json"));
    } else if (format == "step") {
      EXPECT_EQ(r.out.rfind("ISO-10303-21;", 0), 0U) << r.out.substr(0, 40);
      EXPECT_TRUE(r.out.ends_with("END-ISO-10303-21;\n")) << r.out.substr(r.out.size() - 40);
    } else {
      // IGES: 80-column records, the last one the Terminate section ('T' in column 73).
      ASSERT_GE(r.out.size(), 81U);
      EXPECT_EQ(r.out[r.out.size() - 81 + 72], 'T') << r.out.substr(r.out.size() - 81);
    }
  }
  EXPECT_FALSE(fs::exists("-"));
  EXPECT_FALSE(fs::exists(dir / "-"));
}

// checks: a symlink or FIFO named like an --svg figure stops the command before it computes anything:
// no figure is written, nothing is printed, the link and its target stay (was: the run completed, wrote
// two figures, then failed with exit 3).
TEST(Issue24OutputPathPolicy, SvgMemberLinksAreRefusedBeforeTheComputation) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  fs::create_directory(dir / "figures");
  write(dir / "precious.svg", "precious");
  fs::create_symlink(dir / "precious.svg", dir / "figures" / "kappa.svg");
  ASSERT_EQ(::mkfifo((dir / "figures" / "tau.svg").c_str(), 0600), 0);
  const ProcessResult r =
      hula({"analyse", (dir / "c.json").string(), "--samples", "20", "--svg", (dir / "figures").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  EXPECT_NE(message_of(r).find("--svg"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(dir / "figures"), (std::vector<std::string>{"kappa.svg", "tau.svg"}));
  EXPECT_EQ(io::read_text_file(dir / "precious.svg"), "precious");
}

// checks: --log naming a FIFO or a dangling symlink is refused before the run (nothing blocks, nothing
// is created through the link).
TEST(Issue24OutputPathPolicy, LogThroughFifoOrDanglingLinkIsRefused) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "log.json").c_str(), 0600), 0);
  fs::create_symlink(dir / "nowhere.json", dir / "dangling.json");
  for (const std::string name : {"log.json", "dangling.json"}) {
    const ProcessResult r = hula({"optimise", "--problem", "sphere", "--algorithm", "ga-real", "--generations", "2",
                                  "--log", (dir / name).string()});
    EXPECT_EQ(r.exit_code, 3) << name << ": " << r.err;
    EXPECT_NE(message_of(r).find("--log"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  }
  EXPECT_FALSE(fs::exists(dir / "nowhere.json"));
  EXPECT_TRUE(fs::is_fifo(dir / "log.json"));
}

}  // namespace
}  // namespace hula::regress
