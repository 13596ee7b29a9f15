#pragma once
// Private to the SDF module (description/sdformat): one libsdformat model (DOM) to an SdfModel.

#include <string>

#include <sdf/Model.hh>

#include "description/sdf/sdf_model.hpp"
#include "description/sdf/sdf_paths.hpp"

namespace mechsim::description::sdf_detail {

// `pose`: the model frame in its parent (resolved by the caller). Throws SdfError naming the
// model, the element and its file and line.
SdfModel convert_model(const sdf::Model& model, const Pose& pose, const SdfSearch& search);

// "<file>:<line>" of an element, or its file alone.
std::string where(const sdf::ElementPtr& element);

}  // namespace mechsim::description::sdf_detail
