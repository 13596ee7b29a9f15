// Overrides reach any scenario value by path, including the controllers' parameters; a path the
// scenario does not know and a value it refuses are errors naming where the override came from.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "batch/scenario_override.hpp"
#include "batch/sweep_spec.hpp"
#include "control/params.hpp"
#include "temp_dir_util.hpp"

namespace mechsim::batch::test {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string error_of(const std::vector<Override>& o) {
  try {
    load_with_overrides(test_scenario(), o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioOverride, ReachesValuesInTheFileAndOnesTheReaderKnows) {
  const sim::Scenario base = sim::load_scenario(test_scenario());
  const sim::Scenario s = load_with_overrides(test_scenario(), {{"spawn.yaw", "0.25", "t:1"},
                                                               {"world.seed", "17", "t:2"},
                                                               {"timeline.0.twist.vx", "0.3", "t:3"},
                                                               {"checks.0.distance.min", "0.5", "t:4"},
                                                               {"duration", "1.5", "t:5"}});
  EXPECT_DOUBLE_EQ(base.spawn.yaw, 0.0);
  EXPECT_DOUBLE_EQ(s.spawn.yaw, 0.25);
  EXPECT_EQ(s.world.seed, 17u);
  ASSERT_EQ(s.timeline.size(), 1u);
  EXPECT_DOUBLE_EQ(s.timeline[0].twist.linear.x, 0.3);
  EXPECT_DOUBLE_EQ(s.checks[0].min_distance, 0.5);
  EXPECT_DOUBLE_EQ(s.duration, 1.5);
  EXPECT_EQ(s.name, base.name);
}

TEST(ScenarioOverride, ControllerParametersBecomeTheScenariosOverlay) {
  const sim::Scenario s = load_with_overrides(
      test_scenario(), {{"controllers.params.rover_drive_controller.wheel_pid.p", "6.5", "t:1"},
                        {"controllers.params.rover_drive_controller.crab_sensing_wheels", "none", "t:2"}});
  ASSERT_EQ(s.controller_params.size(), 2u);
  EXPECT_EQ(s.controller_params[0].key, "rover_drive_controller/wheel_pid/p");
  EXPECT_DOUBLE_EQ(s.controller_params[0].value.as<double>(), 6.5);
  EXPECT_EQ(s.controller_params[1].key, "rover_drive_controller/crab_sensing_wheels");
  EXPECT_EQ(s.controller_params[1].value.as<std::string>(), "none");
  // A parameter the controllers file does not have is refused (a misspelt gain must not pass).
  EXPECT_THAT(error_of({{"controllers.params.rover_drive_controller.wheel_pid.q", "1", "sweep.yaml:9: axis x"}}),
              AllOf(HasSubstr("sweep.yaml:9"), HasSubstr("controllers.params.rover_drive_controller.wheel_pid.q"),
                    HasSubstr("/cc8/rover_drive_controller/wheel_pid/q")));
}

TEST(ScenarioOverride, AnUnknownPathNamesTheOverrideAndTheKey) {
  EXPECT_THAT(error_of({{"world.sed", "3", "sweep.yaml:7: axis world.sed"}}),
              AllOf(HasSubstr("sweep.yaml:7"), HasSubstr("world.sed"), HasSubstr("no such scenario key"),
                    HasSubstr("cc8_short_drive.yaml")));
  EXPECT_THAT(error_of({{"timeline.3.twist.vx", "1", "sweep.yaml:8: axis t"}}),
              AllOf(HasSubstr("sweep.yaml:8"), HasSubstr("has 1 items: no item 3")));
  EXPECT_THAT(error_of({{"duration.x", "1", "sweep.yaml:9: axis d"}}),
              AllOf(HasSubstr("sweep.yaml:9"), HasSubstr("'duration' is a single value")));
  // Inside a timeline event the reader's own key check speaks.
  EXPECT_THAT(error_of({{"timeline.0.twist.vz", "1", "sweep.yaml:10: axis v"}}),
              AllOf(HasSubstr("sweep.yaml:10"), HasSubstr("unknown key 'vz'")));
}

TEST(ScenarioOverride, ARefusedValueNamesTheOverride) {
  EXPECT_THAT(error_of({{"world.seed", "2.5", "sweep.yaml:4: axis world.seed"}}),
              AllOf(HasSubstr("sweep.yaml:4"), HasSubstr("world.seed"), HasSubstr("expected an integer")));
  EXPECT_THAT(error_of({{"duration", "-1", "sweep.yaml:5: set: duration"}}),
              AllOf(HasSubstr("sweep.yaml:5"), HasSubstr("duration"), HasSubstr("must be in (0, 1e6] s")));
}

}  // namespace
}  // namespace mechsim::batch::test
