// Parameter server values become the Params tree the controller manager reads.
#include <gmock/gmock.h>

#include "ros/xmlrpc_params.hpp"

namespace mechsim::ros {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

XmlRpc::XmlRpcValue controller() {
  XmlRpc::XmlRpcValue pid;
  pid["p"] = 60.0;
  pid["i"] = 5;  // an int where YAML had "5"
  pid["antiwindup"] = true;
  XmlRpc::XmlRpcValue joints;
  joints.setSize(2);
  joints[0] = std::string("steering_FL");
  joints[1] = std::string("steering_FR");
  XmlRpc::XmlRpcValue numbers;
  numbers.setSize(3);
  numbers[0] = 1;
  numbers[1] = 2.5;
  numbers[2] = -3;
  XmlRpc::XmlRpcValue c;
  c["type"] = std::string("effort_controllers/JointPositionController");
  c["pid"] = pid;
  c["joints"] = joints;
  c["diagonal"] = numbers;
  return c;
}

TEST(XmlRpcParams, NamespaceBecomesATreeWithFullPaths) {
  XmlRpc::XmlRpcValue ns;
  ns["steer"] = controller();
  control::Params root;
  control::Params cc8 = root.child_or_create("cc8");
  std::string warning;
  EXPECT_TRUE(fill_params_from_xmlrpc(cc8, ns, &warning));
  EXPECT_EQ(warning, "");
  const control::Params steer = cc8.child("steer");
  EXPECT_EQ(steer.path(), "/cc8/steer");
  EXPECT_EQ(steer.get<std::string>("type"), "effort_controllers/JointPositionController");
  EXPECT_DOUBLE_EQ(steer.get<double>("pid/p"), 60.0);
  EXPECT_EQ(steer.get<int>("pid/i"), 5);
  EXPECT_DOUBLE_EQ(steer.get<double>("pid/i"), 5.0) << "an int reads as a double too";
  EXPECT_TRUE(steer.get<bool>("pid/antiwindup"));
  EXPECT_THAT(steer.get<std::vector<std::string>>("joints"), ElementsAre("steering_FL", "steering_FR"));
  EXPECT_THAT(steer.get<std::vector<double>>("diagonal"), ElementsAre(1.0, 2.5, -3.0));
}

TEST(XmlRpcParams, ReloadReplacesValues) {
  control::Params root;
  std::string warning;
  ASSERT_TRUE(set_param_from_xmlrpc(root, "steer", controller(), &warning));
  XmlRpc::XmlRpcValue changed = controller();
  changed["pid"]["p"] = 10.0;
  ASSERT_TRUE(set_param_from_xmlrpc(root, "steer", changed, &warning));
  EXPECT_DOUBLE_EQ(root.get<double>("steer/pid/p"), 10.0);
}

TEST(XmlRpcParams, UnsupportedValuesAreNamedAndSkipped) {
  XmlRpc::XmlRpcValue mixed;
  mixed.setSize(2);
  mixed[0] = 1.0;
  mixed[1] = std::string("x");
  XmlRpc::XmlRpcValue c = controller();
  c["mixed"] = mixed;
  control::Params root;
  control::Params cc8 = root.child_or_create("cc8");
  std::string warning;
  EXPECT_FALSE(set_param_from_xmlrpc(cc8, "steer", c, &warning));
  EXPECT_THAT(warning, HasSubstr("/cc8/steer/mixed"));
  EXPECT_FALSE(cc8.has("steer/mixed"));
  EXPECT_EQ(cc8.get<std::string>("steer/type"), "effort_controllers/JointPositionController") << "the rest is kept";

  XmlRpc::XmlRpcValue scalar = 3.0;
  warning.clear();
  EXPECT_FALSE(fill_params_from_xmlrpc(cc8, scalar, &warning));
  EXPECT_THAT(warning, HasSubstr("/cc8"));
}

}  // namespace
}  // namespace mechsim::ros
