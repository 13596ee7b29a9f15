// The module side of SDF reading (sdf/sdf_module.hpp): loading SDF worlds and models with
// libsdformat (its own ParserConfig per load: no global search paths), then converting each model
// (sdf_convert.cpp).
#include <array>
#include <filesystem>
#include <set>

#include <sdf/Actor.hh>
#include <sdf/Light.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Physics.hh>
#include <sdf/Root.hh>
#include <sdf/World.hh>

#include "description/sdformat/sdf_convert.hpp"
#include "description/sdf/sdf_model.hpp"
#include "description/sdf/sdf_module.hpp"
#include "description/sdf/sdf_paths.hpp"

namespace mechsim::description {
namespace {

using sdf_detail::where;

// What Gazebo 11 (libsdformat 9) reads without complaint and libsdformat 12 reports (the DOM is
// built all the same): warnings. Anything else refuses the file.
bool tolerated(const sdf::Error& e) {
  const std::string& m = e.Message();
  switch (e.Code()) {
    case sdf::ErrorCode::URI_LOOKUP:  // a model:// include no model path holds: left out
      return true;
    case sdf::ErrorCode::ELEMENT_MISSING:  // a <script> given as text, an old SDF form
      return m.find("<script> element is missing a child <name>") != std::string::npos;
    case sdf::ErrorCode::ELEMENT_INVALID:
      return m.find("<script> element is missing a child <uri>") != std::string::npos ||
             m.find("<image><format> has invalid value") != std::string::npos ||
             m.find("Failed to load a world") != std::string::npos || m.find("Failed to load a model") != std::string::npos;
    default:
      return false;
  }
}

// Splits `errors` into the tolerated ones (appended to `warnings`) and the rest (returned).
sdf::Errors refusing(const sdf::Errors& errors, const std::string& source, std::vector<std::string>& warnings) {
  sdf::Errors rest;
  for (const sdf::Error& e : errors) {
    if (!tolerated(e)) {
      rest.push_back(e);
      continue;
    }
    if (e.Message().find("Failed to load a") != std::string::npos) continue;  // the summary of the others
    std::string w = e.FilePath().value_or(source);
    if (e.LineNumber()) w += ":" + std::to_string(*e.LineNumber());
    warnings.push_back(w + ": " + e.Message() + " (Gazebo 11 reads it; " +
                       (e.Code() == sdf::ErrorCode::URI_LOOKUP ? "the include is left out)" : "taken as Gazebo does)"));
  }
  return rest;
}

std::array<double, 4> rgba(const ignition::math::Color& c) { return {c.R(), c.G(), c.B(), c.A()}; }

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

// parse_sdf_model and load_sdf_world as the module does them (the description library's
// versions call these through sdf_module.hpp's entry point, mechsim_sdformat_module below).
SdfModel read_sdf_model(const std::string& xml, const std::string& source, const SdfOptions& options) {
  const sdf_detail::SdfSearch search = sdf_detail::make_search(options);
  const sdf_detail::BuiltinModels builtin;
  sdf::Root root;
  std::vector<std::string> warnings;
  const sdf::Errors errors = refusing(root.LoadSdfString(xml, parser_config(search, builtin)), source, warnings);
  if (!errors.empty()) throw SdfError(source + ": " + error_text(errors, source));
  const sdf::Model* model = root.Model();
  if (model == nullptr) throw SdfError(source + ": the SDF holds no <model>");
  ignition::math::Pose3d p;
  if (const sdf::Errors e = model->SemanticPose().Resolve(p); !e.empty()) throw SdfError(source + ": " + error_text(e, source));
  SdfModel out = sdf_detail::convert_model(*model, pose_of(p), search);
  out.robot.source = source;
  out.warnings.insert(out.warnings.begin(), warnings.begin(), warnings.end());
  return out;
}

SdfWorld read_sdf_world(const std::string& path, const SdfOptions& options) {
  if (!std::filesystem::is_regular_file(path)) throw SdfError("world file '" + path + "': no such file");
  const sdf_detail::SdfSearch search = sdf_detail::make_search(options);
  const sdf_detail::BuiltinModels builtin;
  sdf::Root root;
  SdfWorld out;
  const sdf::Errors errors = refusing(root.Load(path, parser_config(search, builtin)), path, out.warnings);
  if (!errors.empty()) throw SdfError(error_text(errors, path));
  if (root.WorldCount() == 0) throw SdfError(path + ": the file holds no <world>");
  const sdf::World& w = *root.WorldByIndex(0);
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
  for (uint64_t i = 0; i < w.LightCount(); ++i) {
    const sdf::Light& l = *w.LightByIndex(i);
    SdfLight light;
    light.name = l.Name();
    switch (l.Type()) {
      case sdf::LightType::POINT: light.type = "point"; break;
      case sdf::LightType::SPOT: light.type = "spot"; break;
      default: light.type = "directional"; break;
    }
    light.cast_shadows = l.CastShadows();
    light.diffuse = rgba(l.Diffuse());
    light.specular = rgba(l.Specular());
    light.attenuation_constant = l.ConstantAttenuationFactor();
    light.attenuation_linear = l.LinearAttenuationFactor();
    light.attenuation_quadratic = l.QuadraticAttenuationFactor();
    light.range = l.AttenuationRange();
    light.direction = {l.Direction().X(), l.Direction().Y(), l.Direction().Z()};
    ignition::math::Pose3d p;
    if (l.SemanticPose().Resolve(p).empty()) light.pose = pose_of(p);
    out.lights.push_back(std::move(light));
  }
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

std::string module_parse_model(const std::string& xml, const std::string& source, const SdfOptions& options,
                               SdfModel& out) {
  try {
    out = read_sdf_model(xml, source, options);
    return {};
  } catch (const SdfError& e) {
    return e.what();
  }
}

std::string module_load_world(const std::string& path, const SdfOptions& options, SdfWorld& out) {
  try {
    out = read_sdf_world(path, options);
    return {};
  } catch (const SdfError& e) {
    return e.what();
  }
}

}  // namespace

}  // namespace mechsim::description

extern "C" __attribute__((visibility("default"))) const mechsim::description::sdf_detail::SdfModuleApi*
mechsim_sdformat_module() {
  static const mechsim::description::sdf_detail::SdfModuleApi api{
      mechsim::description::sdf_detail::kSdfModuleVersion, &mechsim::description::module_parse_model,
      &mechsim::description::module_load_world};
  return &api;
}
