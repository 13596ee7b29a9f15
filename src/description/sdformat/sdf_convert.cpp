#include "description/sdformat/sdf_convert.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <set>

#include <sdf/Collision.hh>
#include <sdf/Geometry.hh>
#include <sdf/Box.hh>
#include <sdf/Cylinder.hh>
#include <sdf/Heightmap.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Light.hh>
#include <sdf/Link.hh>
#include <sdf/Material.hh>
#include <sdf/Mesh.hh>
#include <sdf/Plane.hh>
#include <sdf/Sensor.hh>
#include <sdf/Sphere.hh>
#include <sdf/Visual.hh>
#include <tinyxml2.h>

#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::sdf_detail {
namespace {

using Iso = Eigen::Isometry3d;

Iso iso(const ignition::math::Pose3d& p) {
  Iso X = Iso::Identity();
  X.translate(Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z()));
  X.rotate(Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z()).normalized());
  return X;
}

Pose pose(const Iso& X) {
  const Eigen::Quaterniond q(X.rotation());
  const Eigen::Vector3d t = X.translation();
  return {{t.x(), t.y(), t.z()}, {q.w(), q.x(), q.y(), q.z()}};
}

// Errors of a SemanticPose resolution are bad input too (a frame named that does not exist).
template <class T>
Iso resolved(const T& element, const std::string& relative_to, const std::string& what) {
  ignition::math::Pose3d p;
  const sdf::Errors errors = element.SemanticPose().Resolve(p, relative_to);
  if (!errors.empty()) throw SdfError(where(element.Element()) + ": " + what + ": " + errors.front().Message());
  return iso(p);
}

// <surface><friction><ode><mu>/<mu2>/<fdir1>, where written.
void surface_friction(const sdf::Collision& c, std::optional<double>& mu, std::optional<double>& mu2,
                      std::optional<Vec3>& fdir1) {
  const sdf::ElementPtr e = c.Element();
  if (!e || !e->HasElement("surface")) return;
  const sdf::ElementPtr s = e->GetElement("surface");
  if (!s->HasElement("friction")) return;
  const sdf::ElementPtr f = s->GetElement("friction");
  if (!f->HasElement("ode")) return;
  const sdf::ElementPtr ode = f->GetElement("ode");
  if (ode->HasElement("mu") && ode->GetElement("mu")->GetExplicitlySetInFile()) mu = ode->Get<double>("mu");
  if (ode->HasElement("mu2") && ode->GetElement("mu2")->GetExplicitlySetInFile()) mu2 = ode->Get<double>("mu2");
  if (ode->HasElement("fdir1") && ode->GetElement("fdir1")->GetExplicitlySetInFile()) {
    const auto d = ode->Get<ignition::math::Vector3d>("fdir1");
    if (d != ignition::math::Vector3d::Zero) fdir1 = Vec3{d.X(), d.Y(), d.Z()};
  }
}

bool has_contact_parameters(const sdf::Collision& c) {
  const sdf::ElementPtr e = c.Element();
  return e && e->HasElement("surface") && e->GetElement("surface")->HasElement("contact") &&
         e->GetElement("surface")->GetElement("contact")->GetExplicitlySetInFile();
}

class Converter {
 public:
  Converter(const sdf::Model& model, const Pose& model_pose, const SdfSearch& search)
      : model_(model), search_(search) {
    out_.name = model.Name();
    out_.pose = model_pose;
    out_.is_static = model.Static();
    out_.robot.name = model.Name();
    out_.robot.source = model.Element() ? model.Element()->FilePath() : std::string();
  }

