// SPDX-License-Identifier: MIT
// Unit tests of the security middleware's pieces (server/security.hpp); the
// same refusals over a real socket are in server_test.py.
#include "hula/server/security.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace hula::server {
namespace {

SecurityPolicy policy() {
  SecurityPolicy p;
  p.token = std::string(64, 'a');
  p.allowed_hosts = allowed_hosts("127.0.0.1", 8123);
  p.max_body = 1000;
  return p;
}

RequestHead head(std::string_view target) {
  RequestHead h;
  h.method = "GET";
  h.target = target;
  h.host = "127.0.0.1:8123";
  return h;
}

// checks equality and inequality of equal- and unequal-length strings against ==
TEST(Security, ConstantTimeEqualAgreesWithEquality) {
  EXPECT_TRUE(constant_time_equal("abc", "abc"));
  EXPECT_FALSE(constant_time_equal("abc", "abd"));
  EXPECT_FALSE(constant_time_equal("abc", "abcd"));
  EXPECT_FALSE(constant_time_equal("", "a"));
  EXPECT_TRUE(constant_time_equal("", ""));
}

// checks generated tokens are 64 hex digits (256 bits) and differ between calls
TEST(Security, GeneratedTokensAre256RandomBits) {
  const std::string a = generate_token();
  const std::string b = generate_token();
  EXPECT_EQ(a.size(), 64u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, b);
}

// checks the middleware's status for each refusal against the issue's table
TEST(Security, RefusalsCarryTheirStatus) {
  const SecurityPolicy p = policy();
  RequestHead h = head("/api/jobs/1");
  EXPECT_EQ(check_request(h, p)->status(), 401u);
  const std::string bearer = "Bearer " + p.token;
  h.authorization = bearer;
  EXPECT_FALSE(check_request(h, p));
  h.host = "evil.example";
  EXPECT_EQ(check_request(h, p)->status(), 403u);
  h.host = "LOCALHOST:8123";
  EXPECT_FALSE(check_request(h, p));
  h.origin = "http://evil.example";
  EXPECT_EQ(check_request(h, p)->code(), "ForbiddenOrigin");
  h.origin = "http://[::1]:8123";
  EXPECT_FALSE(check_request(h, p));
  h.content_length = 1001;
  EXPECT_EQ(check_request(h, p)->status(), 413u);
  h.content_length = 1000;
  EXPECT_FALSE(check_request(h, p));
  RequestHead health = head("/api/health");
  EXPECT_FALSE(check_request(health, p));
  health.method = "POST";
  EXPECT_EQ(check_request(health, p)->status(), 401u);
  const std::string long_target(p.max_target + 1, 'x');
  EXPECT_EQ(check_request(head(long_target), p)->status(), 414u);
}

// checks the cookie form of the token among other cookies
TEST(Security, TokenCookieIsAccepted) {
  const SecurityPolicy p = policy();
  RequestHead h = head("/api/jobs/1");
  const std::string good = "theme=dark; hula_token=" + p.token + "; x=y";
  h.cookie = good;
  EXPECT_FALSE(check_request(h, p));
  const std::string bad = "hula_token=" + std::string(64, 'b');
  h.cookie = bad;
  EXPECT_EQ(check_request(h, p)->status(), 401u);
}

// checks document names: plain *.hula names pass, traversal, absolute and hidden names are refused naming the rule
TEST(Security, DocumentNamesArePlainFileNames) {
  EXPECT_NO_THROW(validate_document_name("wing profile.hula"));
  for (const char* bad :
       {"", "..", "../x.hula", "/etc/passwd", "a/b.hula", "a\\b.hula", ".x.hula", "x.txt", ".hula", "a..b.hula"}) {
    try {
      validate_document_name(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::InvalidArgument);
      EXPECT_EQ(e.where().field, "name");
    }
  }
  EXPECT_EQ(check_request(head("/api/documents/..%2Fx.hula"), policy())->status(), 401u);  // token first
  SecurityPolicy p = policy();
  RequestHead h = head("/api/documents/..%2Fx.hula/entities");
  const std::string bearer = "Bearer " + p.token;
  h.authorization = bearer;
  EXPECT_EQ(check_request(h, p)->status(), 400u);
}

// checks a symbolic link in the workspace is refused as a document
TEST(Security, SymlinkDocumentsAreRefused) {
  const auto dir = std::filesystem::temp_directory_path() / ("hula-security-test-" + generate_token().substr(0, 8));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "real.hula") << "x";
  std::filesystem::create_symlink("/etc/passwd", dir / "link.hula");
  EXPECT_EQ(document_path(dir, "real.hula"), dir / "real.hula");
  EXPECT_THROW((void)document_path(dir, "link.hula"), Error);
  std::filesystem::remove_all(dir);
}

// checks the JSON depth count skips brackets inside strings and stops past the limit
TEST(Http, JsonNestingDepth) {
  EXPECT_EQ(json_nesting_depth(R"({"a": [1, {"b": "[[[["}]})", 64), 3u);
  EXPECT_EQ(json_nesting_depth(R"("\"[")", 64), 0u);
  EXPECT_EQ(json_nesting_depth(std::string(1000, '['), 10), 11u);
}

// checks percent decoding against hand-decoded strings and refuses malformed escapes
TEST(Http, PercentDecode) {
  EXPECT_EQ(percent_decode("a%20b%2Fc+d"), "a b/c+d");
  EXPECT_THROW((void)percent_decode("%2"), HttpError);
  EXPECT_THROW((void)percent_decode("%zz"), HttpError);
  EXPECT_THROW((void)percent_decode("%00"), HttpError);
  EXPECT_EQ(parse_query("token=abc&x=1%262").at("x"), "1&2");
}

}  // namespace
}  // namespace hula::server
