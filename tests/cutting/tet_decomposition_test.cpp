#include "simulator/cutting/tet_decomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "core/mesh/tet_mesh.h"
#include "simulator/cutting/cut_classification.h"

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

// Every consistent side assignment: corners −1/0/+1, edges cut where the sides are opposite.
std::vector<std::array<int, 4>> all_sides() {
  std::vector<std::array<int, 4>> out;
  for (int code = 0; code < 81; ++code) {
    std::array<int, 4> s{};
    int c = code;
    for (int i = 0; i < 4; ++i)
      s[i] = c % 3 - 1, c /= 3;
    out.push_back(s);
  }
  return out;
}

TetCutPattern pattern_for(const std::array<int, 4>& sides,
                          const std::array<std::uint64_t, 10>& rank) {
  TetCutPattern p;
  p.side = sides;
  p.rank = rank;
  for (int e = 0; e < 6; ++e)
    p.edge_cut[e] = sides[kTetEdges[e][0]] * sides[kTetEdges[e][1]] < 0;
  return p;
}

TEST(TetDecomposition, every_pattern_tiles_the_tet_with_positive_pieces_on_one_side_each) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> t_of(0.2, 0.8);
  const std::array<Vec3, 4> corner{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.2, 1, 0),
                                   Vec3(0.3, 0.3, 1)};
  std::set<std::size_t> child_counts;
  for (const auto& sides : all_sides()) {
    for (int trial = 0; trial < 20; ++trial) {
      std::array<std::uint64_t, 10> rank{};
      for (auto& r : rank)
        r = rng() % 1000;
      const TetCutPattern p = pattern_for(sides, rank);
      std::array<Vec3, 10> x{};
      for (int i = 0; i < 4; ++i)
        x[i] = corner[i];
      for (int e = 0; e < 6; ++e) {
        const double t = t_of(rng);
        x[4 + e] = (1 - t) * corner[kTetEdges[e][0]] + t * corner[kTetEdges[e][1]];
      }
      const auto children = decompose(p);
      int cuts = 0;
      for (bool c : p.edge_cut)
        cuts += c;
      if (cuts == 0) {
        EXPECT_TRUE(children.empty());
        continue;
      }
      child_counts.insert(children.size());
      double volume = 0.0;
      for (const auto& c : children) {
        const double v = std::abs(core::signed_volume(x[c[0]], x[c[1]], x[c[2]], x[c[3]]));
        EXPECT_GT(v, 1e-6);
        volume += v;
        // No child holds corners of both sides.
        int plus = 0, minus = 0;
        for (int k : c) {
          if (k < 4) plus += sides[k] > 0, minus += sides[k] < 0;
        }
        EXPECT_FALSE(plus > 0 && minus > 0);
      }
      EXPECT_NEAR(volume, core::signed_volume(corner[0], corner[1], corner[2], corner[3]), 1e-12);
    }
  }
  // The four cut patterns: 1, 2, 3 or 4 cut edges give 2, 3, 4 or 6 tets.
  EXPECT_EQ(child_counts, (std::set<std::size_t>{2, 3, 4, 6}));
}

// The triangles a decomposition puts on the face (corners f0, f1, f2 of the tet), written with
// global ids so two tets sharing the face can be compared.
std::set<std::array<std::uint64_t, 3>> face_triangles(
    const std::vector<std::array<int, 4>>& children, const std::array<int, 3>& face,
    const std::array<std::uint64_t, 10>& global) {
  std::set<int> on_face(face.begin(), face.end());
  for (int e = 0; e < 6; ++e) {
    if (on_face.count(kTetEdges[e][0]) && on_face.count(kTetEdges[e][1])) on_face.insert(4 + e);
  }
  std::set<std::array<std::uint64_t, 3>> out;
  for (const auto& c : children) {
    std::vector<std::uint64_t> in;
    for (int k : c) {
      if (on_face.count(k)) in.push_back(global[k]);
    }
    if (in.size() == 3) {
      std::sort(in.begin(), in.end());
      out.insert({in[0], in[1], in[2]});
    }
  }
  return out;
}

TEST(TetDecomposition, two_tets_split_their_shared_face_the_same_way) {
  // Tets A = (0,1,2,3) and B = (0,1,2,4) share face (0,1,2); global nodes 0–4, edge nodes by key.
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<int, 5> s{};
    for (int& v : s)
      v = static_cast<int>(rng() % 3) - 1;
    std::array<int, 5> id{};
    for (int i = 0; i < 5; ++i)
      id[i] = static_cast<int>(rng() % 100) * 5 + i;
    const auto global_of = [&](const std::array<int, 4>& nodes) {
      std::array<std::uint64_t, 10> g{};
      for (int i = 0; i < 4; ++i)
        g[i] = static_cast<std::uint64_t>(id[nodes[i]]);
      for (int e = 0; e < 6; ++e) {
        g[4 + e] = (std::uint64_t{1} << 62) +
                   edge_key(id[nodes[kTetEdges[e][0]]], id[nodes[kTetEdges[e][1]]]);
      }
      return g;
    };
    const std::array<int, 4> a{0, 1, 2, 3}, b{0, 1, 2, 4};
    const auto ga = global_of(a), gb = global_of(b);
    const auto pa = pattern_for({s[0], s[1], s[2], s[3]}, ga);
    const auto pb = pattern_for({s[0], s[1], s[2], s[4]}, gb);
    const auto ca = decompose(pa), cb = decompose(pb);
    // An uncut tet keeps the face whole; the other must then not split it either.
    std::vector<std::uint64_t> whole{ga[0], ga[1], ga[2]};
    std::sort(whole.begin(), whole.end());
    const std::set<std::array<std::uint64_t, 3>> unsplit{{whole[0], whole[1], whole[2]}};
    const auto fa = ca.empty() ? unsplit : face_triangles(ca, {0, 1, 2}, ga);
    const auto fb = cb.empty() ? unsplit : face_triangles(cb, {0, 1, 2}, gb);
    EXPECT_EQ(fa, fb) << "trial " << trial;
  }
}

}  // namespace
}  // namespace viscera::sim::cutting
