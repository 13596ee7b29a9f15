#include "mechanism/transmission_factory.hpp"

#include <array>
#include <string_view>

#include "mechanism/differential_transmission.hpp"
#include "mechanism/four_bar_transmission.hpp"
#include "mechanism/pr2_gripper_transmission.hpp"
#include "mechanism/pr2_wrist_transmission.hpp"
#include "mechanism/simple_transmission.hpp"
#include "mechanism/transmission_builder.hpp"

namespace mechsim::mechanism {

namespace {

using Builder = std::unique_ptr<Transmission> (*)(TransmissionBuilder&);

struct TypeEntry {
  std::string_view name;
  Builder build;
};

// "SimpleTransmission" without a package is the pre-Electric PR2 spelling.
constexpr std::array kTypes{
    TypeEntry{"transmission_interface/SimpleTransmission", &build_simple_transmission},
    TypeEntry{"pr2_mechanism_model/SimpleTransmission", &build_simple_transmission},
    TypeEntry{"SimpleTransmission", &build_simple_transmission},
    TypeEntry{"transmission_interface/DifferentialTransmission", &build_differential_transmission},
    TypeEntry{"transmission_interface/FourBarLinkageTransmission", &build_four_bar_transmission},
    TypeEntry{"pr2_mechanism_model/WristTransmission", &build_pr2_wrist_transmission},
    TypeEntry{"WristTransmission", &build_pr2_wrist_transmission},
    TypeEntry{"pr2_mechanism_model/PR2GripperTransmission", &build_pr2_gripper_transmission},
    TypeEntry{"PR2GripperTransmission", &build_pr2_gripper_transmission},
};

}  // namespace

std::unique_ptr<Transmission> build_transmission(TransmissionBuilder& builder) {
  const std::string& type = builder.spec().type;
  for (const TypeEntry& t : kTypes)
    if (t.name == type) return t.build(builder);
  std::string known;
  for (const TypeEntry& t : kTypes) known += (known.empty() ? "" : ", ") + std::string(t.name);
  builder.fail(type.empty() ? "no transmission type given (known: " + known + ")"
                            : "unknown transmission type '" + type + "' (known: " + known + ")");
}

bool is_simple_transmission_type(const std::string& type) {
  for (const TypeEntry& t : kTypes)
    if (t.name == type) return t.build == &build_simple_transmission;
  return false;
}

std::vector<std::string> known_transmission_types() {
  std::vector<std::string> out;
  for (const TypeEntry& t : kTypes) out.emplace_back(t.name);
  return out;
}

}  // namespace mechsim::mechanism
