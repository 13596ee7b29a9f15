// Loading SDF worlds and models with libsdformat (its own ParserConfig per load: no global
// search paths), then converting each model (sdf_convert.cpp).
#include <filesystem>
#include <set>

#include <sdf/Actor.hh>
#include <sdf/Light.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Physics.hh>
#include <sdf/Root.hh>
#include <sdf/World.hh>

#include "description/sdf/sdf_convert.hpp"
#include "description/sdf/sdf_model.hpp"
#include "description/sdf/sdf_paths.hpp"

namespace mechsim::description {
namespace {

using sdf_detail::where;

std::string error_text(const sdf::Errors& errors, const std::string& source) {
  std::string text;
  for (const sdf::Error& e : errors) {
    std::string w = e.FilePath().value_or(source);
    if (e.LineNumber()) w += ":" + std::to_string(*e.LineNumber());
    text += (text.empty() ? "" : "; ") + w + ": " + e.Message();
  }
  return text;
}

Pose pose_of(const ignition::math::Pose3d& p) {
  return {{p.Pos().X(), p.Pos().Y(), p.Pos().Z()}, {p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z()}};
}

sdf::ParserConfig parser_config(const sdf_detail::SdfSearch& search, const sdf_detail::BuiltinModels& builtin) {
  sdf::ParserConfig config;
  std::string paths;
  for (const std::string& d : search.model_dirs) paths += d + ":";
  config.AddURIPath("model://", paths + builtin.dir());
  return config;
}

void explicit_value(const sdf::ElementPtr& physics, const char* name, std::optional<double>& out) {
  if (physics && physics->HasElement(name) && physics->GetElement(name)->GetExplicitlySetInFile())
    out = physics->Get<double>(name);
}

}  // namespace

bool is_sdf_world_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".world" || ext == ".sdf";
}

SdfModel parse_sdf_model(const std::string& xml, const std::string& source, const SdfOptions& options) {
  const sdf_detail::SdfSearch search = sdf_detail::make_search(options);
  const sdf_detail::BuiltinModels builtin;
  sdf::Root root;
  const sdf::Errors errors = root.LoadSdfString(xml, parser_config(search, builtin));
  if (!errors.empty()) throw SdfError(source + ": " + error_text(errors, source));
  const sdf::Model* model = root.Model();
  if (model == nullptr) throw SdfError(source + ": the SDF holds no <model>");
  ignition::math::Pose3d p;
  if (const sdf::Errors e = model->SemanticPose().Resolve(p); !e.empty()) throw SdfError(source + ": " + error_text(e, source));
  SdfModel out = sdf_detail::convert_model(*model, pose_of(p), search);
  out.robot.source = source;
  return out;
}

SdfWorld load_sdf_world(const std::string& path, const SdfOptions& options) {
  if (!std::filesystem::is_regular_file(path)) throw SdfError("world file '" + path + "': no such file");
  const sdf_detail::SdfSearch search = sdf_detail::make_search(options);
  const sdf_detail::BuiltinModels builtin;
  sdf::Root root;
  const sdf::Errors errors = root.Load(path, parser_config(search, builtin));
  if (!errors.empty()) throw SdfError(error_text(errors, path));
  if (root.WorldCount() == 0) throw SdfError(path + ": the file holds no <world>");
  const sdf::World& w = *root.WorldByIndex(0);
  SdfWorld out;
  out.name = w.Name();
  out.file = path;
  const auto g = w.Gravity();
  out.gravity = {g.X(), g.Y(), g.Z()};
  if (root.WorldCount() > 1) out.not_simulated.push_back("worlds after the first ('" + out.name + "') in " + path);
  if (const sdf::Physics* physics = w.PhysicsDefault()) {
    const sdf::ElementPtr e = physics->Element();
    explicit_value(e, "max_step_size", out.max_step_size);
    explicit_value(e, "real_time_update_rate", out.real_time_update_rate);
    explicit_value(e, "real_time_factor", out.real_time_factor);
    if (e && ((e->HasElement("ode") && e->GetElement("ode")->GetExplicitlySetInFile()) ||
              (e->HasElement("bullet") && e->GetElement("bullet")->GetExplicitlySetInFile())))
      out.not_simulated.push_back("physics '" + physics->EngineType() + "' solver and constraint settings (MuJoCo's solver is used)");
  }
  std::set<std::string> names;
  for (uint64_t i = 0; i < w.ModelCount(); ++i) {
    const sdf::Model& m = *w.ModelByIndex(i);
    if (!names.insert(m.Name()).second) throw SdfError(where(m.Element()) + ": a second model named '" + m.Name() + "'");
    ignition::math::Pose3d p;
    if (const sdf::Errors e = m.SemanticPose().Resolve(p); !e.empty()) throw SdfError(error_text(e, path));
    SdfModel model = sdf_detail::convert_model(m, pose_of(p), search);
    out.not_simulated.insert(out.not_simulated.end(), model.not_simulated.begin(), model.not_simulated.end());
    model.not_simulated.clear();
    out.warnings.insert(out.warnings.end(), model.warnings.begin(), model.warnings.end());
    out.models.push_back(std::move(model));
  }
  for (uint64_t i = 0; i < w.LightCount(); ++i) out.not_simulated.push_back("light '" + w.LightByIndex(i)->Name() + "'");
  for (uint64_t i = 0; i < w.ActorCount(); ++i) out.not_simulated.push_back("actor '" + w.ActorByIndex(i)->Name() + "'");
  const sdf::ElementPtr e = w.Element();
  if (e && e->HasElement("gui") && e->GetElement("gui")->GetExplicitlySetInFile()) out.not_simulated.push_back("gui (camera, plugins)");
  if (e && e->HasElement("scene") && e->GetElement("scene")->GetExplicitlySetInFile())
    out.not_simulated.push_back("scene (ambient, background, sky, shadows, grid)");
  if (e && e->HasElement("plugin"))
    for (sdf::ElementPtr p = e->GetElement("plugin"); p; p = p->GetNextElement("plugin"))
      out.not_simulated.push_back("world plugin '" + p->Get<std::string>("name") + "' (" + p->Get<std::string>("filename") + ")");
  for (const char* visual_only : {"atmosphere", "wind", "spherical_coordinates", "audio", "road", "population"})
    if (e && e->HasElement(visual_only) && e->GetElement(visual_only)->GetExplicitlySetInFile())
      out.not_simulated.push_back(std::string("<") + visual_only + ">");
  return out;
}

}  // namespace mechsim::description
