#pragma once
// Transmission types by the name a URDF's <transmission type="..."> or <type> gives them.

#include <memory>
#include <string>
#include <vector>

#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;

// Builds the transmission that builder.spec() describes; MechanismError for an unknown type.
std::unique_ptr<Transmission> build_transmission(TransmissionBuilder& builder);

// Whether `type` names a SimpleTransmission (any of its spellings).
bool is_simple_transmission_type(const std::string& type);

// The type names build_transmission accepts.
std::vector<std::string> known_transmission_types();

}  // namespace mechsim::mechanism
