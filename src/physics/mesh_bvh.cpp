#include "physics/mesh_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace mechsim::physics {

namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();

using V3 = std::array<double, 3>;

void grow(V3& lo, V3& hi, const V3& p) {
  for (int i = 0; i < 3; ++i) {
    lo[static_cast<std::size_t>(i)] = std::min(lo[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(i)]);
    hi[static_cast<std::size_t>(i)] = std::max(hi[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(i)]);
  }
}

// Entry distance of the ray into the box within [0, t_max], or +inf when it misses (slab test;
// `inv` is the inverse direction with a huge finite value for a zero component, so that no slab
// gives NaN: a ray parallel to a slab inside it gets (-huge, +huge), outside an empty range).
double enter(const V3& lo, const V3& hi, const double p[3], const double inv[3], double t_max) {
  double t0 = 0.0, t1 = t_max;
  for (std::size_t i = 0; i < 3; ++i) {
    const double a = (lo[i] - p[i]) * inv[i];
    const double b = (hi[i] - p[i]) * inv[i];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t0 <= t1 ? t0 : kInf;
}

// 1 / x, or +-1e300 for x = 0 (sign of x's zero).
double safe_inverse(double x) { return x != 0.0 ? 1.0 / x : std::copysign(1e300, x); }

}  // namespace

MeshBvh::MeshBvh(const float* vertices, int vertex_count, const int* faces, int face_count) {
  if (vertex_count < 0 || face_count < 0) throw std::logic_error("MeshBvh: negative sizes");
  std::vector<Triangle> source(static_cast<std::size_t>(face_count));
  std::vector<V3> centroids(source.size());
  const auto vertex = [&](int index) {
    if (index < 0 || index >= vertex_count) {
      throw std::logic_error("MeshBvh: vertex index " + std::to_string(index) + " of " + std::to_string(vertex_count));
    }
    const float* v = vertices + 3 * static_cast<std::ptrdiff_t>(index);
    return V3{v[0], v[1], v[2]};
  };
  for (std::size_t f = 0; f < source.size(); ++f) {
    const int* face = faces + 3 * f;
    const V3 a = vertex(face[0]), b = vertex(face[1]), c = vertex(face[2]);
    source[f] = {a, {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, {c[0] - a[0], c[1] - a[1], c[2] - a[2]}};
    centroids[f] = {(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0, (a[2] + b[2] + c[2]) / 3.0};
  }
  std::vector<std::uint32_t> order(source.size());
  std::iota(order.begin(), order.end(), 0u);
  nodes_.reserve(2 * source.size() + 1);
  nodes_.emplace_back();
  build(0, 0, static_cast<std::uint32_t>(source.size()), source, centroids, order);
  triangles_.reserve(source.size());
  for (const std::uint32_t i : order) triangles_.push_back(source[i]);
}

void MeshBvh::build(std::size_t node, std::uint32_t first, std::uint32_t count, const std::vector<Triangle>& source,
                    const std::vector<V3>& centroids, std::vector<std::uint32_t>& order) {
  V3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  V3 clo = lo, chi = hi;
  for (std::uint32_t k = first; k < first + count; ++k) {
    const Triangle& t = source[order[k]];
    grow(lo, hi, t.a);
    grow(lo, hi, {t.a[0] + t.e1[0], t.a[1] + t.e1[1], t.a[2] + t.e1[2]});
    grow(lo, hi, {t.a[0] + t.e2[0], t.a[1] + t.e2[1], t.a[2] + t.e2[2]});
    grow(clo, chi, centroids[order[k]]);
  }
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  if (count <= kLeafSize) {
    nodes_[node].first = first;
    nodes_[node].count = count;
    return;
  }
  std::size_t axis = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (chi[i] - clo[i] > chi[axis] - clo[axis]) axis = i;
  const std::uint32_t half = count / 2;
  const auto begin = order.begin() + first;
  std::nth_element(begin, begin + half, begin + count,
                   [&](std::uint32_t x, std::uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(left, first, half, source, centroids, order);
  build(left + 1, first + half, count - half, source, centroids, order);
}

double MeshBvh::intersect(const double p[3], const double v[3], double t_max) const noexcept {
  if (triangles_.empty()) return -1.0;
  const double inv[3] = {safe_inverse(v[0]), safe_inverse(v[1]), safe_inverse(v[2])};
  double best = t_max;
  bool hit = false;
  // Nodes to visit with the distance at which the ray enters them.
  struct Entry {
    std::uint32_t node;
    double t;
  };
  Entry stack[64];
  int top = 0;
  const double t_root = enter(nodes_[0].lo, nodes_[0].hi, p, inv, best);
  if (t_root == kInf) return -1.0;
  stack[top++] = {0, t_root};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > best) continue;  // a nearer hit was found since it was pushed
    const Node& n = nodes_[e.node];
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        // Moller-Trumbore, either side.
        const Triangle& t = triangles_[k];
        const double q[3] = {v[1] * t.e2[2] - v[2] * t.e2[1], v[2] * t.e2[0] - v[0] * t.e2[2],
                             v[0] * t.e2[1] - v[1] * t.e2[0]};
        const double det = t.e1[0] * q[0] + t.e1[1] * q[1] + t.e1[2] * q[2];
        if (det == 0.0) continue;
        const double f = 1.0 / det;
        const double s[3] = {p[0] - t.a[0], p[1] - t.a[1], p[2] - t.a[2]};
        const double u = f * (s[0] * q[0] + s[1] * q[1] + s[2] * q[2]);
        if (u < 0.0 || u > 1.0) continue;
        const double r[3] = {s[1] * t.e1[2] - s[2] * t.e1[1], s[2] * t.e1[0] - s[0] * t.e1[2],
                             s[0] * t.e1[1] - s[1] * t.e1[0]};
        const double w = f * (v[0] * r[0] + v[1] * r[1] + v[2] * r[2]);
        if (w < 0.0 || u + w > 1.0) continue;
        const double d = f * (t.e2[0] * r[0] + t.e2[1] * r[1] + t.e2[2] * r[2]);
        if (d > 0.0 && d <= best) {
          best = d;
          hit = true;
        }
      }
      continue;
    }
    // Nearer child last on the stack (visited first); a child entered beyond `best` is skipped.
    const double t_left = enter(nodes_[n.first].lo, nodes_[n.first].hi, p, inv, best);
    const double t_right = enter(nodes_[n.first + 1].lo, nodes_[n.first + 1].hi, p, inv, best);
    const bool left_first = t_left <= t_right;
    const double t_far = left_first ? t_right : t_left, t_near = left_first ? t_left : t_right;
    if (t_far != kInf && top < 64) stack[top++] = {left_first ? n.first + 1 : n.first, t_far};
    if (t_near != kInf && top < 64) stack[top++] = {left_first ? n.first : n.first + 1, t_near};
  }
  return hit ? best : -1.0;
}

}  // namespace mechsim::physics
