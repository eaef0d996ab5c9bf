// SPDX-License-Identifier: MIT
// Issue 24, item 12: a hula-document JSON of a future version ("version": 99,
// members this build does not know) was imported silently, dropping what it
// could not read; a curve file of version 99 is refused. Now both are refused.
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: doc import refuses version 99 (field version) and an unknown top-level member (named), and the
// document stays at revision 0 with no entity; version 1 with the known members imports.
TEST(Issue24DocumentVersion, FutureDocumentJsonIsRefused) {
  TempDir dir;
  const std::string doc = (dir / "d.hula").string();
  ASSERT_EQ(hula({"doc", "new", doc}).exit_code, 0);
  const std::string curve =
      R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0, 0], [1, 0, 0]]})";
  write(dir / "v99.json", R"({"format": "hula-document", "version": 99, "entities": [)" + curve + "]}");
  write(dir / "extra.json",
        R"({"format": "hula-document", "version": 1, "layers": ["a"], "entities": [)" + curve + "]}");
  write(dir / "v1.json", R"({"format": "hula-document", "version": 1, "entities": [)" + curve + "]}");
  const ProcessResult v99 = hula({"doc", "import", doc, (dir / "v99.json").string()});
  EXPECT_EQ(v99.exit_code, 3) << v99.err;
  EXPECT_EQ(error_of(v99)["error"]["code"], "ParseError");
  EXPECT_EQ(error_of(v99)["error"]["where"]["field"], "version");
  EXPECT_NE(message_of(v99).find("version = 99"), std::string::npos) << v99.err;
  const ProcessResult extra = hula({"doc", "import", doc, (dir / "extra.json").string()});
  EXPECT_EQ(extra.exit_code, 3) << extra.err;
  EXPECT_NE(message_of(extra).find("layers"), std::string::npos) << extra.err;
  const ProcessResult list = hula({"doc", "list", doc});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_EQ(json::parse(list.out)["revision"], 0);
  EXPECT_TRUE(json::parse(list.out)["entities"].empty());
  const ProcessResult v1 = hula({"doc", "import", doc, (dir / "v1.json").string()});
  ASSERT_EQ(v1.exit_code, 0) << v1.err;
  EXPECT_EQ(json::parse(v1.out)["labels"], json::array({1}));
}

}  // namespace
}  // namespace hula::regress
