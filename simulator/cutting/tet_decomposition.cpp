#include "simulator/cutting/tet_decomposition.h"

#include <stdexcept>

namespace viscera::sim::cutting {
namespace {

using Children = std::vector<std::array<int, 4>>;

int edge_index(int a, int b) {
  for (int e = 0; e < 6; ++e) {
    if ((kTetEdges[e][0] == a && kTetEdges[e][1] == b) ||
        (kTetEdges[e][0] == b && kTetEdges[e][1] == a)) {
      return e;
    }
  }
  throw std::logic_error("decompose: corners are not an edge");
}

// The diagonal of quad (a, b, c, d), in cyclic order, through its lowest-ranked corner:
// true for a–c, false for b–d.
bool diagonal_ac(const TetCutPattern& p, int a, int b, int c, int d) {
  std::uint64_t low = p.rank[a];
  bool ac = true;
  for (int v : {b, c, d}) {
    if (p.rank[v] < low) {
      low = p.rank[v];
      ac = (v == c);
    }
  }
  return ac;
}

// Pyramid with apex `apex` over quad (a, b, c, d).
void pyramid(const TetCutPattern& p, int apex, int a, int b, int c, int d, Children& out) {
  if (diagonal_ac(p, a, b, c, d)) {
    out.push_back({apex, a, b, c});
    out.push_back({apex, a, c, d});
  } else {
    out.push_back({apex, a, b, d});
    out.push_back({apex, b, c, d});
  }
}

// Prism with triangles (a0, a1, a2) and (b0, b1, b2) and lateral edges ai–bi, split with the
// lowest-rank diagonals on its three quads.
void prism(const TetCutPattern& p, const std::array<int, 3>& a, const std::array<int, 3>& b,
           Children& out) {
  // The lowest-ranked corner owns the diagonals of both quads it lies on.
  int best = 0;
  bool in_a = true;
  for (int i = 0; i < 3; ++i) {
    if (p.rank[a[i]] < (in_a ? p.rank[a[best]] : p.rank[b[best]])) best = i, in_a = true;
    if (p.rank[b[i]] < (in_a ? p.rank[a[best]] : p.rank[b[best]])) best = i, in_a = false;
  }
  const int i = best, j = (best + 1) % 3, k = (best + 2) % 3;
  const int apex = in_a ? a[i] : b[i];
  // The tet cut off at the apex: the apex with the opposite triangle.
  if (in_a) {
    out.push_back({apex, b[0], b[1], b[2]});
  } else {
    out.push_back({apex, a[0], a[1], a[2]});
  }
  // The remaining pyramid over quad (aj, ak, bk, bj).
  pyramid(p, apex, a[j], a[k], b[k], b[j], out);
}

}  // namespace

std::vector<std::array<int, 4>> decompose(const TetCutPattern& pattern) {
  int cuts = 0;
  for (int e = 0; e < 6; ++e) {
    const int sa = pattern.side[kTetEdges[e][0]], sb = pattern.side[kTetEdges[e][1]];
    const bool opposite = sa * sb < 0;
    if (opposite != pattern.edge_cut[e]) {
      throw std::logic_error("decompose: cut edges disagree with the corner sides");
    }
    cuts += opposite ? 1 : 0;
  }
  Children out;
  const auto node = [&](int a, int b) { return 4 + edge_index(a, b); };
  if (cuts == 0) return out;
  if (cuts == 1) {
    for (int e = 0; e < 6; ++e) {
      if (!pattern.edge_cut[e]) continue;
      const int a = kTetEdges[e][0], b = kTetEdges[e][1];
      std::array<int, 4> first{0, 1, 2, 3}, second{0, 1, 2, 3};
      first[b] = 4 + e;
      second[a] = 4 + e;
      out.push_back(first);
      out.push_back(second);
    }
    return out;
  }
  // The lone corner: the corner on the side that holds one corner only (for 4 cuts: corner 0).
  int plus = 0, minus = 0;
  for (int s : pattern.side)
    plus += s > 0, minus += s < 0;
  if (cuts == 2 || cuts == 3) {
    const int lone_side = plus == 1 ? 1 : -1;
    int lone = -1;
    std::vector<int> others, zeros;
    for (int c = 0; c < 4; ++c) {
      if (pattern.side[c] == lone_side && lone < 0) {
        lone = c;
      } else if (pattern.side[c] == 0) {
        zeros.push_back(c);
      } else {
        others.push_back(c);
      }
    }
    if (cuts == 2) {
      const int z = zeros.at(0), q1 = others.at(0), q2 = others.at(1);
      const int m1 = node(lone, q1), m2 = node(lone, q2);
      out.push_back({lone, m1, m2, z});
      pyramid(pattern, z, m1, q1, q2, m2, out);
    } else {
      const int q1 = others.at(0), q2 = others.at(1), q3 = others.at(2);
      const int m1 = node(lone, q1), m2 = node(lone, q2), m3 = node(lone, q3);
      out.push_back({lone, m1, m2, m3});
      prism(pattern, {m1, m2, m3}, {q1, q2, q3}, out);
    }
    return out;
  }
  if (cuts == 4) {
    std::vector<int> p, q;
    for (int c = 0; c < 4; ++c)
      (pattern.side[c] > 0 ? p : q).push_back(c);
    const int p1 = p.at(0), p2 = p.at(1), q1 = q.at(0), q2 = q.at(1);
    const int m11 = node(p1, q1), m12 = node(p1, q2), m21 = node(p2, q1), m22 = node(p2, q2);
    prism(pattern, {p1, m11, m12}, {p2, m21, m22}, out);
    prism(pattern, {q1, m11, m21}, {q2, m12, m22}, out);
    return out;
  }
  throw std::logic_error("decompose: a planar cut crosses at most four edges of a tet");
}

}  // namespace viscera::sim::cutting
