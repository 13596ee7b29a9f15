// mechsim: the command-line entry point. Exit status: 0 success, 1 user error, never a crash.

#include <algorithm>
#include <exception>
#include <iostream>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "apps/commands.hpp"

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

// CLI11 reads an unknown first word as a stray argument ("A subcommand is required", or the
// main help with status 0 when --help follows): the word is named here, with the closest command.
bool unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;  // the main options take no values
  const std::string_view word = argv[1];
  std::string closest;
  std::size_t best = std::string::npos;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(std::string(word))) return false;
    const std::size_t d = edit_distance(word, sub->get_name());
    if (d < best) best = d, closest = sub->get_name();
  }
  std::cerr << "mechsim: error: unknown subcommand '" << word << "'";
  if (best <= std::max<std::size_t>(2, word.size() / 3)) std::cerr << " (did you mean '" << closest << "'?)";
  std::cerr << "\nsubcommands:";
  for (const CLI::App* sub : app.get_subcommands({})) std::cerr << " " << sub->get_name();
  std::cerr << "\nrun 'mechsim --help' for more\n";
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mechsim::apps;
  CLI::App app{"mechsim: a MuJoCo-based simulator for ros_control robots described in xacro/URDF"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mechsim 0.1.0");
  CommandResult result;
  add_xacro_command(app, result);
  add_check_command(app, result);
  add_world_command(app, result);
  add_soil_command(app, result);
  add_run_command(app, result);
  add_render_command(app, result);
  add_tune_command(app, result);
  add_spawner_command(app, result);
  add_bench_command(app, result);
  add_sweep_command(app, result);
  add_view_command(app, result);
  add_ros2_command(app, result);
  if (unknown_subcommand(app, argc, argv)) return 1;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::string command = "mechsim";
    for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
    std::cerr << command << ": error: " << e.what() << "\n";
    return 1;
  }
  return result.exit_code;
}
