#include "simulator/dynamics/contact_term.h"

#include <algorithm>

namespace viscera::sim {
namespace {

std::vector<CollisionBodyView> views_of(const std::vector<std::shared_ptr<const BodyModel>>& models,
                                        const SimulationState& state,
                                        const std::vector<Vec3>& positions) {
  std::vector<CollisionBodyView> views;
  for (const auto& m : models)
    views.push_back({state.range(positions, m->body), m->mesh.tets});
  return views;
}

}  // namespace

BodyContactTerm::BodyContactTerm(std::vector<std::shared_ptr<const BodyModel>> models,
                                 double stiffness, const SimulationState& state)
    : models_(std::move(models)), stiffness_(stiffness) {
  rebuild(state, -1);
}

void BodyContactTerm::rebuild(const SimulationState& state, int changed_body) {
  const auto rest_views = views_of(models_, state, state.rest_positions);
  const std::size_t bodies = models_.size();
  std::size_t changed = bodies;  // index in models_ of the changed body; bodies: all changed
  for (std::size_t b = 0; b < bodies && changed_body >= 0; ++b)
    if (models_[b]->body == changed_body) changed = b;
  if (hash_ == nullptr || changed == bodies) {
    // Cell size: the mean tet edge (Teschner et al. 2003); about two buckets per vertex. A cut
    // keeps the hash: its cells only set the speed of detection, never what is found.
    std::size_t vertices = 0;
    for (const auto& m : models_)
      vertices += static_cast<std::size_t>(state.body(m->body).count);
    hash_ = std::make_unique<SpatialHash>(std::max(mean_edge_length(rest_views), 1e-6),
                                          2 * vertices + 1);
  }
  // Only the changed body's adjacency is rebuilt (all of them when none is named).
  adjacency_.resize(bodies);
  surface_nodes_.clear();
  for (std::size_t b = 0; b < bodies; ++b) {
    const auto& m = models_[b];
    if (changed == bodies || b == changed)
      adjacency_[b] = VertexAdjacency::from_tets(
          static_cast<std::size_t>(state.body(m->body).count), m->mesh.tets);
    std::vector<char> on(static_cast<std::size_t>(state.body(m->body).count), 0);
    for (const auto& f : m->surface)
      for (const int v : f)
        on[static_cast<std::size_t>(v)] = 1;
    for (std::size_t i = 0; i < on.size(); ++i)
      if (on[i]) surface_nodes_.push_back(state.body(m->body).first + static_cast<int>(i));
  }
  find_rest_overlaps(rest_views, changed);
  contacts_.clear();
  declared_.clear();
  structure_changed_ = true;
}

void BodyContactTerm::find_rest_overlaps(const std::vector<CollisionBodyView>& rest_views,
                                         std::size_t changed) {
  // Overlaps of the rest configuration are authored (a polyp's base in its wall): never
  // contacts. After a cut only the pairs with the cut body can differ: its own vertices in the
  // other bodies' tets (only tets near it can hold them) and the others' vertices in its tets.
  const std::size_t bodies = models_.size();
  rest_overlap_.resize(bodies);
  std::vector<CollisionBodyView> views = rest_views;
  std::vector<std::vector<core::Tetrahedron>> near(bodies);
  if (changed == bodies) {
    for (std::size_t b = 0; b < bodies; ++b)
      rest_overlap_[b].assign(rest_views[b].positions.size() * bodies, 0);
  } else {
    core::BoundingBox reach;
    for (const auto& p : rest_views[changed].positions)
      reach.add(p);
    for (std::size_t b = 0; b < bodies; ++b) {
      if (b == changed) {
        rest_overlap_[b].assign(rest_views[b].positions.size() * bodies, 0);
        continue;
      }
      for (std::size_t v = 0; v < rest_views[b].positions.size(); ++v)
        rest_overlap_[b][v * bodies + changed] = 0;
      const auto& x = rest_views[b].positions;
      for (const auto& t : rest_views[b].tets) {
        core::BoundingBox box;
        for (const int v : t)
          box.add(x[static_cast<std::size_t>(v)]);
        if ((box.max.array() >= reach.min.array()).all() &&
            (box.min.array() <= reach.max.array()).all())
          near[b].push_back(t);
      }
      views[b].tets = near[b];
    }
  }
  for (const VertexInTet& c : hash_->detect(views, false)) {
    const auto vertex_body = static_cast<std::size_t>(c.vertex_body);
    const auto tet_body = static_cast<std::size_t>(c.tet_body);
    if (changed != bodies && vertex_body != changed && tet_body != changed) continue;
    rest_overlap_[vertex_body][static_cast<std::size_t>(c.vertex) * bodies + tet_body] = 1;
  }
}

void BodyContactTerm::topology_changed(const SimulationState& state, int body) {
  rebuild(state, body);
}

void BodyContactTerm::prepare(const SimulationState& state, const StepContext&) {
  statistics_ = {};
  contacts_.clear();
  const auto views = views_of(models_, state, state.positions);
  const std::vector<VertexInTet> found = hash_->detect(views, false);
  const std::size_t bodies = models_.size();
  // Found contacts come sorted by (vertex body, vertex, tet body, tet): walk runs of one vertex
  // body, per penetrated body.
  std::size_t begin = 0;
  std::vector<int> colliding;
  std::vector<const VertexInTet*> first_contact_of;
  while (begin < found.size()) {
    const int a = found[begin].vertex_body;
    std::size_t end = begin;
    while (end < found.size() && found[end].vertex_body == a)
      ++end;
    for (int b = 0; b < static_cast<int>(bodies); ++b) {
      if (b == a) continue;
      colliding.clear();
      first_contact_of.clear();
      for (std::size_t c = begin; c < end; ++c) {
        const VertexInTet& hit = found[c];
        if (hit.tet_body != b) continue;
        if (!colliding.empty() && colliding.back() == hit.vertex) continue;
        if (rest_overlap_[static_cast<std::size_t>(
                a)][static_cast<std::size_t>(hit.vertex) * bodies + static_cast<std::size_t>(b)])
          continue;
        colliding.push_back(hit.vertex);
        first_contact_of.push_back(&hit);
      }
      if (colliding.empty()) continue;
      const BodyModel& penetrated = *models_[static_cast<std::size_t>(b)];
      const PenetratedSurface surface{views[static_cast<std::size_t>(b)].positions,
                                      penetrated.surface};
      const auto depths =
          penetration_depths(views[static_cast<std::size_t>(a)].positions,
                             adjacency_[static_cast<std::size_t>(a)], colliding, surface);
      statistics_.colliding_points += static_cast<int>(colliding.size());
      const int first_a = state.body(models_[static_cast<std::size_t>(a)]->body).first;
      const int first_b = state.body(penetrated.body).first;
      for (const PointPenetration& pen : depths) {
        const auto at =
            std::lower_bound(colliding.begin(), colliding.end(), pen.point) - colliding.begin();
        const VertexInTet& hit = *first_contact_of[static_cast<std::size_t>(at)];
        const auto& tet = penetrated.mesh.tets[static_cast<std::size_t>(hit.tet)];
        Contact c;
        c.node = {first_a + pen.point, first_b + tet[0], first_b + tet[1], first_b + tet[2],
                  first_b + tet[3]};
        c.weight = hit.barycentric;
        c.direction = pen.direction;
        c.depth = pen.depth;
        for (int k = 0; k < 5; ++k)
          c.at[k] = state.positions[static_cast<std::size_t>(c.node[k])];
        contacts_.push_back(c);
        statistics_.max_penetration = std::max(statistics_.max_penetration, pen.depth);
        statistics_.total_force += stiffness_ * pen.depth;
      }
    }
    begin = end;
  }
  // New blocks are needed only for cliques not declared before.
  structure_changed_ = false;
  for (const Contact& c : contacts_) {
    for (int k = 1; k < 5 && !structure_changed_; ++k) {
      const std::array<int, 2> pair{c.node[0], c.node[k]};
      if (!std::binary_search(declared_.begin(), declared_.end(), pair)) structure_changed_ = true;
    }
  }
}

double BodyContactTerm::gap(const Contact& c, std::span<const Vec3> x) const {
  Vec3 moved = x[c.node[0]] - c.at[0];
  for (int k = 0; k < 4; ++k)
    moved -= c.weight[k] * (x[c.node[k + 1]] - c.at[k + 1]);
  return c.depth - c.direction.dot(moved);
}

double BodyContactTerm::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (const Contact& c : contacts_) {
    const double d = gap(c, x);
    if (d > 0.0) e += 0.5 * stiffness_ * d * d;
  }
  return e;
}

double BodyContactTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                   std::span<Vec3> f) const {
  double e = 0.0;
  for (const Contact& c : contacts_) {
    const double d = gap(c, x);
    if (d <= 0.0) continue;
    const Vec3 push = stiffness_ * d * c.direction;
    f[c.node[0]] += push;
    for (int k = 0; k < 4; ++k)
      f[c.node[k + 1]] -= c.weight[k] * push;
    e += 0.5 * stiffness_ * d * d;
  }
  return e;
}

void BodyContactTerm::declare_blocks(BlockPattern& pattern) const {
  // The pattern only grows between topology changes: pairs of earlier contacts stay declared,
  // so a contact that comes back needs no new structure.
  for (const Contact& c : contacts_)
    for (int k = 1; k < 5; ++k)
      declared_.push_back({c.node[0], c.node[k]});
  std::sort(declared_.begin(), declared_.end());
  declared_.erase(std::unique(declared_.begin(), declared_.end()), declared_.end());
  for (const auto& [vertex, node] : declared_)
    pattern.add(vertex, node);
  // The tet's own pairs (its body's terms declare them too; a lone contact term needs them).
  for (const Contact& c : contacts_)
    pattern.add_clique(std::span<const int>(c.node).subspan(1));
}

void BodyContactTerm::add_stiffness(std::span<const Vec3> x, double scale, bool,
                                    BlockSparseMatrix& m) const {
  for (const Contact& c : contacts_) {
    if (gap(c, x) <= 0.0) continue;
    const Mat3 nn = (scale * stiffness_) * (c.direction * c.direction.transpose());
    const double w[5] = {1.0, -c.weight[0], -c.weight[1], -c.weight[2], -c.weight[3]};
    for (int a = 0; a < 5; ++a)
      for (int b = a; b < 5; ++b)
        m.add_symmetric(c.node[a], c.node[b], (w[a] * w[b]) * nn);
  }
}

}  // namespace viscera::sim
