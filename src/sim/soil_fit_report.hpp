#pragma once
// `mechsim soil fit`: reads a fit's description (which plate-sinkage and shear tests, in which
// files, with which plates), fits the soil's constants (physics/soil_fit.hpp) and writes a soil
// file worlds and scenarios can name (sim/soil_config.hpp), the fit's residuals and a plot.
//
//   name: cmu_sand                  # the soil's name
//   base: dry_sand                  # what the tests do not give (c, phi and K without shear
//                                   # tests; c1, c2, bedrock): a named soil or a soil file
//   model: ding                     # the wheel-soil model the soil uses: ding (default) | wong_reece
//   method: two_stage               # plate fit: two_stage (default) | direct (physics/soil_fit.hpp)
//   values: {friction_angle_deg: 29}   # optional: values measured elsewhere (soil file keys),
//                                      # laid over the base; the tests' constants are laid last
//   plates:                         # plate-sinkage tests, two sizes or more
//     - diameter: 0.060             # a circular plate (m): Bekker's b is its radius
//       files: [plates/a_1.tsv, plates/a_2.tsv]    # relative to this file
//     - {width: 0.05, length: 0.25, files: [...]} # a rectangular plate: b is its width
//   plates_columns: {z: z_m, p: pressure_Pa}      # default; or {z: z_m, force: force_N}: p = F / area
//   shear:                          # optional: shear tests, two normal pressures or more
//     - {normal_pressure: 5000, files: [shear/5kPa.tsv]}   # Pa
//   shear_columns: {j: j_m, tau: tau_Pa}          # default
//
// Test files are text tables: lines starting with '#' are comments, the first other line names
// the columns (tab-, comma- or space-separated), every later line is numbers (SI units).

#include <optional>
#include <string>
#include <vector>

#include "physics/soil.hpp"
#include "physics/soil_fit.hpp"

namespace mechsim::sim {

struct SoilFitSpec {
  std::string file;  // the description's path
  std::string name;
  std::string base = "dry_sand";
  physics::WheelSoilModel model = physics::WheelSoilModel::Ding;
  physics::PlateFitMethod method = physics::PlateFitMethod::TwoStage;
  physics::SoilParameters start;  // the base with `values` laid over it
  std::vector<std::string> given;  // the soil keys `values` set
  std::vector<physics::PlateTest> plates;
  std::vector<physics::ShearTest> shear;
};

// Reads the description and every test file it names. Throws ScenarioError naming the file, the
// line and the key (or the test file and its line).
SoilFitSpec read_soil_fit_spec(const std::string& path);

struct SoilFitOutcome {
  physics::SoilParameters soil;
  physics::PlateFit plates;
  std::optional<physics::ShearFit> shear;
  std::vector<std::string> not_from_tests;  // the soil's constants that came from base or values
  std::vector<std::string> files;           // written, relative to the output folder
  std::vector<std::string> warnings;
  std::string summary;                      // what `mechsim soil fit` prints
};

// Fits, and with `out_dir` writes <name>.soil.yaml, plate_fit.tsv (every sample with the model's
// pressure and the residual), plate_fit.png (with `plots`) and, with shear tests, shear_fit.tsv
// and shear_fit.png. Throws std::invalid_argument (a fit that cannot be made, a soil that fails
// physics::check_soil) or std::runtime_error (the folder cannot be written).
SoilFitOutcome run_soil_fit(const SoilFitSpec& spec, const std::string& out_dir, bool plots);

}  // namespace mechsim::sim
