#include "simulator/dynamics/attachment_term.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

namespace viscera::sim {
namespace {

std::array<double, 4> barycentric(const std::array<Vec3, 4>& p, const Vec3& q) {
  Eigen::Matrix3d a;
  a << p[1] - p[0], p[2] - p[0], p[3] - p[0];
  const Vec3 w = a.fullPivLu().solve(q - p[0]);
  return {1.0 - w.sum(), w[0], w[1], w[2]};
}

}  // namespace

int locate_in_tets(const core::TetMesh& mesh, const Vec3& p, std::array<double, 4>& weight) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& n = mesh.tets[t];
    const std::array<Vec3, 4> x{mesh.nodes[n[0]], mesh.nodes[n[1]], mesh.nodes[n[2]],
                                mesh.nodes[n[3]]};
    std::array<double, 4> w = barycentric(x, p);
    if (*std::min_element(w.begin(), w.end()) >= 0.0) {
      weight = w;
      return static_cast<int>(t);
    }
    // Outside: clamp to the tet (negative weights to zero, renormalised) and measure.
    double sum = 0.0;
    for (double& v : w)
      sum += v = std::max(v, 0.0);
    if (!(sum > 0.0)) continue;
    Vec3 q = Vec3::Zero();
    for (int k = 0; k < 4; ++k)
      q += (w[k] / sum) * x[k];
    const double distance = (q - p).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(t);
      for (int k = 0; k < 4; ++k)
        weight[k] = w[k] / sum;
    }
  }
  return best;
}

AttachmentTerm::AttachmentTerm(std::vector<Attachment> attachments,
                               std::vector<std::shared_ptr<const BodyModel>> models,
                               const SimulationState& state)
    : attachments_(std::move(attachments)), models_(std::move(models)) {
  resolve(state);
}

void AttachmentTerm::resolve(const SimulationState& state) {
  global_.clear();
  for (const Attachment& a : attachments_) {
    const int host_first = state.body(a.host).first;
    const auto& tet =
        models_[static_cast<std::size_t>(a.host)]->mesh.tets[static_cast<std::size_t>(a.tet)];
    global_.push_back({state.body(a.body).first + a.node, host_first + tet[0], host_first + tet[1],
                       host_first + tet[2], host_first + tet[3]});
  }
}

void AttachmentTerm::release(int body, std::span<const std::uint8_t> released) {
  std::erase_if(attachments_, [&](const Attachment& a) {
    return a.body == body && a.node >= 0 && static_cast<std::size_t>(a.node) < released.size() &&
           released[static_cast<std::size_t>(a.node)] != 0;
  });
}

void AttachmentTerm::topology_changed(const SimulationState& state, int body) {
  std::vector<Attachment> kept;
  for (Attachment a : attachments_) {
    if (a.body == body && a.node >= state.body(body).count) continue;
    if (a.host == body) {
      a.tet = locate_in_tets(models_[static_cast<std::size_t>(body)]->mesh, a.host_rest, a.weight);
      if (a.tet < 0) continue;
    }
    kept.push_back(a);
  }
  attachments_ = std::move(kept);
  resolve(state);
}

double AttachmentTerm::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t s = 0; s < attachments_.size(); ++s) {
    const auto& n = global_[s];
    const auto& w = attachments_[s].weight;
    const Vec3 gap = x[n[0]] - (w[0] * x[n[1]] + w[1] * x[n[2]] + w[2] * x[n[3]] + w[3] * x[n[4]]);
    e += 0.5 * attachments_[s].stiffness * gap.squaredNorm();
  }
  return e;
}

double AttachmentTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                  std::span<Vec3> f) const {
  double e = 0.0;
  for (std::size_t s = 0; s < attachments_.size(); ++s) {
    const auto& n = global_[s];
    const auto& w = attachments_[s].weight;
    const Vec3 gap = x[n[0]] - (w[0] * x[n[1]] + w[1] * x[n[2]] + w[2] * x[n[3]] + w[3] * x[n[4]]);
    const Vec3 pull = attachments_[s].stiffness * gap;
    f[n[0]] -= pull;
    for (int k = 0; k < 4; ++k)
      f[n[k + 1]] += w[k] * pull;
    e += 0.5 * attachments_[s].stiffness * gap.squaredNorm();
  }
  return e;
}

void AttachmentTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& n : global_)
    pattern.add_clique(n);
}

void AttachmentTerm::add_stiffness(std::span<const Vec3>, double scale, bool,
                                   BlockSparseMatrix& m) const {
  for (std::size_t s = 0; s < attachments_.size(); ++s) {
    const auto& n = global_[s];
    const auto& w = attachments_[s].weight;
    const double c[5] = {1.0, -w[0], -w[1], -w[2], -w[3]};
    const double k = scale * attachments_[s].stiffness;
    for (int a = 0; a < 5; ++a)
      for (int b = a; b < 5; ++b) {
        if (n[a] == n[b] && a != b) continue;  // never the case for a node outside its host
        m.add_symmetric(n[a], n[b], (k * c[a] * c[b]) * Mat3::Identity());
      }
  }
}

}  // namespace viscera::sim
