// Which middleware's framing a service request has (service.hpp).
#include "ros2/service.hpp"

namespace mechsim::ros2 {

std::string user_data_value(const std::string& user_data, const std::string& key) {
  const std::string needle = key + "=";
  std::size_t at = 0;
  while ((at = user_data.find(needle, at)) != std::string::npos) {
    if (at == 0 || user_data[at - 1] == ';') {
      const std::size_t start = at + needle.size();
      const std::size_t end = user_data.find(';', start);
      return user_data.substr(start, end == std::string::npos ? std::string::npos : end - start);
    }
    at += needle.size();
  }
  return "";
}

ClientForm client_form(const SampleInfo& info, const std::string& user_data) {
  // rmw_fastrtps sends its reply reader's GUID as the request's related_sample_identity.
  if (info.related.writer != Guid{}) return ClientForm::FastRtps;
  if (!user_data_value(user_data, "clientid").empty()) return ClientForm::CycloneDds;
  // GUID prefixes start with the vendor id: Eclipse Cyclone DDS is 0x0110.
  if (info.identity.writer[0] == 0x01 && info.identity.writer[1] == 0x10) return ClientForm::CycloneDds;
  return ClientForm::FastRtps;
}

}  // namespace mechsim::ros2