  SdfModel run() {
    const std::string m = "model '" + out_.name + "'";
    if (model_.LinkCount() == 0) throw SdfError(where(model_.Element()) + ": " + m + " has no link");
    for (uint64_t i = 0; i < model_.ModelCount(); ++i)
      note(m + ": nested model '" + model_.ModelByIndex(i)->Name() + "' (mechsim simulates one level of models)");

    // Joints first: which link hangs from which, so that link frames can follow URDF's rule.
    for (uint64_t i = 0; i < model_.JointCount(); ++i) add_joint(*model_.JointByIndex(i));
    for (uint64_t i = 0; i < model_.LinkCount(); ++i) {
      const sdf::Link& link = *model_.LinkByIndex(i);
      X_ML_[link.Name()] = resolved(link, "__model__", "link '" + link.Name() + "' pose");
    }
    // A link's frame in the RobotModel: its parent joint's frame, or its own for a root.
    for (const auto& [name, X] : X_ML_) X_ML_frame_[name] = parent_joint_.count(name) ? X_MJ_[parent_joint_[name]] : X;
    for (uint64_t i = 0; i < model_.LinkCount(); ++i) add_link(*model_.LinkByIndex(i));
    connect_roots();
    set_joint_origins();
    read_sensors_and_plugins();
    return std::move(out_);
  }

 private:
  void note(const std::string& what) { out_.not_simulated.push_back(what); }


  void add_joint(const sdf::Joint& j) {
    const std::string what = "model '" + out_.name + "' joint '" + j.Name() + "'";
    Joint joint;
    joint.name = j.Name();
    joint.parent_link = j.ParentLinkName();
    joint.child_link = j.ChildLinkName();
    joint.line = j.Element() && j.Element()->LineNumber() ? *j.Element()->LineNumber() : 0;
    if (joint.child_link == "world") throw SdfError(where(j.Element()) + ": " + what + ": the world cannot be a child");
    if (parent_joint_.count(joint.child_link))
      throw SdfError(where(j.Element()) + ": " + what + ": link '" + joint.child_link + "' already has parent joint '" +
                     parent_joint_[joint.child_link] + "' (mechsim simulates trees, not loops)");
    X_MJ_[j.Name()] = resolved(j, "__model__", what + " pose");
    switch (j.Type()) {
      case sdf::JointType::REVOLUTE: joint.type = JointType::Revolute; break;
      case sdf::JointType::CONTINUOUS: joint.type = JointType::Continuous; break;
      case sdf::JointType::PRISMATIC: joint.type = JointType::Prismatic; break;
      case sdf::JointType::FIXED: joint.type = JointType::Fixed; break;
      default:
        joint.type = JointType::Fixed;
        note(what + ": a " + type_name(j.Type()) + " joint, simulated as fixed");
    }
    if (const sdf::JointAxis* axis = j.Axis(0); axis != nullptr && joint.type != JointType::Fixed) {
      ignition::math::Vector3d xyz;
      const sdf::Errors errors = axis->ResolveXyz(xyz, "__model__");
      if (!errors.empty()) throw SdfError(where(j.Element()) + ": " + what + " axis: " + errors.front().Message());
      const Eigen::Vector3d a = X_MJ_[j.Name()].rotation().transpose() * Eigen::Vector3d(xyz.X(), xyz.Y(), xyz.Z());
      joint.axis = {a.x(), a.y(), a.z()};
      // SDF's defaults are +-1e16 (no limit), effort and velocity -1 (none).
      JointLimits limits;
      const bool bounded = axis->Lower() > -1e15 && axis->Upper() < 1e15;
      if (joint.type == JointType::Revolute && !bounded) joint.type = JointType::Continuous;
      if (bounded) limits.lower = axis->Lower(), limits.upper = axis->Upper();
      limits.effort = axis->Effort() > 0.0 ? axis->Effort() : 0.0;
      limits.velocity = axis->MaxVelocity() > 0.0 ? axis->MaxVelocity() : 0.0;
      joint.limits = limits;
      if (axis->Damping() != 0.0 || axis->Friction() != 0.0) joint.dynamics = Dynamics{axis->Damping(), axis->Friction()};
      if (axis->SpringStiffness() != 0.0) note(what + ": its spring (stiffness " + std::to_string(axis->SpringStiffness()) + ")");
    }
    if (j.Axis(1) != nullptr && joint.type != JointType::Fixed) note(what + ": its second axis");
    parent_joint_[joint.child_link] = joint.name;
    if (joint.parent_link == "world") world_joints_.push_back(joint.name);
    out_.robot.joints.push_back(std::move(joint));
  }

