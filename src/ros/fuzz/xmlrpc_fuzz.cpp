// Fuzz target: what the parameter server hands mechsim_node when it reads a controller
// namespace, i.e. an XML-RPC <value> (the master's getParam reply, parsed by roscpp's xmlrpcpp)
// converted to controller parameters (ros/xmlrpc_params.hpp), then every controller it names
// loaded, started, ticked and unloaded as in controllers_fuzz. Values of any type may sit where a
// controller expects another (an int gain, a struct joint name, a list of lists, binary, dates):
// the conversion skips what Params cannot hold with a warning and a controller refuses what it
// cannot use; nothing else may happen.

#include <cstddef>
#include <cstdint>
#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

#include "control/params.hpp"
#include "controller_fuzz_robot.hpp"
#include "ros/xmlrpc_params.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  int offset = 0;
  XmlRpc::XmlRpcValue value(xml, &offset);
  if (!value.valid()) return 0;
  mechsim::control::Params params;
  std::string warning;
  (void)mechsim::ros::fill_params_from_xmlrpc(params, value, &warning);
  mechsim::fuzz::run_controllers(params);
  return 0;
}
