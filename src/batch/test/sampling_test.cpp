// The points of a sweep: products, draws, Latin hypercube strata, and the same points from the
// same seed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "batch/sampling.hpp"

namespace mechsim::batch::test {
namespace {

Axis list_axis(std::string path, std::vector<std::string> values) {
  Axis a;
  a.path = std::move(path);
  a.kind = Axis::Kind::List;
  a.values = std::move(values);
  return a;
}

Axis range_axis(std::string path, Axis::Kind kind, double a, double b, int steps = 0) {
  Axis x;
  x.path = std::move(path);
  x.kind = kind;
  x.a = a;
  x.b = b;
  x.steps = steps;
  return x;
}

std::vector<double> column(const std::vector<Point>& points, std::size_t axis) {
  std::vector<double> out;
  for (const Point& p : points) out.push_back(std::stod(p.values[axis]));
  return out;
}

TEST(Sampling, GridsAndListsMakeTheProductFirstAxisSlowest) {
  SweepSpec s;
  s.axes = {list_axis("world.seed", {"1", "2"}), range_axis("spawn.yaw", Axis::Kind::Grid, -0.5, 0.5, 3)};
  const std::vector<Point> p = plan_points(s);
  ASSERT_EQ(p.size(), 6u);
  const std::vector<std::vector<std::string>> expected = {{"1", "-0.5"}, {"1", "0.0"}, {"1", "0.5"},
                                                          {"2", "-0.5"}, {"2", "0.0"}, {"2", "0.5"}};
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p[i].index, i);
    EXPECT_EQ(p[i].values, expected[i]) << i;
  }
}

TEST(Sampling, RandomDrawsAreRepeatableAndEachAxisHasItsOwnStream) {
  SweepSpec s;
  s.samples = 50;
  s.seed = 3;
  s.axes = {range_axis("a", Axis::Kind::Uniform, 2, 8)};
  const std::vector<Point> one = plan_points(s);
  EXPECT_EQ(plan_points(s)[17].values, one[17].values);
  for (double v : column(one, 0)) {
    EXPECT_GE(v, 2.0);
    EXPECT_LT(v, 8.0);
  }
  // A list axis in front multiplies the points; the draws are the same for each of its values.
  s.axes.insert(s.axes.begin(), list_axis("b", {"x", "y"}));
  const std::vector<Point> two = plan_points(s);
  ASSERT_EQ(two.size(), 100u);
  for (std::size_t k = 0; k < 50; ++k) {
    EXPECT_EQ(two[k].values[1], two[50 + k].values[1]);
  }
  // Another seed, other values.
  s.seed = 4;
  EXPECT_NE(plan_points(s)[0].values[1], two[0].values[1]);
}

TEST(Sampling, NormalAndLogUniformHaveTheirShape) {
  SweepSpec s;
  s.samples = 20000;
  s.axes = {range_axis("n", Axis::Kind::Normal, 1.0, 0.1), range_axis("l", Axis::Kind::LogUniform, 1e-3, 1e-1)};
  const std::vector<Point> p = plan_points(s);
  const std::vector<double> n = column(p, 0), l = column(p, 1);
  double mean = 0, var = 0;
  for (double v : n) mean += v / static_cast<double>(n.size());
  for (double v : n) var += (v - mean) * (v - mean) / static_cast<double>(n.size() - 1);
  EXPECT_NEAR(mean, 1.0, 0.003);
  EXPECT_NEAR(std::sqrt(var), 0.1, 0.003);
  // Log-uniform: as many draws in each decade.
  const auto below = std::count_if(l.begin(), l.end(), [](double v) { return v < 1e-2; });
  EXPECT_NEAR(static_cast<double>(below) / static_cast<double>(l.size()), 0.5, 0.02);
  for (double v : l) {
    EXPECT_GE(v, 1e-3);
    EXPECT_LE(v, 1e-1);
  }
}

TEST(Sampling, LatinHypercubePutsOneDrawInEachStratumOfEachAxis) {
  SweepSpec s;
  s.samples = 40;
  s.axes = {range_axis("a", Axis::Kind::Lhs, 0, 4), range_axis("b", Axis::Kind::Lhs, -1, 1)};
  const std::vector<Point> p = plan_points(s);
  for (std::size_t axis = 0; axis < 2; ++axis) {
    const double lo = axis == 0 ? 0 : -1, width = axis == 0 ? 4 : 2;
    std::set<int> strata;
    for (double v : column(p, axis)) strata.insert(static_cast<int>(std::floor((v - lo) / width * 40)));
    EXPECT_EQ(strata.size(), 40u) << "axis " << axis;
  }
  // The two axes are shuffled independently: not the same order of strata.
  EXPECT_NE(std::floor(column(p, 0)[0] / 4 * 40), std::floor((column(p, 1)[0] + 1) / 2 * 40));
}

TEST(Sampling, IntegerAxesAndNumbersReadBackExactly) {
  SweepSpec s;
  s.samples = 30;
  Axis seed = range_axis("seed", Axis::Kind::Uniform, 1, 1000);
  seed.integer = true;
  s.axes = {seed, range_axis("x", Axis::Kind::Uniform, 0, 1)};
  for (const Point& p : plan_points(s)) {
    EXPECT_EQ(p.values[0].find_first_not_of("0123456789"), std::string::npos) << p.values[0];
    EXPECT_EQ(format_value(std::stod(p.values[1]), false), p.values[1]);
  }
  EXPECT_EQ(format_value(2.0, false), "2.0");
  EXPECT_EQ(format_value(0.1, false), "0.1");
  EXPECT_EQ(format_value(-0.4, true), "0");
  EXPECT_EQ(format_value(2.5, true), "3");
}

}  // namespace
}  // namespace mechsim::batch::test
