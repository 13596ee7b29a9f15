// xacro: the lean xacro program, `xacro FILE [name:=value ...] [-o OUT]` as ROS's. It links the
// description layer only: roslaunch runs xacro as a command for every robot, and `mechsim xacro`
// spends most of its start-up loading and relocating the physics and simulation libraries'
// shared dependencies (MuJoCo, assimp, image codecs) that expanding a document never touches.
// Exit status: 0 success, 1 user error.
#include <exception>
#include <iostream>

#include "apps/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"xacro (mechsim): expand a xacro file to URDF, as ROS's xacro (in-order processing)"};
  mechsim::apps::add_xacro_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "xacro: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
