// SPDX-License-Identifier: MIT
// Issue 24, items 9 and 17 (server): `hula serve --token-file /dev/zero` read
// without limit and never started, a FIFO token file blocked forever; the
// Bearer scheme was case-sensitive (RFC 7235 makes it case-insensitive); two
// Host headers were accepted, the first winning. The same over a real socket is
// in tests/server/server_test.py (SecurityTest).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hula/core/error.hpp"
#include "hula/server/security.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::regress {
namespace {

namespace fs = std::filesystem;

// checks: /dev/zero, a FIFO without a writer and a file over the 4 KiB cap are refused (IoError, field
// token-file) at once, without reading them; a regular file's first line is the token.
TEST(Issue24ServerRequests, TokenFileIsCappedAndNeverAStream) {
  testing::TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  std::ofstream(dir / "big") << std::string(server::kMaxTokenFileBytes + 1, 'a');
  for (const fs::path& p : {fs::path("/dev/zero"), dir / "fifo", dir / "big"}) {
    try {
      (void)server::read_token_file(p);
      ADD_FAILURE() << p << " was read as a token file";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::IoError) << p;
      EXPECT_EQ(e.where().field, "token-file") << p;
      EXPECT_NE(e.message().find(p.string()), std::string::npos) << e.message();
    }
  }
  const std::string token(40, 'k');
  std::ofstream(dir / "token") << "  " << token << "\nsecond line\n";
  EXPECT_EQ(server::read_token_file(dir / "token"), token);
}

server::RequestHead api_request(const std::string& authorization) {
  server::RequestHead h;
  h.method = "GET";
  h.target = "/api/jobs/1";
  h.host = "127.0.0.1:8123";
  h.authorization = authorization;
  return h;
}

// checks: the Bearer scheme in any case, followed by one or more spaces, authorises; another scheme or a
// wrong token does not.
TEST(Issue24ServerRequests, BearerSchemeIsCaseInsensitive) {
  server::SecurityPolicy p;
  p.token = std::string(64, 'a');
  p.allowed_hosts = server::allowed_hosts("127.0.0.1", 8123);
  for (const std::string scheme : {"Bearer ", "bearer ", "BEARER ", "bEaReR  "})
    EXPECT_FALSE(server::check_request(api_request(scheme + p.token), p)) << scheme;
  for (const std::string& wrong : {"Basic " + p.token, "Bearer" + p.token, "bearer " + std::string(64, 'b')}) {
    const auto refusal = server::check_request(api_request(wrong), p);
    ASSERT_TRUE(refusal) << wrong;
    EXPECT_EQ(refusal->status(), 401U) << wrong;
  }
}

// checks: a request with two Host headers is refused with 400 BadRequest before the Host check (even when the
// first one is this server's).
TEST(Issue24ServerRequests, DuplicateHostIsRefused) {
  server::SecurityPolicy p;
  p.token = std::string(64, 'a');
  p.allowed_hosts = server::allowed_hosts("127.0.0.1", 8123);
  server::RequestHead h = api_request("Bearer " + p.token);
  h.host_count = 2;
  const auto refusal = server::check_request(h, p);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->status(), 400U);
  EXPECT_EQ(refusal->code(), "BadRequest");
  h.host_count = 1;
  EXPECT_FALSE(server::check_request(h, p));
}

}  // namespace
}  // namespace hula::regress