  static std::string type_name(sdf::JointType t) {
    switch (t) {
      case sdf::JointType::BALL: return "ball";
      case sdf::JointType::GEARBOX: return "gearbox";
      case sdf::JointType::REVOLUTE2: return "revolute2";
      case sdf::JointType::SCREW: return "screw";
      case sdf::JointType::UNIVERSAL: return "universal";
      default: return "unknown";
    }
  }

  std::optional<Geometry> geometry(const sdf::Geometry& g, const std::string& what, const std::string& file) {
    Geometry out;
    switch (g.Type()) {
      case sdf::GeometryType::BOX: {
        const auto s = g.BoxShape()->Size();
        out.type = GeometryType::Box;
        out.size = {s.X(), s.Y(), s.Z()};
        return out;
      }
      case sdf::GeometryType::CYLINDER:
        out.type = GeometryType::Cylinder;
        out.radius = g.CylinderShape()->Radius();
        out.length = g.CylinderShape()->Length();
        return out;
      case sdf::GeometryType::SPHERE:
        out.type = GeometryType::Sphere;
        out.radius = g.SphereShape()->Radius();
        return out;
      case sdf::GeometryType::MESH: {
        const sdf::Mesh& mesh = *g.MeshShape();
        out.type = GeometryType::Mesh;
        out.mesh_uri = mesh.Uri();
        out.mesh_path = resolve_uri(mesh.Uri(), mesh.FilePath().empty() ? file : mesh.FilePath(), search_);
        const auto s = mesh.Scale();
        out.mesh_scale = {s.X(), s.Y(), s.Z()};
        if (!mesh.Submesh().empty()) note(what + ": only submesh '" + mesh.Submesh() + "' of its mesh was asked for; the whole mesh is used");
        return out;
      }
      case sdf::GeometryType::CAPSULE: note(what + ": capsule geometry"); return std::nullopt;
      case sdf::GeometryType::ELLIPSOID: note(what + ": ellipsoid geometry"); return std::nullopt;
      default: note(what + ": geometry of an unsupported type"); return std::nullopt;
    }
  }

