// Which middleware's framing a service request has (service.hpp).
#include <gtest/gtest.h>

#include "ros2/service.hpp"

namespace mechsim::ros2 {
namespace {

TEST(Service, ReadsUserDataKeys) {
  EXPECT_EQ(user_data_value("typehash=RIHS01_ab;clientid=01.10.aa;", "clientid"), "01.10.aa");
  EXPECT_EQ(user_data_value("serviceid=x;", "clientid"), "");
  EXPECT_EQ(user_data_value("myclientid=1;clientid=2;", "clientid"), "2");
  EXPECT_EQ(user_data_value("clientid=3", "clientid"), "3");
}

TEST(Service, TellsTheClientsFraming) {
  SampleInfo fast;
  fast.identity.writer = {0x01, 0x0f, 1, 2};
  fast.related.writer = {0x01, 0x0f, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x04, 0x04};  // its reply reader
  EXPECT_EQ(client_form(fast, ""), ClientForm::FastRtps);
  SampleInfo cyclone;
  cyclone.identity.writer = {0x01, 0x10, 9};
  EXPECT_EQ(client_form(cyclone, "clientid=01.10.09;"), ClientForm::CycloneDds);
  EXPECT_EQ(client_form(cyclone, ""), ClientForm::CycloneDds);  // Cyclone's vendor id
  SampleInfo other;
  other.identity.writer = {0x01, 0x01, 9};
  EXPECT_EQ(client_form(other, ""), ClientForm::FastRtps);
}

}  // namespace
}  // namespace mechsim::ros2
