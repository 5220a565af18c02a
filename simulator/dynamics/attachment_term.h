#pragma once
/// Barycentric attachments: a node of one body (a polyp's or myoma's base) bound by a zero-length
/// spring to the point of a host tet that held it at rest, p = Σ w_k x_k (the host tet's nodes
/// and the node's barycentric weights at rest), so a pathology moves with the wall it grows on.
/// E = ½ k |x_n − Σ w_k x_k|²: linear, its Hessian k c cᵀ ⊗ I with c = (1, −w) is constant and
/// positive semi-definite.

#include <memory>
#include <vector>

#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

struct Attachment {
  int body = 0;                    ///< the attached body (pathology)
  int node = 0;                    ///< its body-local node
  int host = 0;                    ///< host body
  int tet = 0;                     ///< host-local tet
  std::array<double, 4> weight{};  ///< barycentric of the node's rest position in that tet
  Vec3 host_rest = Vec3::Zero();   ///< the bound point in the host's rest space, m
  double stiffness = 0.0;          ///< N/m
};

/// Barycentric coordinates of `p` in the tet of `mesh` that contains it, or — outside every
/// tet — in the tet whose clamped barycentric point is nearest; returns the tet (−1 for a mesh
/// without tets).
int locate_in_tets(const core::TetMesh& mesh, const Vec3& p, std::array<double, 4>& weight);

class AttachmentTerm : public ForceTerm {
 public:
  /// `models` indexed by body; attachments name body-local nodes and tets.
  AttachmentTerm(std::vector<Attachment> attachments,
                 std::vector<std::shared_ptr<const BodyModel>> models,
                 const SimulationState& state);
  std::string name() const override { return "attachments"; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  /// A re-meshed host: every attachment on it is located anew from its host_rest point in the
  /// host's new rest mesh; a re-meshed attached body keeps nodes that still exist.
  void topology_changed(const SimulationState& state, int body) override;
  /// Drops the attachments of the nodes of `body` flagged in `released` (BodyTopology), before
  /// the topology change that renumbers nothing below their count.
  void release(int body, std::span<const std::uint8_t> released);
  const std::vector<Attachment>& attachments() const { return attachments_; }

 private:
  void resolve(const SimulationState& state);
  std::vector<Attachment> attachments_;
  std::vector<std::shared_ptr<const BodyModel>> models_;
  std::vector<std::array<int, 5>> global_;  ///< node, then the host tet's four nodes
};

}  // namespace viscera::sim
