#include "simulator/cutting/visual_surface_cut.h"

#include <algorithm>
#include <optional>
#include <span>
#include <unordered_map>

namespace viscera::sim::cutting {
namespace {

using core::Tetrahedron;
using core::Vec3;

struct Embedded {
  int tet = 0;
  std::array<double, 4> weights{};
};

// The barycentric embedding of rest point p among candidate tets: the one holding it, or the
// one whose smallest weight is largest.
Embedded embed_among(const Vec3& p, std::span<const int> candidates, const core::TetMesh& mesh) {
  Embedded best{candidates.front(), {0.25, 0.25, 0.25, 0.25}};
  double best_low = -1e300;
  for (int t : candidates) {
    const Tetrahedron& q = mesh.tets[t];
    const auto w = core::barycentric(p, mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]],
                                     mesh.nodes[q[3]]);
    const double low = std::min({w[0], w[1], w[2], w[3]});
    if (low > best_low) best_low = low, best = {t, w};
  }
  return best;
}

class VisualCutter {
 public:
  VisualCutter(const core::SurfaceMesh& visual, const core::SurfaceEmbedding& embedding,
               const core::TetMesh& body, const std::vector<Vec3>& old_current,
               const CutSurfaceIndex& index, TopologyChange& change)
      : in_(visual), emb_(embedding), body_(body), old_x_(old_current), index_(index), c_(change) {}