  void add_link(const sdf::Link& l) {
    const std::string lw = "model '" + out_.name + "' link '" + l.Name() + "'";
    Link link;
    link.name = l.Name();
    link.line = l.Element() && l.Element()->LineNumber() ? *l.Element()->LineNumber() : 0;
    if (auto it = parent_joint_.find(l.Name()); it != parent_joint_.end()) link.parent_joint = it->second;
    const Iso X_frame_L = X_ML_frame_[l.Name()].inverse() * X_ML_[l.Name()];  // the link's SDF frame in its RobotModel frame
    const ignition::math::Inertiald& in = l.Inertial();
    if (!out_.is_static) {
      Inertial inertial;
      inertial.origin = pose(X_frame_L * iso(in.Pose()));
      inertial.mass = in.MassMatrix().Mass();
      const auto d = in.MassMatrix().DiagonalMoments();
      const auto o = in.MassMatrix().OffDiagonalMoments();
      inertial.ixx = d.X(), inertial.iyy = d.Y(), inertial.izz = d.Z();
      inertial.ixy = o.X(), inertial.ixz = o.Y(), inertial.iyz = o.Z();
      link.inertial = inertial;
    }
    const std::string file = l.Element() ? l.Element()->FilePath() : std::string();
    GazeboLinkProperties gz;
    for (uint64_t i = 0; i < l.CollisionCount(); ++i) {
      const sdf::Collision& c = *l.CollisionByIndex(i);
      const std::string cw = lw + " collision '" + c.Name() + "'";
      const Iso X_LC = resolved(c, l.Name(), cw + " pose");
      const std::string scoped = out_.name + "::" + l.Name() + "::" + c.Name();
      if (has_contact_parameters(c)) note(cw + ": surface contact parameters (MuJoCo's contact model is used)");
      std::optional<double> mu, mu2;
      std::optional<Vec3> fdir1;
      surface_friction(c, mu, mu2, fdir1);
      if (c.Geom()->Type() == sdf::GeometryType::PLANE) {
        add_plane(c, X_ML_[l.Name()] * X_LC, scoped, cw, mu, mu2);
        continue;
      }
      if (c.Geom()->Type() == sdf::GeometryType::HEIGHTMAP) {
        add_heightmap(c, X_ML_[l.Name()] * X_LC, scoped, cw, file);
        continue;
      }
      std::optional<Geometry> g = geometry(*c.Geom(), cw, file);
      if (!g) continue;
      Collision collision;
      collision.name = c.Name();
      collision.origin = pose(X_frame_L * X_LC);
      collision.geometry = std::move(*g);
      if (c.Element() && c.Element()->HasElement("laser_retro")) collision.laser_retro = c.Element()->Get<double>("laser_retro");
      link.collisions.push_back(std::move(collision));
      // mechsim's geoms have one friction per link (as URDF's gazebo <mu1>/<mu2>).
      if ((mu && gz.mu1 && *gz.mu1 != *mu) || (mu2 && gz.mu2 && *gz.mu2 != *mu2))
        out_.warnings.push_back(cw + ": its friction differs from the link's other collisions; the first one's is used");
      if (mu && !gz.mu1) gz.mu1 = mu;
      if (mu2 && !gz.mu2) gz.mu2 = mu2;
      if (fdir1) note(cw + ": <fdir1> (MuJoCo's contact frames have no set direction; mu and mu2 make one coefficient, their mean)");
    }
    for (uint64_t i = 0; i < l.VisualCount(); ++i) {
      const sdf::Visual& v = *l.VisualByIndex(i);
      const std::string vw = lw + " visual '" + v.Name() + "'";
      if (v.Geom()->Type() == sdf::GeometryType::PLANE || v.Geom()->Type() == sdf::GeometryType::HEIGHTMAP) continue;
      std::optional<Geometry> g = geometry(*v.Geom(), vw, file);
      if (!g) continue;
      Visual visual;
      visual.name = v.Name();
      visual.origin = pose(X_frame_L * resolved(v, l.Name(), vw + " pose"));
      visual.geometry = std::move(*g);
      if (const sdf::Material* m = v.Material()) {
        const auto c = m->Diffuse();
        visual.rgba = std::array<double, 4>{c.R(), c.G(), c.B(), c.A()};
      }
      link.visuals.push_back(std::move(visual));
    }
    for (uint64_t i = 0; i < l.SensorCount(); ++i) sensors_.push_back({l.Name(), l.SensorByIndex(i)});
    for (uint64_t i = 0; i < l.LightCount(); ++i) note(lw + ": light '" + l.LightByIndex(i)->Name() + "'");
    if (l.Element() && l.Element()->HasElement("gravity") && !l.Element()->Get<bool>("gravity")) gz.gravity = false;
    if (model_.SelfCollide() || (l.Element() && l.Element()->HasElement("self_collide") && l.Element()->Get<bool>("self_collide")))
      gz.self_collide = true;
    if (l.Element() && l.Element()->HasElement("kinematic") && l.Element()->Get<bool>("kinematic"))
      note(lw + ": kinematic (simulated as a dynamic link)");
    if (gz.mu1 || gz.mu2 || gz.gravity || gz.self_collide) out_.robot.gazebo_links[l.Name()] = gz;
    out_.robot.links.push_back(std::move(link));
  }

