// Soils as scenarios name them (sim/soil_config.hpp): named sets, soil files (what `mechsim soil
// fit` writes, read back to the same values), the user's values with the model's keys; which
// links are wheels (sim/wheel_config.hpp); the fit's description (sim/soil_fit_report.hpp) with
// its errors named.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "sim/scenario.hpp"
#include "sim/soil_config.hpp"
#include "sim/soil_fit_report.hpp"
#include "sim/wheel_config.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

class SoilConfig : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_soil_config_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(SoilConfig, ASoilFileReadsBackToTheValuesItWasWrittenFrom) {
  physics::SoilParameters s = *physics::find_soil("lete_sand");
  s.name = "my \"sand\"";
  s.source = "fitted";
  s.k_c = -1.5e5;
  s.k_phi = 9e6;
  s.model = physics::WheelSoilModel::Ding;
  s.rear_ratio = 0.07;
  s.n1 = 0.3;
  s.n2 = 0.2;
  s.multi_pass = true;
  write("s.soil.yaml", soil_yaml(s, "a comment\nof two lines"));
  const physics::SoilParameters r = soil_by_name("s.soil.yaml", dir_);
  EXPECT_EQ(r.name, s.name);
  EXPECT_EQ(r.source, s.source);
  EXPECT_EQ(r.model, s.model);
  for (const auto& [a, b] : {std::pair{r.n, s.n}, {r.k_c, s.k_c}, {r.k_phi, s.k_phi}, {r.cohesion, s.cohesion},
                             {r.friction_angle, s.friction_angle}, {r.shear_modulus, s.shear_modulus}, {r.c1, s.c1}, {r.c2, s.c2},
                             {r.rear_ratio, s.rear_ratio}, {r.n1, s.n1}, {r.n2, s.n2}, {r.bedrock_depth, s.bedrock_depth}})
    EXPECT_NEAR(a, b, 1e-5 * std::abs(b));
  EXPECT_TRUE(r.multi_pass);
  // A scenario names it by its path (relative to the scenario), or lays values over it.
  const control::Params over = control::Params::from_yaml_string("{base: s.soil.yaml, model: wong_reece, n1: 0.1}");
  const physics::SoilParameters o = read_soil(over, dir_);
  EXPECT_EQ(o.model, physics::WheelSoilModel::WongReece);
  EXPECT_DOUBLE_EQ(o.n1, 0.1);
  EXPECT_NEAR(o.k_c, s.k_c, 1e-5 * std::abs(s.k_c));
  EXPECT_EQ(o.name, s.name + " (modified)");
}