  void run() {
    // The new tets of each old tet (CSR: piece_offset_ per old tet into pieces_).
    piece_offset_.assign(body_.tets.size() + 1, 0);
    for (int p : c_.tet_parent)
      ++piece_offset_[p + 1];
    for (std::size_t t = 0; t < body_.tets.size(); ++t)
      piece_offset_[t + 1] += piece_offset_[t];
    pieces_.resize(c_.tet_parent.size());
    std::vector<int> fill(piece_offset_.begin(), piece_offset_.end() - 1);
    for (int t = 0; t < static_cast<int>(c_.tet_parent.size()); ++t)
      pieces_[fill[c_.tet_parent[t]]++] = t;
    out_ = in_;
    out_.triangles.clear();
    const std::size_t n = in_.vertices.size();
    // Cut faces of earlier cuts stay cut faces.
    cut_flag_.assign(n, 0);
    if (const auto it = in_.vertex_attributes.find("cut_face");
        it != in_.vertex_attributes.end() && it->second.size() == n) {
      for (std::size_t i = 0; i < n; ++i)
        cut_flag_[i] = it->second[i] > 0.5 ? 1 : 0;
    }
    material_.resize(n);
    current_.resize(n);
    outcode_.resize(n);
    c_.visual_embedding.tet.resize(n);
    c_.visual_embedding.weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Tetrahedron& q = body_.tets[emb_.tet[i]];
      material_[i].setZero();
      current_[i].setZero();
      for (int k = 0; k < 4; ++k) {
        material_[i] += emb_.weights[i][k] * body_.nodes[q[k]];
        current_[i] += emb_.weights[i][k] * old_x_[q[k]];
      }
      outcode_[i] = index_.outcode(current_[i]);
      const std::span<const int> candidates(pieces_.data() + piece_offset_[emb_.tet[i]],
                                            pieces_.data() + piece_offset_[emb_.tet[i] + 1]);
      const auto& now = c_.mesh.tets[emb_.tet[i]];
      const bool same =
          candidates.size() == 1 && now == q && c_.mesh.nodes[q[0]] == body_.nodes[q[0]] &&
          c_.mesh.nodes[q[1]] == body_.nodes[q[1]] && c_.mesh.nodes[q[2]] == body_.nodes[q[2]] &&
          c_.mesh.nodes[q[3]] == body_.nodes[q[3]];
      if (same) {
        c_.visual_embedding.tet[i] = emb_.tet[i];
        c_.visual_embedding.weights[i] = emb_.weights[i];
      } else {
        const Embedded e = embed_among(material_[i], candidates, c_.mesh);
        c_.visual_embedding.tet[i] = e.tet;
        c_.visual_embedding.weights[i] = e.weights;
      }
    }
    for (const auto& tri : in_.triangles)
      split_triangle(tri);
    add_cut_faces();
    finish_attributes();
    c_.visual = std::move(out_);
  }

 private:
  // A copy of the point at parameter t on visual edge a→b, on a's side, embedded near a.
  int crossing_vertex(int a, int b, double t) {
    const std::uint64_t k = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
    if (const auto it = crossing_.find(k); it != crossing_.end()) return it->second;
    const int v = add_vertex_between(a, b, t);
    // The crossing point lies on the cut at the border of a's piece: it follows that piece.
    const int host = c_.visual_embedding.tet[a];
    const Embedded e = embed_among(material_[v], std::span<const int>(&host, 1), c_.mesh);
    c_.visual_embedding.tet.push_back(e.tet);
    c_.visual_embedding.weights.push_back(e.weights);
    crossing_.emplace(k, v);
    return v;
  }

  int add_vertex_between(int a, int b, double t) {
    const int v = static_cast<int>(out_.vertices.size());
    out_.vertices.push_back((1 - t) * in_.vertices[a] + t * in_.vertices[b]);
    if (!in_.normals.empty()) {
      out_.normals.push_back(((1 - t) * in_.normals[a] + t * in_.normals[b]).normalized());
    }
    if (!in_.uvs.empty()) out_.uvs.push_back((1 - t) * in_.uvs[a] + t * in_.uvs[b]);
    for (auto& [name, values] : out_.vertex_attributes) {
      const auto& src = in_.vertex_attributes.at(name);
      values.push_back((1 - t) * src[a] + t * src[b]);
    }
    material_.push_back((1 - t) * material_[a] + t * material_[b]);
    current_.push_back((1 - t) * current_[a] + t * current_[b]);
    // A point on an earlier cut face's edge is on that cut face.
    cut_flag_.push_back(cut_flag_[a] != 0 && cut_flag_[b] != 0 ? 1 : 0);
    return v;
  }

  void split_triangle(const core::Triangle& tri) {
    double t[3];
    int crossed = 0, lone = -1;
    for (int e = 0; e < 3; ++e) {
      const int a = tri[e], b = tri[(e + 1) % 3];
      const auto hit =
          (outcode_[a] & outcode_[b]) ? std::nullopt : index_.crossing(current_[a], current_[b]);
      t[e] = hit ? hit->t : -1.0;
      crossed += hit ? 1 : 0;
    }
    if (crossed != 2) {
      out_.triangles.push_back(tri);
      return;
    }
    // The lone corner is shared by the two crossed edges.
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= 0 && t[(k + 2) % 3] >= 0) lone = k;
    }
    const int a = tri[lone], b = tri[(lone + 1) % 3], c = tri[(lone + 2) % 3];
    const double tab = t[lone], tca = t[(lone + 2) % 3];  // along a→b and c→a
    const int pa = crossing_vertex(a, b, tab), pb = crossing_vertex(b, a, 1.0 - tab);
    const int qa = crossing_vertex(a, c, 1.0 - tca), qc = crossing_vertex(c, a, tca);
    out_.triangles.push_back({a, pa, qa});
    out_.triangles.push_back({pb, b, c});
    out_.triangles.push_back({pb, c, qc});
  }

  void add_cut_faces() {
    std::unordered_map<int, int> vertex_of_node;
    for (std::size_t slot = 0; slot < c_.cut_surface_faces.size(); ++slot) {
      const int f = c_.cut_surface_faces[slot];
      const auto& face = c_.mesh.surface_faces[f];
      core::Triangle tri{};
      for (int k = 0; k < 3; ++k) {
        const int node = face[k];
        auto [it, inserted] = vertex_of_node.try_emplace(node, 0);
        if (inserted) {
          it->second = static_cast<int>(out_.vertices.size());
          out_.vertices.push_back(c_.mesh.nodes[node]);  // rest, like every visual vertex
          if (!in_.normals.empty()) out_.normals.push_back(Vec3::UnitZ());
          if (!in_.uvs.empty()) out_.uvs.push_back(core::Vec2::Zero());
          for (auto& [name, values] : out_.vertex_attributes)
            values.push_back(0.0);
          material_.push_back(c_.mesh.nodes[node]);
          current_.push_back(c_.current[node]);
          cut_flag_.resize(out_.vertices.size(), 0);
          cut_flag_.back() = 1;
          // The node is a corner of the tet the cut face bounds.
          const int tet = c_.cut_face_tets[slot];
          const auto& corners = c_.mesh.tets[tet];
          std::array<double, 4> w{0, 0, 0, 0};
          w[std::find(corners.begin(), corners.end(), node) - corners.begin()] = 1.0;
          c_.visual_embedding.tet.push_back(tet);
          c_.visual_embedding.weights.push_back(w);
        }
        tri[k] = it->second;
      }
      c_.visual_cut_triangles.push_back(static_cast<int>(out_.triangles.size()));
      out_.triangles.push_back(tri);
    }
  }

  void finish_attributes() {
    const std::size_t n = out_.vertices.size();
    cut_flag_.resize(n, 0);
    auto& flag = out_.vertex_attributes["cut_face"];
    auto& mx = out_.vertex_attributes["material_x"];
    auto& my = out_.vertex_attributes["material_y"];
    auto& mz = out_.vertex_attributes["material_z"];
    flag.assign(n, 0.0);
    mx.resize(n);
    my.resize(n);
    mz.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      flag[i] = cut_flag_[i];
      mx[i] = material_[i].x();
      my[i] = material_[i].y();
      mz[i] = material_[i].z();
    }
    if (!out_.normals.empty()) {
      // Cut vertices take the mean normal of their cut triangles.
      for (int f : c_.visual_cut_triangles) {
        const auto& t = out_.triangles[f];
        const Vec3 nrm = (out_.vertices[t[1]] - out_.vertices[t[0]])
                             .cross(out_.vertices[t[2]] - out_.vertices[t[0]]);
        for (int v : t) {
          if (cut_flag_[v]) out_.normals[v] = nrm;  // last one wins before normalising
        }
      }
      for (std::size_t i = 0; i < n; ++i) {
        if (cut_flag_[i] && out_.normals[i].norm() > 0) out_.normals[i].normalize();
      }
    }
  }

  const core::SurfaceMesh& in_;
  const core::SurfaceEmbedding& emb_;
  const core::TetMesh& body_;
  const std::vector<Vec3>& old_x_;
  const CutSurfaceIndex& index_;
  TopologyChange& c_;
  core::SurfaceMesh out_;
  std::vector<int> piece_offset_, pieces_;
  std::vector<std::uint8_t> outcode_;  ///< per input vertex, of its current place
  std::vector<Vec3> material_, current_;
  std::vector<std::uint8_t> cut_flag_;
  std::unordered_map<std::uint64_t, int> crossing_;
};

}  // namespace

void cut_visual_surface(const core::SurfaceMesh& visual, const core::SurfaceEmbedding& embedding,
                        const core::TetMesh& body, const std::vector<Vec3>& old_current,
                        const CutSurfaceIndex& index, TopologyChange& change) {
  VisualCutter(visual, embedding, body, old_current, index, change).run();
}

}  // namespace viscera::sim::cutting
