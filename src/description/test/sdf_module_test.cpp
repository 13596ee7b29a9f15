// The SDF module (description/sdf/sdf_module.hpp): this build's module loads and reads SDF; files
// that are absent, not shared objects, or shared objects of something else are passed over, each
// named with the reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "description/sdf/sdf_model.hpp"
#include "description/sdf/sdf_module.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kModule = std::string(MECHSIM_BINARY_DIR) + "/lib/" + sdf_detail::kSdfModuleFile;

TEST(SdfModule, ThisBuildsModuleReadsAModel) {
  const sdf_detail::SdfModuleLoad loaded = sdf_detail::load_sdf_module({"/nonexistent/first.so", kModule});
  ASSERT_NE(loaded.api, nullptr) << loaded.error;
  SdfModel model;
  const std::string error = loaded.api->parse_model(
      "<sdf version='1.6'><model name='ball'><link name='b'><inertial><mass>0.5</mass></inertial></link></model></sdf>",
      "<ball>", SdfOptions{{}, {}, false}, model);
  EXPECT_EQ(error, "");
  EXPECT_EQ(model.name, "ball");
  ASSERT_EQ(model.robot.links.size(), 1u);
  EXPECT_DOUBLE_EQ(model.robot.links[0].inertial->mass, 0.5);
  // An SdfError inside the module comes back as its message.
  SdfModel none;
  EXPECT_THAT(loaded.api->parse_model("not xml", "<junk>", SdfOptions{{}, {}, false}, none), HasSubstr("<junk>"));
}

TEST(SdfModule, FilesPassedOverAreNamedWithTheReason) {
  const fs::path text = fs::temp_directory_path() / ("mechsim_sdf_module_test_" + std::to_string(::getpid()) + ".so");
  std::ofstream(text) << "not a shared object\n";
  // A shared object every Debian system has, which is not the module.
  const std::string other = "/lib/x86_64-linux-gnu/libz.so.1";
  const sdf_detail::SdfModuleLoad loaded = sdf_detail::load_sdf_module({"/nonexistent/libmechsim_sdformat.so", text.string(), other});
  fs::remove(text);
  EXPECT_EQ(loaded.api, nullptr);
  EXPECT_THAT(loaded.error, HasSubstr("SDF support is unavailable: cannot load libmechsim_sdformat.so"));
  EXPECT_THAT(loaded.error, HasSubstr("/nonexistent/libmechsim_sdformat.so (absent)"));
  EXPECT_THAT(loaded.error, HasSubstr(text.string() + " ("));
  if (fs::exists(other)) {
    EXPECT_THAT(loaded.error, HasSubstr(other + " (not this build's SDF module)"));
  }
  EXPECT_EQ(sdf_detail::load_sdf_module({}).api, nullptr);
}

}  // namespace
}  // namespace mechsim::description
