// SPDX-License-Identifier: MIT
// Issue 24, item 6: a 278-byte hostile entity blob (an array count of
// 150,000,000) made `doc check` allocate 3.5 GB for 9 s, and with 0xFFFFFFFF
// every `doc` command exited 6 (out of memory). Every count read from a blob is
// now bounded by the bytes that remain before anything is allocated. The same
// holds for the counts a DXF or an IGES file states before its arrays.
#include <sqlite3.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>

#include "cli.hpp"

namespace hula::regress {
namespace {

// An entity blob: magic "HLE1", a skeleton of `text`, then an array count with nothing after it.
std::string hostile_blob(std::uint32_t count) {
  const std::string text = R"({"kind": "curve", "attributes": {}, "data": {"$f64": 0}})";
  std::string blob = "HLE1";
  const auto u32 = [&](std::uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4);
    blob.append(b, 4);
  };
  u32(static_cast<std::uint32_t>(text.size()));
  blob += text;
  u32(count);
  blob.append(8, '\0');  // one empty array's length, so the blob is not simply truncated at the count
  return blob;
}

// Replaces entity 1's stored state with `blob`, with SQLite directly (a hostile or damaged file).
void plant(const fs::path& doc, const std::string& blob) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(doc.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "UPDATE entities SET state = ? WHERE label = 1", -1, &st, nullptr), SQLITE_OK);
  sqlite3_bind_blob(st, 1, blob.data(), static_cast<int>(blob.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(st), SQLITE_DONE) << sqlite3_errmsg(db);
  EXPECT_EQ(sqlite3_changes(db), 1);
  sqlite3_finalize(st);
  sqlite3_close(db);
}

// checks: under a 1 GB address-space limit, `doc check` of a document whose entity blob claims 150,000,000
// and 0xFFFFFFFF arrays reports the file broken (exit 3, "ok": false) with a problem naming the array
// count, and `doc list` refuses it as corrupt (exit 3, DocumentCorrupt) — neither runs out of memory (exit 6).
TEST(Issue24BlobCounts, HostileArrayCountIsRefusedBeforeAllocating) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const fs::path doc = dir / "d.hula";
  ASSERT_EQ(hula({"doc", "new", doc.string()}).exit_code, 0);
  ASSERT_EQ(hula({"doc", "add", doc.string(), "--curve", (dir / "c.json").string()}).exit_code, 0);
  for (const std::uint32_t count : {150'000'000U, 0xFFFFFFFFU}) {
    plant(doc, hostile_blob(count));
    const auto limited = [&](const std::string& command) {
      return testing::run_process("/bin/sh", {"-c", "ulimit -v 1000000 && exec \"$0\" doc \"$1\" \"$2\"", HULA_CLI_PATH,
                                              command, doc.string()});
    };
    const ProcessResult check = limited("check");
    ASSERT_EQ(check.exit_code, 3) << count << ": " << check.err.substr(0, 300);
    const json report = json::parse(check.out);
    EXPECT_EQ(report["ok"], false);
    EXPECT_NE(report["problems"].dump().find("array count " + std::to_string(count)), std::string::npos)
        << report["problems"].dump();
    const ProcessResult list = limited("list");
    EXPECT_EQ(list.exit_code, 3) << count << ": " << list.err.substr(0, 300);
    EXPECT_NE(message_of(list).find("array count"), std::string::npos) << list.err.substr(0, 300);
    // A document whose entity does not load is corrupt, not an I/O failure: the server answers it 422, not 500
    // (item 13; docs/errors.md).
    EXPECT_EQ(error_of(list)["error"]["code"], "DocumentCorrupt") << list.err.substr(0, 300);
  }
}

// `hula ARGS...` under a 1 GB address-space limit (the exchange helper inherits it).
ProcessResult limited(const std::vector<std::string>& args) {
  std::vector<std::string> all{"-c", "ulimit -v 1000000 && exec \"$@\"", "sh", HULA_CLI_PATH};
  all.insert(all.end(), args.begin(), args.end());
  return testing::run_process("/bin/sh", all);
}

