#pragma once
// ROS 2 names as rcl resolves them, and their DDS form (rmw's mangling).
//
//   node namespace  absolute ("/", "/cc8"); a node's fully qualified name is ns + "/" + name
//   topic           "/abs", "rel" (-> ns/rel) or "~/priv" (-> ns/node/priv)
//   remapping       "from:=to", both expanded in the node's context; a topic whose expanded name
//                   equals an expanded `from` takes the expanded `to` (gazebo_ros' <remapping>)
//   DDS topic       "rt" + the fully qualified name (topics); "rq"/"rr" + name + "Request"/"Reply"
//                   (services)
//
// Names are checked as rcl checks them: tokens of [A-Za-z0-9_], not starting with a digit, no
// "//", no trailing "/". A bad one throws NameError naming it and why.

#include <stdexcept>
#include <string>
#include <vector>

namespace mechsim::ros2 {

struct NameError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Remap {
  std::string from, to;  // as written ("~/out", "scan", "/cc8/cmd_vel")
};

// "/" or "/a/b" from "", "a/b", "/a/b/" (a namespace always absolute, no trailing "/").
std::string normalize_namespace(const std::string& ns);
// Throws NameError unless `name` is a valid node name (one token).
void check_node_name(const std::string& name);
// The fully qualified name of `topic` for node `name` in namespace `ns`. Throws NameError.
std::string expand_topic(const std::string& topic, const std::string& ns, const std::string& name);
// expand_topic, then the first matching remapping.
std::string resolve_topic(const std::string& topic, const std::string& ns, const std::string& name,
                          const std::vector<Remap>& remaps);
// "from:=to" -> Remap; throws NameError when there is no ":=".
Remap parse_remap(const std::string& rule);

// DDS topic names of a fully qualified ROS name.
std::string dds_topic(const std::string& fq_name);            // "rt" + name
std::string dds_request_topic(const std::string& fq_name);    // "rq" + name + "Request"
std::string dds_reply_topic(const std::string& fq_name);      // "rr" + name + "Reply"
// The ROS name of a DDS topic name of those forms ("" when it is none of them).
std::string ros_topic_of(const std::string& dds_name);

}  // namespace mechsim::ros2