TEST_F(SoilConfig, BadSoilsAreNamedWithTheirPlace) {
  const auto error = [&](const std::string& yaml) {
    try {
      read_soil(control::Params::from_yaml_string("soil: " + yaml, "scenario.yaml").child("soil"), dir_);
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("missing.soil.yaml").find("not found"), std::string::npos);
  EXPECT_NE(error("{base: dry_sand, model: bekker}").find("unknown model 'bekker'"), std::string::npos);
  EXPECT_NE(error("{base: dry_sand, rear_ratio: 2}").find("rear ratio"), std::string::npos);
  EXPECT_NE(error("{base: dry_sand, name: x}").find("unknown key 'name'"), std::string::npos);
  write("noname.soil.yaml", "n: 1.0\nk_phi: 1e6\n");
  EXPECT_NE(error("noname.soil.yaml").find("needs a name"), std::string::npos);
  write("bad.soil.yaml", "name: b\nbase: dry_sand\n");
  EXPECT_NE(error("bad.soil.yaml").find("unknown key 'base'"), std::string::npos);
}

TEST(WheelConfig, LinksAreMadeWheelsOrNotWithDimensionsAndGrousers) {
  const control::Params node = control::Params::from_yaml_string(
      "{caster: false, wheel: {grousers: {height: 0.005, count: 12}}, hub: {radius: 0.1, width: 0.04}, other: true}", "s.yaml");
  const std::vector<physics::WheelOverride> o = read_wheel_overrides(node);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_EQ(o[0].link, "caster");
  EXPECT_FALSE(o[0].wheel);
  EXPECT_EQ(o[1].grouser_count, 12);
  EXPECT_DOUBLE_EQ(o[1].grouser_height, 0.005);
  EXPECT_DOUBLE_EQ(*o[2].radius, 0.1);
  EXPECT_DOUBLE_EQ(*o[2].width, 0.04);
  EXPECT_TRUE(o[3].wheel);
  for (const char* bad : {"{w: {radius: -1}}", "{w: {diameter: 0.1}}", "{w: {grousers: {height: 0.01, count: 0}}}", "{w: maybe}", "[w]"})
    EXPECT_THROW(read_wheel_overrides(control::Params::from_yaml_string(std::string("wheels: ") + bad, "s.yaml").child("wheels")), ScenarioError)
        << bad;
}

TEST_F(SoilConfig, AFitDescriptionReadsItsTestsAndNamesWhatIsWrong) {
  // Two plate sizes from known constants (n 1.2, k_c 2e4, k_phi 5e6), one as forces.
  const auto plate = [&](const std::string& name, double b, bool force) {
    std::string text = "# a comment\n" + std::string(force ? "z_m\tforce_N\n" : "z_m,pressure_Pa\n");
    for (int i = 1; i <= 50; ++i) {
      const double z = 0.0005 * i, p = (2e4 / b + 5e6) * std::pow(z, 1.2);
      text += std::to_string(z) + (force ? "\t" + std::to_string(p * M_PI * b * b) : "," + std::to_string(p)) + "\n";
    }
    write(name, text);
  };
  plate("a.tsv", 0.03, false);
  plate("b.tsv", 0.05, false);
  const fs::path spec = write("tests.yaml", "name: t\nbase: dry_sand\nmodel: wong_reece\nvalues: {friction_angle_deg: 31}\n"
                                            "plates:\n  - {diameter: 0.06, files: [a.tsv]}\n  - {diameter: 0.10, files: b.tsv}\n");
  const SoilFitSpec s = read_soil_fit_spec(spec.string());
  ASSERT_EQ(s.plates.size(), 2u);
  EXPECT_DOUBLE_EQ(s.plates[0].b, 0.03);
  const SoilFitOutcome out = run_soil_fit(s, (dir_ / "out").string(), false);
  EXPECT_NEAR(out.soil.n, 1.2, 1e-4);
  EXPECT_NEAR(out.soil.k_c, 2e4, 0.01 * 2e4);
  EXPECT_NEAR(out.soil.friction_angle, 31.0 * M_PI / 180.0, 1e-12) << "values are laid over the base";
  EXPECT_EQ(out.soil.model, physics::WheelSoilModel::WongReece);
  EXPECT_TRUE(fs::exists(dir_ / "out/t.soil.yaml"));
  EXPECT_TRUE(fs::exists(dir_ / "out/plate_fit.tsv"));
  EXPECT_NEAR(soil_by_name((dir_ / "out/t.soil.yaml").string()).k_phi, out.soil.k_phi, 1e-5 * out.soil.k_phi);

  // Shear tests at two normal pressures (c 800 Pa, phi 30 deg, K 3 mm): the soil takes c, phi, K
  // from them, not from the base.
  for (const double sigma : {4000.0, 12000.0}) {
    std::string text = "j_m tau_Pa\n";
    for (int i = 0; i <= 40; ++i) {
      const double j = 0.0005 * i;
      text += std::to_string(j) + " " + std::to_string((800.0 + sigma * std::tan(30.0 * M_PI / 180.0)) * (1.0 - std::exp(-j / 0.003))) + "\n";
    }
    write("shear_" + std::to_string(static_cast<int>(sigma)) + ".tsv", text);
  }
  const fs::path with_shear = write("shear.yaml", "plates:\n  - {diameter: 0.06, files: [a.tsv]}\n  - {diameter: 0.10, files: [b.tsv]}\n"
                                                  "shear:\n  - {normal_pressure: 4000, files: [shear_4000.tsv]}\n"
                                                  "  - {normal_pressure: 12000, files: [shear_12000.tsv]}\n");
  const SoilFitOutcome sheared = run_soil_fit(read_soil_fit_spec(with_shear.string()), (dir_ / "out2").string(), false);
  ASSERT_TRUE(sheared.shear);
  EXPECT_NEAR(sheared.soil.cohesion, 800.0, 2.0);
  EXPECT_NEAR(sheared.soil.friction_angle, 30.0 * M_PI / 180.0, 1e-3);
  EXPECT_NEAR(sheared.soil.shear_modulus, 0.003, 1e-5);
  EXPECT_TRUE(fs::exists(dir_ / "out2/shear_fit.tsv"));
  EXPECT_EQ(sheared.soil.model, physics::WheelSoilModel::Ding) << "the default for fitted soils";

  plate("f.tsv", 0.03, true);
  const fs::path forces = write("forces.yaml", "plates_columns: {z: z_m, force: force_N}\nplates:\n  - {diameter: 0.06, files: [f.tsv]}\n"
                                               "  - {width: 0.05, length: 0.05, files: [f.tsv]}\n");
  EXPECT_NO_THROW(read_soil_fit_spec(forces.string()));
  const auto error = [&](const std::string& yaml) {
    try {
      read_soil_fit_spec(write("e.yaml", yaml).string());
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("plates:\n  - {diameter: 0.06, files: [nope.tsv]}\n").find("nope.tsv"), std::string::npos);
  EXPECT_NE(error("plates:\n  - {diameter: 0.06, width: 0.1, files: [a.tsv]}\n").find("circular (diameter) or rectangular"), std::string::npos);
  EXPECT_NE(error("plates_columns: {z: depth}\nplates:\n  - {diameter: 0.06, files: [a.tsv]}\n").find("no column 'depth'"), std::string::npos);
  EXPECT_NE(error("plate: []\n").find("unknown key 'plate'"), std::string::npos);
  write("nan.tsv", "z_m,pressure_Pa\n0.001,abc\n");
  EXPECT_NE(error("plates:\n  - {diameter: 0.06, files: [nan.tsv]}\n").find("nan.tsv:2"), std::string::npos);
}

}  // namespace
}  // namespace mechsim::sim
