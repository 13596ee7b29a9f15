// `mechsim view`'s pieces on a real report (a 0.4 s run of a two-link robot): the folder check
// and its messages for incomplete, foreign and truncated folders; the HTTP server on loopback
// (the page, status.json, only listed report files, a busy port); the self-contained export.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <unistd.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "web/page_export.hpp"
#include "web/replay_folder.hpp"
#include "web/view_server.hpp"

namespace mechsim::web {
namespace {

namespace fs = std::filesystem;
namespace http = boost::beast::http;

constexpr const char* kRobot = R"(<robot name="two">
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><box size="0.3 0.3 0.1"/></geometry></visual>
    <collision><geometry><box size="0.3 0.3 0.1"/></geometry></collision>
  </link>
  <joint name="j" type="continuous"><parent link="base"/><child link="top"/><origin xyz="0 0 0.2"/><axis xyz="0 0 1"/></joint>
  <link name="top">
    <inertial><mass value="0.2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><sphere radius="0.05"/></geometry></visual>
  </link>
</robot>)";

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class ViewTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(fs::temp_directory_path() / ("mechsim_view_" + std::to_string(::getpid())));
    fs::create_directories(*root_);
    std::ofstream(*root_ / "two.urdf") << kRobot;
    std::ofstream(*root_ / "s.yaml") << "name: two_links\nrobot: {description: two.urdf}\nspawn: {z: 0.05}\nduration: 0.4\n";
    sim::RunOptions options;
    options.output_dir = (*root_ / "report").string();
    options.plots = false;
    const sim::ScenarioResult r = sim::run_scenario(sim::load_scenario((*root_ / "s.yaml").string()), options);
    ASSERT_TRUE(r.completed) << r.error;
    fs::create_directories(*root_ / "page");
    std::ofstream(*root_ / "page" / "index.html") << "<html><body><!--MECHSIM_EMBED-->\n<script src=\"app.js\"></script></body></html>";
    std::ofstream(*root_ / "page" / "app.js") << "console.log('</script>' + 1);";
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }
  // A copy of the good report to spoil.
  fs::path copy(const std::string& name) {
    const fs::path to = *root_ / name;
    fs::remove_all(to);
    fs::copy(*root_ / "report", to, fs::copy_options::recursive);
    return to;
  }
  static fs::path* root_;
};
fs::path* ViewTest::root_ = nullptr;

TEST_F(ViewTest, AWholeReportIsOkAndListsThePagesFiles) {
  const ReplayFolder f = check_replay_folder(*root_ / "report");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.scenario, "two_links");
  for (const char* file : {"replay/manifest.json", "replay/robot.json", "replay/world.json", "replay/poses.bin"}) {
    EXPECT_NE(std::find(f.files.begin(), f.files.end(), file), f.files.end()) << file;
  }
}

TEST_F(ViewTest, BadFoldersSayWhatAndWhere) {
  auto error_of = [](const fs::path& dir) {
    const ReplayFolder f = check_replay_folder(dir);
    EXPECT_FALSE(f.ok);
    return f.error;
  };
  EXPECT_NE(error_of(*root_ / "nowhere").find("no such report folder"), std::string::npos);
  EXPECT_NE(error_of(*root_ / "page").find("not a scenario report"), std::string::npos);

  const fs::path no_replay = copy("no_replay");
  fs::remove_all(no_replay / "replay");
  EXPECT_NE(error_of(no_replay).find("no replay/ folder"), std::string::npos);

  const fs::path unfinished = copy("unfinished");
  fs::remove(unfinished / "replay" / "manifest.json");
  EXPECT_NE(error_of(unfinished).find("replay/manifest.json: missing"), std::string::npos);

  const fs::path newer = copy("newer");
  nlohmann::json manifest = nlohmann::json::parse(read(newer / "replay" / "manifest.json"));
  manifest["version"] = 99;
  std::ofstream(newer / "replay" / "manifest.json") << manifest.dump();
  const std::string version_error = error_of(newer);
  EXPECT_NE(version_error.find("replay format version 99, this mechsim reads version 1"), std::string::npos) << version_error;

  const fs::path garbled = copy("garbled");
  std::ofstream(garbled / "replay" / "manifest.json") << "{\"format\": ";
  EXPECT_NE(error_of(garbled).find("replay/manifest.json: not a JSON object"), std::string::npos);

  const fs::path truncated = copy("truncated");
  fs::resize_file(truncated / "replay" / "poses.bin", fs::file_size(truncated / "replay" / "poses.bin") - 10);
  EXPECT_NE(error_of(truncated).find("replay/poses.bin: "), std::string::npos);
  EXPECT_NE(error_of(truncated).find("truncated"), std::string::npos);

  const fs::path no_robot = copy("no_robot");
  fs::remove(no_robot / "replay" / "robot.json");
  EXPECT_NE(error_of(no_robot).find("replay/robot.json: missing"), std::string::npos);

  const fs::path escape = copy("escape");
  manifest = nlohmann::json::parse(read(escape / "replay" / "manifest.json"));
  manifest["plots"] = {{{"file", "../../two.urdf"}}};
  std::ofstream(escape / "replay" / "manifest.json") << manifest.dump();
  EXPECT_NE(error_of(escape).find("points outside the report folder"), std::string::npos);

  // Objects listed that the frames do not hold.
  const fs::path objects = copy("objects");
  manifest = nlohmann::json::parse(read(objects / "replay" / "manifest.json"));
  manifest["objects"] = {"crate"};
  std::ofstream(objects / "replay" / "manifest.json") << manifest.dump();
  const std::string objects_error = error_of(objects);
  EXPECT_NE(objects_error.find("does not fit"), std::string::npos) << objects_error;
  EXPECT_NE(objects_error.find("and 1 objects"), std::string::npos) << objects_error;
}