// `text` with the value of the first group `code` of its SPLINE entity replaced by `value` (DXF: a group code
// line, then its value line).
std::string with_spline_group(const std::string& text, const std::string& code, const std::string& value) {
  std::istringstream in(text);
  std::string out, line;
  bool spline = false, done = false, replace_next = false;
  while (std::getline(in, line)) {
    if (replace_next) {
      line = value;
      replace_next = false;
      done = true;
    } else if (line == "SPLINE") {
      spline = true;
    } else if (spline && !done && line.find_first_not_of(' ') != std::string::npos &&
               line.substr(line.find_first_not_of(' ')) == code) {
      replace_next = true;
    }
    out += line + "\n";
  }
  EXPECT_TRUE(done) << "no SPLINE group " << code;
  return out;
}

// checks: a DXF SPLINE stating 150,000,000 or 0xFFFFFFFF knots (group code 72) or control points (73) — dxflib
// allocated and zeroed that many before reading them: exit 6 under 1 GB — is refused with exit 3, ParseError
// naming the file, the line and the count, and no output is written.
TEST(Issue24BlobCounts, HostileDxfCountIsRefusedBeforeAllocating) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  ASSERT_EQ(hula({"convert", (dir / "c.json").string(), "-o", (dir / "c.dxf").string()}).exit_code, 0);
  const std::string dxf = io::read_text_file(dir / "c.dxf");
  for (const std::string count : {"150000000", "4294967295"}) {
    for (const auto& [code, what] : {std::pair<std::string, std::string>{"72", "knots"}, {"73", "control points"}}) {
      const fs::path bad = dir / ("bad-" + code + ".dxf");
      write(bad, with_spline_group(dxf, code, count));
      const ProcessResult r = limited({"convert", bad.string(), "-o", (dir / "out.json").string()});
      EXPECT_EQ(r.exit_code, 3) << code << " = " << count << ": " << r.err.substr(0, 300);
      EXPECT_EQ(error_of(r)["error"]["code"], "ParseError");
      EXPECT_NE(message_of(r).find("states " + count + " " + what + " (group code " + code + ")"), std::string::npos)
          << message_of(r);
      EXPECT_NE(message_of(r).find(bad.filename().string()), std::string::npos) << message_of(r);
      EXPECT_FALSE(fs::exists(dir / "out.json"));
    }
  }
}

#ifdef HULA_WITH_OCCT
// checks: an IGES rational B-spline curve (entity 126) stating K = 150,000,000 or 0xFFFFFFFF — the exchange
// helper allocated and filled arrays of that size (3.5 GB for 32 s, then a crash) — is refused before the helper
// runs: exit 3, ParseError naming the file, the entity's directory entry and K, no output.
TEST(Issue24BlobCounts, HostileIgesCountIsRefusedBeforeTheHelperRuns) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  ASSERT_EQ(hula({"convert", (dir / "c.json").string(), "-o", (dir / "c.igs").string()}).exit_code, 0);
  const std::string iges = io::read_text_file(dir / "c.igs");
  const std::size_t at = iges.find("\n126,");
  ASSERT_NE(at, std::string::npos);
  const std::size_t k_end = iges.find(',', at + 5);
  for (const std::string count : {"150000000", "4294967295"}) {
    // The parameter data keeps its 64 columns: the longer K takes the place of the shortest reals after it.
    std::string line = iges.substr(at + 1, iges.find('\n', at + 1) - at - 1);
    std::string data = "126," + count + line.substr(k_end - at - 1, 64 - (k_end - at - 1));
    for (std::size_t z; data.size() > 64 && (z = data.find("0.0000000000000000E+00")) != std::string::npos;)
      data.replace(z, 22, "0.0");
    ASSERT_LE(data.size(), 64U) << data;
    data.resize(64, ' ');
    std::string text = iges;
    text.replace(at + 1, 64, data);
    write(dir / "bad.igs", text);
    const ProcessResult r = limited({"convert", (dir / "bad.igs").string(), "-o", (dir / "out.json").string()});
    EXPECT_EQ(r.exit_code, 3) << count << ": " << r.err.substr(0, 300);
    EXPECT_EQ(error_of(r)["error"]["code"], "ParseError");
    EXPECT_NE(message_of(r).find("(type 126) states K = " + count), std::string::npos) << message_of(r);
    EXPECT_NE(message_of(r).find("bad.igs"), std::string::npos) << message_of(r);
    EXPECT_FALSE(fs::exists(dir / "out.json"));
  }
  // The file as written reads back (the check refuses only counts above what an entity holds).
  EXPECT_EQ(limited({"convert", (dir / "c.igs").string(), "-o", (dir / "back.json").string()}).exit_code, 0);
}
#endif

}  // namespace
}  // namespace hula::regress
