// `mechsim world` run as a user would: statistics, export and re-load, features, bad input.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// One folder per test process: CTest runs the tests of this program in parallel processes, which
// must not share output files.
// Removed when the program ends (tests reuse it).
fs::path scratch() {
  struct Folder {
    fs::path path = fs::temp_directory_path() / ("mechsim_world_cli_test_" + std::to_string(::getpid()));
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  fs::create_directories(folder.path);
  return folder.path;
}

// Runs `mechsim ARGS` through the shell (arguments are quoted by the caller where needed),
// bounded by coreutils' timeout so that a hang fails instead of blocking.
CliRun mechsim(const std::string& args) {
  const fs::path dir = scratch();
  const std::string cmd = "timeout 120 '" + std::string(MECHSIM_EXE) + "' " + args + " >'" + (dir / "out").string() +
                          "' 2>'" + (dir / "err").string() + "' </dev/null";
  const int status = std::system(cmd.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(dir / "out");
  run.err = slurp(dir / "err");
  return run;
}

std::string line_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) return line;
  }
  return "(no line starting with '" + prefix + "')";
}

TEST(WorldCli, StatsOfTheGeneratedYard) {
  const CliRun run = mechsim("world stats mars_yard_2024 --seed 7");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("mars_yard_2024 (seed 7)"));
  EXPECT_THAT(run.out, HasSubstr("usable area  37.50 m x 24.00 m = 900.0 m^2"));
  EXPECT_THAT(run.out, HasSubstr("811 x 541 samples"));
  EXPECT_THAT(line_starting(run.out, "slope"), HasSubstr("median 1"));
  EXPECT_THAT(run.out, HasSubstr("8 craters"));
}

TEST(WorldCli, StatsOfTheEmptyWorld) {
  const CliRun run = mechsim("world stats empty");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("flat ground plane"));
}

TEST(WorldCli, StatsOfThe2022ElevationModel) {
  const fs::path model = fs::path(MECHSIM_SHARED_DIR) / "terrain" / "marsyard2022_heightmap.tif";
  if (!fs::exists(model)) GTEST_SKIP() << "shared terrain data absent: " << model;
  const CliRun run = mechsim("world stats '" + model.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("257 x 257 samples"));
  EXPECT_THAT(run.out, HasSubstr("50.00 m x 50.00 m"));
  EXPECT_THAT(run.out, HasSubstr("median 10.7 deg"));
  EXPECT_THAT(run.out, HasSubstr("7.2 % of the area steeper than 30 deg"));
}

TEST(WorldCli, ExportedImagesLoadBackWithTheSameTerrain) {
  const fs::path dir = scratch();
  fs::remove(dir / "yard.png");
  fs::remove(dir / "yard.tif");
  const CliRun png = mechsim("world export mars_yard_2024 --seed 3 -o '" + (dir / "yard.png").string() + "'");
  ASSERT_EQ(png.exit_code, 0) << png.err;
  EXPECT_THAT(png.out, HasSubstr("16-bit grayscale PNG"));
  EXPECT_THAT(png.out, HasSubstr("0 = 0.0000 m"));
  const CliRun tif = mechsim("world export mars_yard_2024 --seed 3 -o '" + (dir / "yard.tif").string() + "'");
  ASSERT_EQ(tif.exit_code, 0) << tif.err;
  ASSERT_TRUE(fs::exists(dir / "yard.png"));
  ASSERT_TRUE(fs::exists(dir / "yard.tif"));

  const CliRun generated = mechsim("world stats mars_yard_2024 --seed 3");
  const CliRun from_tif = mechsim("world stats '" + (dir / "yard.tif").string() + "'");
  const CliRun from_png = mechsim("world stats '" + (dir / "yard.png").string() + "'");
  ASSERT_EQ(from_tif.exit_code, 0) << from_tif.err;
  ASSERT_EQ(from_png.exit_code, 0) << from_png.err;
  // A file has no usable-area margin, so compare footprint and whole-map heights.
  EXPECT_EQ(line_starting(from_tif.out, "grid"), line_starting(generated.out, "grid"));
  EXPECT_EQ(line_starting(from_tif.out, "footprint"), line_starting(generated.out, "footprint"));
  EXPECT_EQ(line_starting(from_png.out, "footprint"), line_starting(generated.out, "footprint"));
  EXPECT_EQ(line_starting(from_png.out, "heights"), line_starting(from_tif.out, "heights"));
  EXPECT_EQ(line_starting(from_png.out, "slope"), line_starting(from_tif.out, "slope"));
}

TEST(WorldCli, FeaturesListTheYard) {
  const CliRun run = mechsim("world features mars_yard_2024");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::istringstream in(run.out);
  int craters = 0, rocks = 0, starts = 0, mounds = 0;
  for (std::string line; std::getline(in, line);) {
    craters += line.rfind("crater ", 0) == 0;
    rocks += line.rfind("rock ", 0) == 0;
    starts += line.rfind("start ", 0) == 0;
    mounds += line.rfind("mound ", 0) == 0;
  }
  EXPECT_EQ(craters, 8);
  EXPECT_EQ(starts, 1);
  EXPECT_GE(mounds, 2);
  EXPECT_GT(rocks, 300);
  EXPECT_THAT(run.out, HasSubstr("canyon "));
  EXPECT_THAT(run.out, HasSubstr("river "));
  EXPECT_THAT(run.out, HasSubstr("dunes "));
}

TEST(WorldCli, BadInputExitsOneWithAMessage) {
  const fs::path dir = scratch();
  std::ofstream(dir / "notes.png") << "not an image\n";
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"world stats nowhere_world", "unknown world 'nowhere_world'"},
      {"world stats '" + (dir / "notes.png").string() + "'", "not a PNG or TIFF image"},
      {"world export empty -o '" + (dir / "e.png").string() + "'", "has no heightmap"},
      {"world export mars_yard_2024 -o '" + (dir / "y.jpg").string() + "'", "unknown image type"},
      {"world stats empty --seed 3", "--seed applies to mars_yard_2024 only"},
      {"world stats mars_yard_2024 --size-x 3", "apply to heightmap files only"},
      {"world features empty", "has no feature list"},
      {"world stats", "WORLD is required"},
  };
  for (const Case& c : cases) {
    const CliRun run = mechsim(c.args);
    EXPECT_EQ(run.exit_code, 1) << c.args;
    EXPECT_THAT(run.err, HasSubstr(c.expected)) << c.args;
  }
}

}  // namespace
}  // namespace mechsim::apps::test
