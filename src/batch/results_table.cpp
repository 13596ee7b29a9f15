#include "batch/results_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "batch/point_result.hpp"

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c == '\n' ? ' ' : c;
  }
  return out + "\"";
}

void write_aside(const fs::path& file, const std::string& text) {
  const fs::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
  }
  fs::rename(tmp, file);
}

}  // namespace

std::string table_number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}

Table collect_table(const fs::path& dir, const Plan& plan) {
  Table t;
  t.columns = {"index", "status", "passed"};
  for (const PlanAxis& a : plan.axes) t.columns.push_back(a.path);
  t.columns.push_back("checks_passed");
  t.columns.push_back("checks_total");
  for (const std::string& m : plan.metrics) t.columns.push_back(m);
  t.columns.push_back("error");
  for (const Point& p : plan.points) {
    std::vector<std::string> row{std::to_string(p.index)};
    const auto r = read_point_result(point_dir(dir, p.index));
    const bool passed = r && r->status == PointStatus::Passed;
    row.push_back(r ? status_name(r->status) : "missing");
    row.push_back(passed ? "1" : "0");
    for (const std::string& v : p.values) row.push_back(v);
    std::size_t checks_passed = 0;
    if (r) {
      for (const auto& c : r->checks) checks_passed += c.second ? 1 : 0;
    }
    row.push_back(r ? std::to_string(checks_passed) : "");
    row.push_back(r ? std::to_string(r->checks.size()) : "");
    for (const std::string& m : plan.metrics) {
      std::string cell;
      if (r) {
        if (const auto found = r->metrics.find(m); found != r->metrics.end()) cell = table_number(found->second);
      }
      row.push_back(cell);
    }
    row.push_back(r ? r->error : "");
    t.rows.push_back(std::move(row));
    if (!r) ++t.missing;
    else ++(passed ? t.passed : t.not_passed);
  }
  return t;
}

void write_table(const fs::path& dir, const Plan& plan, const Table& t) {
  std::string csv;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (c) csv += ',';
    csv += csv_field(t.columns[c]);
  }
  csv += "\n";
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) csv += ',';
      csv += csv_field(row[c]);
    }
    csv += "\n";
  }
  write_aside(dir / "results.csv", csv);

  nlohmann::ordered_json j;
  j["name"] = plan.name;
  j["scenario"] = plan.scenario;
  j["points_total"] = plan.points.size();
  j["passed"] = t.passed;
  j["not_passed"] = t.not_passed;
  j["missing"] = t.missing;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& row : t.rows) {
    nlohmann::ordered_json r;
    std::size_t c = 0;
    r["index"] = std::stoul(row[c++]);
    r["status"] = row[c++];
    r["passed"] = row[c++] == "1";
    nlohmann::ordered_json values;
    for (const PlanAxis& a : plan.axes) values[a.path] = row[c++];
    r["values"] = values;
    r["checks_passed"] = row[c].empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(std::stoul(row[c]));
    ++c;
    r["checks_total"] = row[c].empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(std::stoul(row[c]));
    ++c;
    nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
    for (const std::string& m : plan.metrics) {
      const std::string& v = row[c++];
      metrics[m] = v.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(std::stod(v));
    }
    r["metrics"] = metrics;
    r["error"] = row[c];
    rows.push_back(r);
  }
  j["points"] = rows;
  write_aside(dir / "results.json", j.dump(1) + "\n");
}

}  // namespace mechsim::batch