  void add_plane(const sdf::Collision& c, const Iso& X_MC, const std::string& name, const std::string& what,
                 std::optional<double> mu, std::optional<double> mu2) {
    if (!out_.is_static) {
      note(what + ": a plane on a link that moves (planes belong to static models)");
      return;
    }
    // The plane's frame: the collision frame turned so that its z axis is the normal.
    const auto n = c.Geom()->PlaneShape()->Normal();
    const Eigen::Vector3d normal = Eigen::Vector3d(n.X(), n.Y(), n.Z()).normalized();
    Iso X = X_MC;
    X.rotate(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal));
    SdfPlane p;
    p.name = name;
    p.pose = pose(X);
    p.mu = mu;
    p.mu2 = mu2;
    out_.planes.push_back(std::move(p));
  }

  void add_heightmap(const sdf::Collision& c, const Iso& X_MC, const std::string& name, const std::string& what,
                     const std::string& file) {
    if (!out_.is_static) {
      note(what + ": a heightmap on a link that moves (heightmaps belong to static models)");
      return;
    }
    const sdf::Heightmap& h = *c.Geom()->HeightmapShape();
    SdfHeightmap m;
    m.name = name;
    m.uri = h.Uri();
    m.path = resolve_uri(h.Uri(), h.FilePath().empty() ? file : h.FilePath(), search_);
    m.size = {h.Size().X(), h.Size().Y(), h.Size().Z()};
    m.position = {h.Position().X(), h.Position().Y(), h.Position().Z()};
    m.pose = pose(X_MC);
    out_.heightmaps.push_back(std::move(m));
  }

  // The links' <sensor>s and the model's <plugin>s, read by the same code as a URDF's <gazebo>
  // blocks (the elements are SDF in both): each one becomes <gazebo reference="LINK"> (a model
  // plugin: <gazebo>) of a small URDF-like document. A sensor's pose is given in the SDF link's
  // frame (or its relative_to frame); the RobotModel's link frame is the link's parent joint frame,
  // so the pose is rewritten in that frame first.
  void read_sensors_and_plugins() {
    for (const auto& [link, sensor] : sensors_) {
      const sdf::ElementPtr e = sensor->Element();
      if (!e) continue;
      const Iso X_MS = resolved(*sensor, "__model__", "link '" + link + "' sensor '" + sensor->Name() + "' pose");
      const Iso X_LS = X_ML_frame_.at(link).inverse() * X_MS;
      const sdf::ElementPtr copy = e->Clone();
      const sdf::ElementPtr pose_element = copy->GetElement("pose");
      const Eigen::Quaterniond q(X_LS.rotation());
      const Eigen::Vector3d t = X_LS.translation();
      pose_element->Set(ignition::math::Pose3d(t.x(), t.y(), t.z(), q.w(), q.x(), q.y(), q.z()));
      if (const sdf::ParamPtr relative_to = pose_element->GetAttribute("relative_to")) relative_to->Reset();
      read_gazebo_block("<gazebo reference=\"" + link + "\">" + copy->ToString("") + "</gazebo>", e);
    }
    if (const sdf::ElementPtr m = model_.Element(); m && m->HasElement("plugin")) {
      for (sdf::ElementPtr p = m->GetElement("plugin"); p; p = p->GetNextElement("plugin"))
        read_gazebo_block("<gazebo>" + p->ToString("") + "</gazebo>", p);
    }
  }

  void read_gazebo_block(const std::string& block, const sdf::ElementPtr& origin) {
    const std::string xml = "<robot name=\"" + out_.name + "\">\n" + block + "\n</robot>";
    tinyxml2::XMLDocument doc;
    if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
      throw SdfError(where(origin) + ": model '" + out_.name + "': cannot read <" + origin->GetName() + "> (" +
                     (doc.ErrorStr() != nullptr ? doc.ErrorStr() : "?") + ")");
    }
    // Messages name the element's file and line; lines inside it count from there.
    detail::Problems problems(where(origin) + " (model '" + out_.name + "')");
    detail::read_gazebo(*doc.RootElement(), problems, out_.robot);
    const ValidationReport& report = problems.report();
    for (const std::string& w : report.warnings) out_.warnings.push_back(w);
    if (!report.errors.empty()) {
      std::string text;
      for (const std::string& e : report.errors) text += (text.empty() ? "" : "; ") + e;
      throw SdfError(text);
    }
  }

  // A RobotModel is one tree with one root. Links no joint holds: a static model welds them to
  // the first (everything stands still anyway); in a moving model they would float apart.
  void connect_roots() {
    std::vector<std::string> roots;
    for (const Link& l : out_.robot.links)
      if (l.parent_joint.empty()) roots.push_back(l.name);
    const bool to_world = !world_joints_.empty();
    if (to_world || (roots.size() > 1 && out_.is_static)) {
      Link world;
      world.name = "world";
      for (const std::string& r : roots) {
        if (to_world && !out_.is_static)
          throw SdfError(where(model_.Element()) + ": model '" + out_.name + "': link '" + r +
                         "' hangs from no joint while another is jointed to the world (mechsim simulates one tree per model)");
        Joint weld;
        weld.name = "__weld_" + r;
        weld.type = JointType::Fixed;
        weld.parent_link = "world";
        weld.child_link = r;
        out_.robot.joints.push_back(weld);
        X_MJ_[weld.name] = X_ML_[r];
        link_named(r).parent_joint = weld.name;
      }
      out_.robot.links.insert(out_.robot.links.begin(), std::move(world));
      out_.robot.root_link = "world";
      X_ML_frame_["world"] = Iso::Identity();
      out_.root_offset = Pose{};
    } else {
      if (roots.size() != 1)
        throw SdfError(where(model_.Element()) + ": model '" + out_.name + "': links " + list(roots) +
                       " hang from no joint (a moving model must be one tree: mechsim simulates one per model)");
      out_.robot.root_link = roots.front();
      out_.root_offset = pose(X_ML_frame_[roots.front()]);
    }
    for (Link& l : out_.robot.links) l.child_joints.clear();
    for (const Joint& j : out_.robot.joints) link_named(j.parent_link).child_joints.push_back(j.name);
  }

  void set_joint_origins() {
    // A joint's frame is its child link's frame (a welded root's weld sits at the root's own frame).
    for (Joint& j : out_.robot.joints) {
      j.origin = pose(X_ML_frame_.at(j.parent_link).inverse() * X_MJ_.at(j.name));
    }
  }

  Link& link_named(const std::string& name) {
    for (Link& l : out_.robot.links)
      if (l.name == name) return l;
    throw SdfError("model '" + out_.name + "': a joint names link '" + name + "', which the model does not have");
  }

  static std::string list(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out;
  }

  const sdf::Model& model_;
  const SdfSearch& search_;
  SdfModel out_;
  std::map<std::string, std::string> parent_joint_;  // child link -> joint
  std::vector<std::string> world_joints_;
  std::vector<std::pair<std::string, const sdf::Sensor*>> sensors_;  // link name, sensor
  std::map<std::string, Iso, std::less<>> X_ML_, X_ML_frame_, X_MJ_;
};

}  // namespace

std::string where(const sdf::ElementPtr& element) {
  if (!element) return "<sdf>";
  std::string w = element->FilePath().empty() ? std::string("<sdf>") : element->FilePath();
  if (element->LineNumber()) w += ":" + std::to_string(*element->LineNumber());
  return w;
}

SdfModel convert_model(const sdf::Model& model, const Pose& model_pose, const SdfSearch& search) {
  return Converter(model, model_pose, search).run();
}

}  // namespace mechsim::description::sdf_detail
