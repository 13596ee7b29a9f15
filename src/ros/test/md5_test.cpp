// Every ROS type mechsim builds against must carry the checksum that ROS 1 computes for it, or
// roscpp/rospy peers reject the connection. The reference is ../shared/msgs/md5sums.tsv; the
// table compared with it is written by CMake (ros_type_checksums.hpp) from the traits of the
// generated (and Debian's) headers.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <stdexcept>
#include <vector>

#include "ros_type_checksums.hpp"

namespace mechsim::ros {
namespace {

struct TsvRow {
  std::string kind;
  std::string md5;
  int line = 0;
};

// type -> row of md5sums.tsv (columns: type, kind, md5, fields; first line is the header).
std::map<std::string, TsvRow> readChecksumTable(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::map<std::string, TsvRow> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 || line.empty()) continue;
    std::istringstream cols(line);
    std::string type;
    TsvRow row;
    row.line = number;
    if (!std::getline(cols, type, '\t') || !std::getline(cols, row.kind, '\t') ||
        !std::getline(cols, row.md5, '\t')) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) +
                               ": fewer than 3 tab-separated columns");
    }
    if (!rows.emplace(type, row).second) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) +
                               ": duplicate type " + type);
    }
  }
  return rows;
}

const std::filesystem::path kTablePath =
    std::filesystem::path(MECHSIM_SHARED_DIR) / "msgs" / "md5sums.tsv";

TEST(RosTypeChecksums, HeaderDatatypeMatchesListedName) {
  const auto table = generatedTypeChecksums();
  ASSERT_FALSE(table.empty());
  for (const auto& t : table) {
    EXPECT_EQ(t.datatype, t.type) << "DataType trait of " << t.type;
    EXPECT_EQ(t.md5.size(), 32u) << t.type;
  }
}

TEST(RosTypeChecksums, EveryTableRowMatchesGeneratedHeaders) {
  if (!std::filesystem::exists(kTablePath)) {
    GTEST_SKIP() << "shared checksum table not found at " << kTablePath
                 << " (../shared is absent); cannot compare ROS checksums";
  }
  const auto reference = readChecksumTable(kTablePath);
  ASSERT_FALSE(reference.empty()) << kTablePath;

  const auto table = generatedTypeChecksums();
  std::map<std::string, const TypeChecksum*> ours;
  for (const auto& t : table) {
    ASSERT_TRUE(ours.emplace(t.type, &t).second) << "type listed twice in CMake: " << t.type;
  }

  std::size_t matching = 0;
  for (const auto& [type, row] : reference) {
    const auto it = ours.find(type);
    if (it == ours.end()) {
      ADD_FAILURE() << kTablePath.string() << ":" << row.line << ": " << type
                    << " has no generated or listed header";
      continue;
    }
    EXPECT_EQ(it->second->kind, row.kind) << "kind of " << type;
    EXPECT_EQ(it->second->md5, row.md5) << "MD5Sum of " << type << " (table line " << row.line << ")";
    if (it->second->md5 == row.md5 && it->second->kind == row.kind) ++matching;
  }
  for (const auto& [type, entry] : ours) {
    EXPECT_TRUE(reference.count(type)) << type << " is built but missing from " << kTablePath;
  }
  EXPECT_EQ(ours.size(), reference.size());
  EXPECT_EQ(matching, reference.size()) << "types whose kind and MD5 match the table";
  std::cout << "[ ROS md5  ] " << matching << "/" << reference.size() << " types match "
            << kTablePath.string() << "\n";
}

}  // namespace
}  // namespace mechsim::ros
