// The mesh BVH against a test of every triangle (the reference: what mj_rayMesh does) on random
// triangle soups and a closed sphere, from outside and inside, with limits.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "physics/mesh_bvh.hpp"

namespace mechsim::physics {
namespace {

struct Mesh {
  std::vector<float> vertices;
  std::vector<int> faces;
  int vertex_count() const { return static_cast<int>(vertices.size() / 3); }
  int face_count() const { return static_cast<int>(faces.size() / 3); }
};

// Every triangle, nearest hit in (0, t_max] (Moller-Trumbore in long double), or -1.
double brute_force(const Mesh& m, const double p[3], const double v[3], double t_max) {
  long double best = t_max;
  bool hit = false;
  for (int f = 0; f < m.face_count(); ++f) {
    long double a[3], e1[3], e2[3];
    for (int i = 0; i < 3; ++i) {
      const float* A = &m.vertices[static_cast<std::size_t>(3 * m.faces[static_cast<std::size_t>(3 * f)])];
      const float* B = &m.vertices[static_cast<std::size_t>(3 * m.faces[static_cast<std::size_t>(3 * f + 1)])];
      const float* C = &m.vertices[static_cast<std::size_t>(3 * m.faces[static_cast<std::size_t>(3 * f + 2)])];
      a[i] = A[i];
      e1[i] = static_cast<long double>(B[i]) - A[i];
      e2[i] = static_cast<long double>(C[i]) - A[i];
    }
    const long double q[3] = {v[1] * e2[2] - v[2] * e2[1], v[2] * e2[0] - v[0] * e2[2], v[0] * e2[1] - v[1] * e2[0]};
    const long double det = e1[0] * q[0] + e1[1] * q[1] + e1[2] * q[2];
    if (det == 0) continue;
    const long double s[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const long double u = (s[0] * q[0] + s[1] * q[1] + s[2] * q[2]) / det;
    const long double r[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const long double w = (v[0] * r[0] + v[1] * r[1] + v[2] * r[2]) / det;
    const long double t = (e2[0] * r[0] + e2[1] * r[1] + e2[2] * r[2]) / det;
    if (u < 0 || w < 0 || u + w > 1 || t <= 0 || t > best) continue;
    best = t;
    hit = true;
  }
  return hit ? static_cast<double>(best) : -1.0;
}

Mesh soup(std::mt19937_64& rng, int triangles) {
  std::uniform_real_distribution<float> centre(-1.0f, 1.0f), edge(-0.15f, 0.15f);
  Mesh m;
  for (int t = 0; t < triangles; ++t) {
    const float c[3] = {centre(rng), centre(rng), centre(rng)};
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) m.vertices.push_back(c[i] + edge(rng));
      m.faces.push_back(3 * t + k);
    }
  }
  return m;
}

// A UV sphere of radius 0.5 (shared vertices).
Mesh sphere(int rings, int segments) {
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    const double th = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double ph = 2.0 * M_PI * s / segments;
      m.vertices.push_back(static_cast<float>(0.5 * std::sin(th) * std::cos(ph)));
      m.vertices.push_back(static_cast<float>(0.5 * std::sin(th) * std::sin(ph)));
      m.vertices.push_back(static_cast<float>(0.5 * std::cos(th)));
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const int a = r * segments + s, b = r * segments + (s + 1) % segments;
      const int c = a + segments, d = b + segments;
      for (const int i : {a, c, b, b, c, d}) m.faces.push_back(i);
    }
  return m;
}

struct Agreement {
  int rays = 0, hits = 0, disagree = 0;
  double worst = 0.0;
};

Agreement compare(const Mesh& m, std::mt19937_64& rng, int rays, double origin_spread, double t_max) {
  const MeshBvh bvh(m.vertices.data(), m.vertex_count(), m.faces.data(), m.face_count());
  std::uniform_real_distribution<double> pos(-origin_spread, origin_spread);
  std::normal_distribution<double> dir(0.0, 1.0);
  Agreement a;
  for (int i = 0; i < rays; ++i) {
    const double p[3] = {pos(rng), pos(rng), pos(rng)};
    double v[3] = {dir(rng), dir(rng), dir(rng)};
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (double& x : v) x /= n;
    if (i % 7 == 0) v[i % 3] = 0.0;  // rays parallel to a box face
    const double want = brute_force(m, p, v, t_max);
    const double got = bvh.intersect(p, v, t_max);
    ++a.rays;
    if ((want < 0) != (got < 0)) {
      ++a.disagree;
      continue;
    }
    if (want >= 0) {
      ++a.hits;
      a.worst = std::max(a.worst, std::abs(want - got));
    }
  }
  return a;
}

TEST(MeshBvh, AgreesWithEveryTriangleOnARandomSoup) {
  std::mt19937_64 rng(7);
  const Mesh m = soup(rng, 3000);
  const Agreement a = compare(m, rng, 20000, 2.0, 10.0);
  EXPECT_EQ(a.disagree, 0);
  EXPECT_GT(a.hits, 3000);
  EXPECT_LT(a.worst, 1e-9);
}

TEST(MeshBvh, ClosedSphereFromInsideAndOutsideAndWithinALimit) {
  std::mt19937_64 rng(11);
  const Mesh m = sphere(24, 48);
  const MeshBvh bvh(m.vertices.data(), m.vertex_count(), m.faces.data(), m.face_count());
  EXPECT_EQ(bvh.triangle_count(), 24u * 48u * 2u);
  const Agreement inside = compare(m, rng, 5000, 0.2, 10.0);
  EXPECT_EQ(inside.disagree, 0);
  EXPECT_EQ(inside.hits, inside.rays);  // every ray from inside leaves through the surface
  EXPECT_LT(inside.worst, 1e-9);
  const Agreement limited = compare(m, rng, 5000, 1.5, 0.6);  // many hits lie beyond 0.6
  EXPECT_EQ(limited.disagree, 0);
  EXPECT_LT(limited.worst, 1e-9);
  // Straight at the pole from outside: the surface at z = 0.5 (the pole vertex).
  const double p[3] = {0.0, 0.0, 2.0}, v[3] = {0.0, 0.0, -1.0};
  EXPECT_NEAR(bvh.intersect(p, v, 10.0), 1.5, 1e-6);
  EXPECT_EQ(bvh.intersect(p, v, 1.4), -1.0);
}

TEST(MeshBvh, EmptyMeshAndBadIndices) {
  const MeshBvh empty(nullptr, 0, nullptr, 0);
  const double p[3] = {0, 0, 0}, v[3] = {1, 0, 0};
  EXPECT_EQ(empty.intersect(p, v, 1.0), -1.0);
  const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int faces[3] = {0, 1, 3};
  EXPECT_THROW(MeshBvh(vertices, 3, faces, 1), std::logic_error);
}

}  // namespace
}  // namespace mechsim::physics
