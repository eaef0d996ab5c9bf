// SPDX-License-Identifier: MIT
// Issue 24, item 17 (command line): `--tolerance 0` on approximate, fit and
// law --to-nurbs printed "Value 0 not in range 0.000000 to 1797693…" (a
// 309-digit number) with an empty `where`; `doc import a.dxf` said only "not
// valid JSON". The server's messages (a lowercase Bearer scheme, two Host
// headers) are in issue_24_server_requests_test.cpp.
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: each --tolerance 0 is a usage error that names --tolerance and the real range "> 0", carries
// where.field "tolerance", and has no long run of digits.
TEST(Issue24Messages, ToleranceZeroNamesTheOptionAndItsRange) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  const std::string points = (dir / "points.csv").string(), out = (dir / "o.json").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"approximate", "--points", points, "--tolerance", "0", "-o", out},
        {"fit", "--points", points, "--tolerance", "0", "-o", out},
        {"law", "vec(t, t, 0)", "--to-nurbs", "0,1", "--tolerance", "0", "-o", out}}) {
    const ProcessResult r = hula(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.err;
    const json e = error_of(r)["error"];
    const std::string m = e.value("message", std::string());
    EXPECT_NE(m.find("--tolerance 0: must be a number > 0"), std::string::npos) << args[0] << ": " << m;
    EXPECT_EQ(m.find("1797693"), std::string::npos) << m;
    EXPECT_EQ(e["where"]["field"], "tolerance") << args[0];
    EXPECT_FALSE(fs::exists(out));
  }
}

// checks: importing a file that is neither JSON, STEP/IGES nor DXF (a DWG name) names the formats doc import
// reads and the file's extension; the document is unchanged.
TEST(Issue24Messages, ImportOfAnUnknownFormatNamesTheFormatsExpected) {
  TempDir dir;
  const std::string doc = (dir / "d.hula").string();
  ASSERT_EQ(hula({"doc", "new", doc}).exit_code, 0);
  write(dir / "a.dwg", "0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n");
  const ProcessResult r = hula({"doc", "import", doc, (dir / "a.dwg").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const std::string m = message_of(r);
  for (const char* piece : {"a.dwg", "'.dwg' is none of these", "JSON", ".step", ".iges", ".dxf"})
    EXPECT_NE(m.find(piece), std::string::npos) << piece << " in " << m;
  EXPECT_EQ(error_of(r)["error"]["where"]["field"], "input");
  EXPECT_EQ(json::parse(hula({"doc", "list", doc}).out)["revision"], 0);
}

}  // namespace
}  // namespace hula::regress
