#include "live/stream_messages.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <utility>

#include <nlohmann/json.hpp>

namespace mechsim::live {

namespace {

using description::Pose;
using description::Quat;
using description::Vec3;

// Appends JSON text without building a document (these run at the streaming rate).
void number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void integer(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void quoted(std::string& out, const std::string& s) {
  out += nlohmann::json(s).dump();
}

// {"sec":S,"nsec":N} of simulation time t (s).
void stamp(std::string& out, double t) {
  const auto ns = static_cast<std::uint64_t>(std::llround(std::max(0.0, t) * 1e9));
  out += "{\"sec\":";
  integer(out, ns / 1000000000u);
  out += ",\"nsec\":";
  integer(out, ns % 1000000000u);
  out += '}';
}

// {"k1":v1,"k2":v2,...} of numbers.
void numbers(std::string& out, std::initializer_list<std::pair<const char*, double>> fields) {
  char sep = '{';
  for (const auto& [key, value] : fields) {
    out += sep;
    out += '"';
    out += key;
    out += "\":";
    number(out, value);
    sep = ',';
  }
  out += '}';
}

void vec3(std::string& out, const Vec3& v) { numbers(out, {{"x", v.x}, {"y", v.y}, {"z", v.z}}); }

void quat(std::string& out, const Quat& q) { numbers(out, {{"x", q.x}, {"y", q.y}, {"z", q.z}, {"w", q.w}}); }

Quat conjugate(const Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

Quat multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Vec3 rotate(const Quat& q, const Vec3& v) {
  const Quat r = multiply(multiply(q, Quat{0.0, v.x, v.y, v.z}), conjugate(q));
  return {r.x, r.y, r.z};
}

// X_PC = X_WP^-1 * X_WC.
Pose relative(const Pose& X_WP, const Pose& X_WC) {
  const Quat q_PW = conjugate(X_WP.orientation);
  const Vec3 d{X_WC.position.x - X_WP.position.x, X_WC.position.y - X_WP.position.y, X_WC.position.z - X_WP.position.z};
  Pose X_PC;
  X_PC.position = rotate(q_PW, d);
  X_PC.orientation = multiply(q_PW, X_WC.orientation);
  return X_PC;
}

void pose(std::string& out, const Pose& X) {
  out += "{\"position\":";
  vec3(out, X.position);
  out += ",\"orientation\":";
  quat(out, X.orientation);
  out += '}';
}

void header(std::string& out, double t, const std::string& frame) {
  out += "\"header\":{\"seq\":0,\"stamp\":";
  stamp(out, t);
  out += ",\"frame_id\":";
  quoted(out, frame);
  out += '}';
}

template <class F>
void array(std::string& out, std::size_t n, F&& each) {
  out += '[';
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) out += ',';
    each(k);
  }
  out += ']';
}

}  // namespace

void encode_frame_transforms(const StreamLayout& layout, const Snapshot& s, std::string& out) {
  out.clear();
  out += "{\"transforms\":";
  array(out, layout.links.size(), [&](std::size_t k) {
    const std::size_t parent = layout.parent[k];
    const bool from_world = parent >= layout.links.size();
    const Pose X = from_world ? s.X_WL[k] : relative(s.X_WL[parent], s.X_WL[k]);
    out += "{\"timestamp\":";
    stamp(out, s.time);
    out += ",\"parent_frame_id\":";
    quoted(out, from_world ? layout.world_frame : layout.links[parent]);
    out += ",\"child_frame_id\":";
    quoted(out, layout.links[k]);
    out += ",\"translation\":";
    vec3(out, X.position);
    out += ",\"rotation\":";
    quat(out, X.orientation);
    out += '}';
  });
  out += '}';
}

void encode_joint_states(const StreamLayout& layout, const Snapshot& s, std::string& out) {
  out.clear();
  out += '{';
  header(out, s.time, "");
  out += ",\"name\":";
  array(out, layout.joints.size(), [&](std::size_t k) { quoted(out, layout.joints[k]); });
  out += ",\"position\":";
  array(out, s.position.size(), [&](std::size_t k) { number(out, s.position[k]); });
  out += ",\"velocity\":";
  array(out, s.velocity.size(), [&](std::size_t k) { number(out, s.velocity[k]); });
  out += ",\"effort\":";
  array(out, s.effort.size(), [&](std::size_t k) { number(out, s.effort[k]); });
  out += '}';
}

void encode_odometry(const StreamLayout& layout, const Snapshot& s, std::string& out) {
  out.clear();
  out += '{';
  header(out, s.time, layout.odom_frame);
  out += ",\"child_frame_id\":";
  quoted(out, layout.odom_child_frame);
  out += ",\"pose\":{\"pose\":";
  Pose X;
  X.position = {s.odom_x, s.odom_y, s.odom_z};
  X.orientation = s.odom_orientation;
  pose(out, X);
  out += ",\"covariance\":[";
  for (int k = 0; k < 36; ++k) out += k == 0 ? "0" : ",0";
  out += "]},\"twist\":{\"twist\":{\"linear\":{\"x\":0,\"y\":0,\"z\":0},\"angular\":{\"x\":0,\"y\":0,\"z\":0}},\"covariance\":[";
  for (int k = 0; k < 36; ++k) out += k == 0 ? "0" : ",0";
  out += "]}}";
}

void encode_laser_scan(const StreamLayout& layout, std::size_t laser, const Snapshot& s, std::string& out) {
  const LaserLayout& l = layout.lasers[laser];
  const LaserFrame& f = s.lasers[laser];
  out.clear();
  out += "{\"timestamp\":";
  stamp(out, f.stamp);
  out += ",\"frame_id\":";
  quoted(out, l.link);
  out += ",\"pose\":";
  pose(out, l.X_LS);
  out += ",\"start_angle\":";
  number(out, l.angle_min);
  out += ",\"end_angle\":";
  number(out, l.angle_max);
  out += ",\"ranges\":";
  array(out, f.ranges.size(), [&](std::size_t k) { number(out, static_cast<double>(f.ranges[k])); });
  out += ",\"intensities\":[]}";
}

std::string encode_robot_description(const std::string& urdf) { return nlohmann::json{{"data", urdf}}.dump(); }

std::string encode_waypoint_markers(const StreamLayout& layout, double time) {
  nlohmann::json spheres = nlohmann::json::array();
  nlohmann::json points = nlohmann::json::array();
  const nlohmann::json orientation = {{"x", 0}, {"y", 0}, {"z", 0}, {"w", 1}};
  for (const auto& w : layout.waypoints) {
    const nlohmann::json position = {{"x", w[0]}, {"y", w[1]}, {"z", 0.2}};
    spheres.push_back({{"pose", {{"position", position}, {"orientation", orientation}}},
                       {"size", {{"x", 0.4}, {"y", 0.4}, {"z", 0.4}}},
                       {"color", {{"r", 1.0}, {"g", 0.55}, {"b", 0.0}, {"a", 0.9}}}});
    points.push_back(position);
  }
  const auto ns = static_cast<std::uint64_t>(std::llround(std::max(0.0, time) * 1e9));
  const nlohmann::json stamp_json = {{"sec", ns / 1000000000u}, {"nsec", ns % 1000000000u}};
  nlohmann::json line = {{"type", 0},  // LINE_STRIP
                         {"pose", {{"position", {{"x", 0}, {"y", 0}, {"z", 0}}}, {"orientation", orientation}}},
                         {"thickness", 0.05},
                         {"scale_invariant", false},
                         {"points", points},
                         {"color", {{"r", 1.0}, {"g", 0.55}, {"b", 0.0}, {"a", 0.9}}},
                         {"colors", nlohmann::json::array()},
                         {"indices", nlohmann::json::array()}};
  nlohmann::json entity = {{"timestamp", stamp_json},
                           {"frame_id", layout.world_frame},
                           {"id", "waypoints"},
                           {"lifetime", {{"sec", 0}, {"nsec", 0}}},
                           {"frame_locked", false},
                           {"metadata", nlohmann::json::array()},
                           {"arrows", nlohmann::json::array()},
                           {"cubes", nlohmann::json::array()},
                           {"spheres", spheres},
                           {"cylinders", nlohmann::json::array()},
                           {"lines", nlohmann::json::array({line})},
                           {"triangles", nlohmann::json::array()},
                           {"texts", nlohmann::json::array()},
                           {"models", nlohmann::json::array()}};
  return nlohmann::json{{"deletions", nlohmann::json::array()}, {"entities", nlohmann::json::array({entity})}}.dump();
}

namespace {

// JSON Schema building blocks.
nlohmann::json number_type() { return {{"type", "number"}}; }
nlohmann::json object_of(std::initializer_list<std::pair<const char*, nlohmann::json>> fields) {
  nlohmann::json properties = nlohmann::json::object();
  for (const auto& [name, schema] : fields) properties[name] = schema;
  return {{"type", "object"}, {"properties", properties}};
}
nlohmann::json array_of(nlohmann::json items) { return {{"type", "array"}, {"items", std::move(items)}}; }
nlohmann::json time_type() { return object_of({{"sec", {{"type", "integer"}}}, {"nsec", {{"type", "integer"}}}}); }
nlohmann::json vector3_type() { return object_of({{"x", number_type()}, {"y", number_type()}, {"z", number_type()}}); }
nlohmann::json quaternion_type() {
  return object_of({{"x", number_type()}, {"y", number_type()}, {"z", number_type()}, {"w", number_type()}});
}
nlohmann::json pose_type() { return object_of({{"position", vector3_type()}, {"orientation", quaternion_type()}}); }
nlohmann::json color_type() {
  return object_of({{"r", number_type()}, {"g", number_type()}, {"b", number_type()}, {"a", number_type()}});
}
nlohmann::json header_type() {
  return object_of({{"seq", {{"type", "integer"}}}, {"stamp", time_type()}, {"frame_id", {{"type", "string"}}}});
}
nlohmann::json empty_array() { return array_of(object_of({})); }

}  // namespace

const std::string& frame_transforms_schema() {
  static const std::string schema =
      object_of({{"transforms", array_of(object_of({{"timestamp", time_type()},
                                                    {"parent_frame_id", {{"type", "string"}}},
                                                    {"child_frame_id", {{"type", "string"}}},
                                                    {"translation", vector3_type()},
                                                    {"rotation", quaternion_type()}}))}})
          .dump();
  return schema;
}

const std::string& joint_state_schema() {
  static const std::string schema = object_of({{"header", header_type()},
                                               {"name", array_of({{"type", "string"}})},
                                               {"position", array_of(number_type())},
                                               {"velocity", array_of(number_type())},
                                               {"effort", array_of(number_type())}})
                                        .dump();
  return schema;
}

const std::string& odometry_schema() {
  static const std::string schema =
      object_of({{"header", header_type()},
                 {"child_frame_id", {{"type", "string"}}},
                 {"pose", object_of({{"pose", pose_type()}, {"covariance", array_of(number_type())}})},
                 {"twist", object_of({{"twist", object_of({{"linear", vector3_type()}, {"angular", vector3_type()}})},
                                      {"covariance", array_of(number_type())}})}})
          .dump();
  return schema;
}

const std::string& laser_scan_schema() {
  static const std::string schema = object_of({{"timestamp", time_type()},
                                               {"frame_id", {{"type", "string"}}},
                                               {"pose", pose_type()},
                                               {"start_angle", number_type()},
                                               {"end_angle", number_type()},
                                               {"ranges", array_of(number_type())},
                                               {"intensities", array_of(number_type())}})
                                        .dump();
  return schema;
}

const std::string& string_schema() {
  static const std::string schema = object_of({{"data", {{"type", "string"}}}}).dump();
  return schema;
}

const std::string& scene_update_schema() {
  static const std::string schema =
      object_of({{"deletions", empty_array()},
                 {"entities", array_of(object_of({{"timestamp", time_type()},
                                                  {"frame_id", {{"type", "string"}}},
                                                  {"id", {{"type", "string"}}},
                                                  {"lifetime", time_type()},
                                                  {"frame_locked", {{"type", "boolean"}}},
                                                  {"metadata", empty_array()},
                                                  {"arrows", empty_array()},
                                                  {"cubes", empty_array()},
                                                  {"spheres", array_of(object_of({{"pose", pose_type()},
                                                                                  {"size", vector3_type()},
                                                                                  {"color", color_type()}}))},
                                                  {"cylinders", empty_array()},
                                                  {"lines", array_of(object_of({{"type", {{"type", "integer"}}},
                                                                                {"pose", pose_type()},
                                                                                {"thickness", number_type()},
                                                                                {"scale_invariant", {{"type", "boolean"}}},
                                                                                {"points", array_of(vector3_type())},
                                                                                {"color", color_type()},
                                                                                {"colors", empty_array()},
                                                                                {"indices", empty_array()}}))},
                                                  {"triangles", empty_array()},
                                                  {"texts", empty_array()},
                                                  {"models", empty_array()}}))}})
          .dump();
  return schema;
}

}  // namespace mechsim::live
