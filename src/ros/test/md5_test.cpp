// Every ROS type mechsim builds against must carry the checksum that ROS 1 computes for it, or
// roscpp/rospy peers reject the connection. The reference is ../shared/msgs/md5sums.tsv, which
// also lists types mechsim does not build yet; the set mechsim must build is pinned in
// pinned_types.tsv. The table compared with both is written by CMake (ros_type_checksums.hpp)
// from the traits of the generated (and Debian's) headers.

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
    if (line.empty() || line[0] == '#' || line.rfind("type\t", 0) == 0) continue;
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
const std::filesystem::path kUpstreamPath =
    std::filesystem::path(MECHSIM_SOURCE_DIR) / "src" / "ros" / "test" / "upstream_md5s.tsv";
const std::filesystem::path kPinnedPath =
    std::filesystem::path(MECHSIM_SOURCE_DIR) / "src" / "ros" / "test" / "pinned_types.tsv";

// type -> kind of pinned_types.tsv (columns: type, kind; '#' starts a comment line).
std::map<std::string, std::string> readPinnedTypes(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::map<std::string, std::string> pinned;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    if (tab == std::string::npos) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": expected 'type<TAB>kind'");
    }
    if (!pinned.emplace(line.substr(0, tab), line.substr(tab + 1)).second) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) + ": duplicate type");
    }
  }
  return pinned;
}

std::map<std::string, const TypeChecksum*> builtTypes(const std::vector<TypeChecksum>& table) {
  std::map<std::string, const TypeChecksum*> built;
  for (const auto& t : table) {
    if (!built.emplace(t.type, &t).second) ADD_FAILURE() << "type listed twice in CMake: " << t.type;
  }
  return built;
}

TEST(RosTypeChecksums, HeaderDatatypeMatchesListedName) {
  const auto table = generatedTypeChecksums();
  ASSERT_FALSE(table.empty());
  for (const auto& t : table) {
    EXPECT_EQ(t.datatype, t.type) << "DataType trait of " << t.type;
    EXPECT_EQ(t.md5.size(), 32u) << t.type;
  }
}

// The pinned set is what the build must produce: a type dropped from the build (a definition
// deleted, a Debian type no longer listed) fails here, and so does a new type not yet pinned.
TEST(RosTypeChecksums, BuiltTypesAreThePinnedSet) {
  const auto pinned = readPinnedTypes(kPinnedPath);
  ASSERT_FALSE(pinned.empty()) << kPinnedPath;
  const auto table = generatedTypeChecksums();
  const auto built = builtTypes(table);
  for (const auto& [type, kind] : pinned) {
    const auto it = built.find(type);
    if (it == built.end()) {
      ADD_FAILURE() << kPinnedPath.string() << ": " << type << " is pinned but not built";
      continue;
    }
    EXPECT_EQ(it->second->kind, kind) << "kind of " << type << " (pinned in " << kPinnedPath.string() << ")";
  }
  for (const auto& [type, entry] : built) {
    EXPECT_TRUE(pinned.count(type)) << type << " is built but not pinned: add it to " << kPinnedPath.string();
  }
}

// The shared table is the ROS ecosystem's reference: every type mechsim builds must be in it with
// the same kind and MD5. Table types that mechsim does not build yet are counted, not failed.
TEST(RosTypeChecksums, EveryBuiltTypeMatchesTheTable) {
  if (!std::filesystem::exists(kTablePath)) {
    GTEST_SKIP() << "shared checksum table not found at " << kTablePath
                 << " (../shared is absent); cannot compare ROS checksums";
  }
  const auto reference = readChecksumTable(kTablePath);
  ASSERT_FALSE(reference.empty()) << kTablePath;
  const auto table = generatedTypeChecksums();
  const auto built = builtTypes(table);

  // Types the shared table lacks are checked against upstream's published checksums.
  const auto upstream = readChecksumTable(kUpstreamPath);
  std::size_t matching = 0, own = 0;
  for (const auto& [type, entry] : built) {
    // mechsim's own types (mechsim_msgs: /mechsim/step_simulation) have no upstream to match.
    if (type.rfind("mechsim_msgs/", 0) == 0) {
      ++own;
      continue;
    }
    auto it = reference.find(type);
    std::string source = kTablePath.string();
    if (it == reference.end()) {
      it = upstream.find(type);
      source = kUpstreamPath.string();
      if (it == upstream.end()) {
        ADD_FAILURE() << type << " is built but missing from " << kTablePath.string() << " and " << kUpstreamPath.string();
        continue;
      }
    }
    const TsvRow& row = it->second;
    EXPECT_EQ(entry->kind, row.kind) << "kind of " << type << " (" << source << ":" << row.line << ")";
    EXPECT_EQ(entry->md5, row.md5) << "MD5Sum of " << type << " (" << source << ":" << row.line << ")";
    if (entry->md5 == row.md5 && entry->kind == row.kind) ++matching;
  }
  EXPECT_EQ(matching + own, built.size()) << "built types whose kind and MD5 match the table";

  std::vector<std::string> not_built;
  for (const auto& [type, row] : reference) {
    if (!built.count(type)) not_built.push_back(type);
  }
  std::cout << "[ ROS md5  ] " << matching << " of " << built.size() << " built types match "
            << kTablePath.string() << "; " << (reference.size() - not_built.size()) << " of "
            << reference.size() << " table types built";
  if (!not_built.empty()) {
    std::cout << "; not yet built (" << not_built.size() << "):";
    for (const auto& type : not_built) std::cout << " " << type;
  }
  std::cout << "\n";
}

// The project's own table holds only what the shared one lacks (no type checked against two
// references), and only types the build produces.
TEST(RosTypeChecksums, UpstreamTableOnlyAddsBuiltTypesTheSharedTableLacks) {
  const auto upstream = readChecksumTable(kUpstreamPath);
  ASSERT_FALSE(upstream.empty()) << kUpstreamPath;
  const auto table = generatedTypeChecksums();
  const auto built = builtTypes(table);
  for (const auto& [type, row] : upstream) {
    EXPECT_TRUE(built.count(type)) << kUpstreamPath.string() << ":" << row.line << ": " << type << " is not built";
  }
  if (!std::filesystem::exists(kTablePath)) GTEST_SKIP() << "shared checksum table not found at " << kTablePath;
  const auto reference = readChecksumTable(kTablePath);
  for (const auto& [type, row] : upstream) {
    EXPECT_FALSE(reference.count(type)) << kUpstreamPath.string() << ":" << row.line << ": " << type
                                        << " is in the shared table already: remove it here";
  }
}

}  // namespace
}  // namespace mechsim::ros
