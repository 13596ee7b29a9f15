// gazebo_ros_init's world services (std_srvs/srv/Empty) called by clients of both default
// middlewares' framings (service.hpp): Cyclone DDS in rmw_cyclonedds_cpp's (header in the
// payload, "clientid" USER_DATA) and Fast DDS in rmw_fastrtps_cpp's (related_sample_identity);
// /clock shows the world paused and running again. Humble and Jazzy, each client pausing once.
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

class ServiceWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

double seconds_of(const nlohmann::json& t) { return t["sec"].get<double>() + 1e-9 * t["nanosec"].get<double>(); }

nlohmann::json call_line(const std::vector<nlohmann::json>& lines) {
  for (const auto& l : lines)
    if (l.contains("service")) return l;
  return {};
}

// The simulated time /clock covered while the peer listened (s), and the wall time (s).
std::pair<double, double> clock_spans(const std::vector<nlohmann::json>& lines) {
  const auto s = summary(lines, "/clock");
  if (s.is_null() || s["count"].get<int>() < 2) return {-1.0, 0.0};
  return {seconds_of(s["last"]["clock"]) - seconds_of(first_sample(lines, "/clock")["clock"]), s["span"].get<double>()};
}

TEST_P(ServiceWire, PauseAndUnpauseFromBothMiddlewares) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  const std::vector<std::string> pause{"--call", "/pause_physics=empty", "--sub", "/clock=clock", "--seconds", "1.5"};
  const std::vector<std::string> unpause{"--call", "/unpause_physics=empty", "--sub", "/clock=clock", "--seconds", "1.5"};
  // Humble: rmw_fastrtps pauses, rmw_cyclonedds resumes; Jazzy the other way round.
  const bool fast_pauses = distro == "humble";
  const auto paused = fast_pauses ? run_fastdds(distro, pause, "pause") : run_cyclone(distro, pause, "pause");
  const auto resumed = fast_pauses ? run_cyclone(distro, unpause, "unpause") : run_fastdds(distro, unpause, "unpause");
  const std::string log = stop_mechsim();

  const auto p = call_line(paused), r = call_line(resumed);
  ASSERT_FALSE(p.is_null()) << log;
  ASSERT_FALSE(r.is_null()) << log;
  EXPECT_TRUE(p["available"].get<bool>()) << p;
  EXPECT_TRUE(p["reply"].get<bool>()) << p << "\n" << log;
  EXPECT_EQ(p["form"], fast_pauses ? "rmw_fastrtps" : "rmw_cyclonedds");
  EXPECT_TRUE(r["reply"].get<bool>()) << r << "\n" << log;
  EXPECT_EQ(r["form"], fast_pauses ? "rmw_cyclonedds" : "rmw_fastrtps");

  // Paused: /clock keeps coming (10 Hz of wall time) with the time standing still (the
  // transient-local history the subscription got first spans a few ticks before the pause).
  const auto [paused_sim, paused_wall] = clock_spans(paused);
  EXPECT_GT(paused_wall, 1.0);
  EXPECT_GE(paused_sim, 0.0);
  EXPECT_LT(paused_sim, 0.05);
  // Running again: about as much simulated time as wall time.
  const auto [running_sim, running_wall] = clock_spans(resumed);
  EXPECT_GT(running_sim, 0.7 * running_wall) << running_sim << " s simulated in " << running_wall << " s";
}

INSTANTIATE_TEST_SUITE_P(Distros, ServiceWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