// One GET on 127.0.0.1:port: (status, body).
std::pair<int, std::string> get(unsigned short port, const std::string& target) {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket socket(io);
  socket.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  http::request<http::empty_body> request(http::verb::get, target, 11);
  request.set(http::field::host, "127.0.0.1");
  http::write(socket, request);
  boost::beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(socket, buffer, response);
  return {static_cast<int>(response.result_int()), response.body()};
}

TEST_F(ViewTest, ServesThePageStatusAndOnlyTheListedReportFiles) {
  ViewServer server(*root_ / "report", *root_ / "page", 0);
  ASSERT_NE(server.port(), 0);
  std::atomic<int> stop{0};
  std::thread thread([&] { server.run(stop); });
  const auto [page_status, page] = get(server.port(), "/");
  EXPECT_EQ(page_status, 200);
  EXPECT_NE(page.find("MECHSIM_EMBED"), std::string::npos);
  const auto [status_code, status] = get(server.port(), "/status.json");
  EXPECT_EQ(status_code, 200);
  EXPECT_TRUE(nlohmann::json::parse(status)["ok"].get<bool>()) << status;
  const auto [poses_code, poses] = get(server.port(), "/report/replay/poses.bin");
  EXPECT_EQ(poses_code, 200);
  EXPECT_EQ(poses, read(*root_ / "report" / "replay" / "poses.bin"));
  EXPECT_EQ(get(server.port(), "/report/summary.json").first, 404) << "not a file the page reads";
  EXPECT_EQ(get(server.port(), "/report/../two.urdf").first, 404);
  EXPECT_EQ(get(server.port(), "/report/replay/../../two.urdf").first, 404);
  EXPECT_EQ(get(server.port(), "/nothing").first, 404);

  // A port in use: a clear error, and the running server goes on.
  try {
    ViewServer second(*root_ / "report", *root_ / "page", server.port());
    ADD_FAILURE() << "a second server bound port " << server.port();
  } catch (const ViewError& e) {
    EXPECT_NE(std::string(e.what()).find("port " + std::to_string(server.port()) + " on 127.0.0.1 is in use"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(get(server.port(), "/status.json").first, 200);

  // The folder is checked at every request: a report rewritten under the server says so.
  const fs::path manifest = *root_ / "report" / "replay" / "manifest.json";
  const std::string saved = read(manifest);
  fs::rename(manifest, manifest.string() + ".away");
  const auto [code, text] = get(server.port(), "/status.json");
  fs::rename(manifest.string() + ".away", manifest);
  EXPECT_EQ(code, 200);
  EXPECT_FALSE(nlohmann::json::parse(text)["ok"].get<bool>());
  EXPECT_NE(nlohmann::json::parse(text)["error"].get<std::string>().find("manifest.json: missing"), std::string::npos);
  stop = 1;
  thread.join();
}

TEST_F(ViewTest, Base64MatchesRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST_F(ViewTest, ExportInlinesTheScriptAndEveryFile) {
  const ReplayFolder f = check_replay_folder(*root_ / "report");
  ASSERT_TRUE(f.ok) << f.error;
  const fs::path out = *root_ / "page.html";
  export_page(f, *root_ / "page", out);
  const std::string html = read(out);
  EXPECT_EQ(html.find("src=\"app.js\""), std::string::npos);
  EXPECT_NE(html.find("console.log('<\\/script>' + 1);"), std::string::npos) << "no early </script>";
  const std::size_t start = html.find("window.MECHSIM_EMBED = ") + 23;
  const std::size_t end = html.find(";</script>", start);
  const nlohmann::json embed = nlohmann::json::parse(html.substr(start, end - start));
  EXPECT_EQ(embed["files"].size(), f.files.size());
  EXPECT_EQ(embed["files"]["replay/poses.bin"], base64(read(*root_ / "report" / "replay" / "poses.bin")));

  ReplayFolder bad = f;
  bad.ok = false;
  bad.error = "replay/manifest.json: missing";
  EXPECT_THROW(export_page(bad, *root_ / "page", *root_ / "bad.html"), ViewError);
}

}  // namespace
}  // namespace mechsim::web
