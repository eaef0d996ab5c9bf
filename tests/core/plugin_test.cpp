// SPDX-License-Identifier: MIT
// hula::plugin_symbol (hula/core/plugin.hpp): where plugins are looked for and what a missing plugin or entry
// point reports. The real Ceres plugin of this build (libhula_ceres.so, built beside the tests) is the
// plugin that exists.
#include "hula/core/plugin.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "hula/core/error.hpp"
#include "hula/testing/temp_dir.hpp"

namespace {

// HULA_PLUGIN_DIR set for the scope of one test.
class PluginDir {
 public:
  explicit PluginDir(const std::string& dir) { ::setenv("HULA_PLUGIN_DIR", dir.c_str(), 1); }
  ~PluginDir() { ::unsetenv("HULA_PLUGIN_DIR"); }
  PluginDir(const PluginDir&) = delete;
  PluginDir& operator=(const PluginDir&) = delete;
};

// checks: a plugin no directory holds is an IoError on field "plugin" naming its file, the HULA_PLUGIN_DIR
// directory first among those tried, and how to name another directory
TEST(Plugin, MissingPluginNamesItsFileAndEveryDirectoryTried) {
  const hula::testing::TempDir dir;
  const PluginDir env(dir.path().string());
  try {
    (void)hula::plugin_symbol("no_such_plugin", "hula_entry");
    FAIL() << "no error";
  } catch (const hula::Error& e) {
    EXPECT_EQ(e.code(), hula::Errc::IoError);
    EXPECT_EQ(e.where().field, "plugin");
    const std::string message = e.message();
    const std::string first = (dir.path() / "libhula_no_such_plugin.so").string();
    EXPECT_NE(message.find("the no_such_plugin plugin libhula_no_such_plugin.so is not installed"), std::string::npos)
        << message;
    EXPECT_NE(message.find("(looked for " + first + ", "), std::string::npos) << message;
    EXPECT_NE(message.find("HULA_PLUGIN_DIR"), std::string::npos) << message;
  }
}

// checks: a plugin that exists but lacks the entry point asked for is an IoError naming the plugin's path and
// the symbol; its real entry point is found
TEST(Plugin, MissingEntryPointNamesThePluginsPathAndTheSymbol) {
  EXPECT_NE(hula::plugin_symbol("ceres", "hula_ceres_solve"), nullptr);
  try {
    (void)hula::plugin_symbol("ceres", "hula_no_such_entry");
    FAIL() << "no error";
  } catch (const hula::Error& e) {
    EXPECT_EQ(e.code(), hula::Errc::IoError);
    EXPECT_EQ(e.where().field, "plugin");
    EXPECT_NE(e.message().find("/libhula_ceres.so has no entry point hula_no_such_entry"), std::string::npos)
        << e.message();
  }
}

}  // namespace
