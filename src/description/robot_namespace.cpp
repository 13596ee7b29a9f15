#include "description/robot_namespace.hpp"

#include <tinyxml2.h>

namespace mechsim::description {

namespace {

void add_to_plugins(tinyxml2::XMLElement& parent, const std::string& ns, tinyxml2::XMLDocument& doc) {
  for (tinyxml2::XMLElement* c = parent.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::string(c->Name()) == "plugin" && c->FirstChildElement("robotNamespace") == nullptr) {
      tinyxml2::XMLElement* key = doc.NewElement("robotNamespace");
      key->SetText(ns.c_str());
      c->InsertEndChild(key);
    }
    add_to_plugins(*c, ns, doc);
  }
}

}  // namespace

std::string with_robot_namespace(const std::string& xml, const std::string& robot_namespace) {
  if (robot_namespace.empty()) return xml;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) return xml;
  const std::string root = doc.RootElement()->Name();
  if (root != "robot" && root != "sdf") return xml;
  add_to_plugins(*doc.RootElement(), robot_namespace, doc);
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace mechsim::description
