#include "simulator/collision/contact_response.h"

#include <algorithm>

namespace viscera::sim {
namespace {

std::vector<CollisionBodyView> views_of(const std::vector<DeformableBody>& bodies) {
  std::vector<CollisionBodyView> views;
  for (const auto& body : bodies) views.push_back({body.positions(), body.volume_terms().tets});
  return views;
}

std::size_t table_size_for(const std::vector<DeformableBody>& bodies) {
  std::size_t vertices = 0;
  for (const auto& body : bodies) vertices += body.node_count();
  // About two buckets per vertex, odd so the modulo mixes the hash's high bits.
  return 2 * vertices + 1;
}

}  // namespace

ContactResponse::ContactResponse(const std::vector<DeformableBody>& bodies, double stiffness)
    : stiffness_(stiffness),
      hash_(std::max(mean_edge_length(views_of(bodies)), 1e-6), table_size_for(bodies)) {
  for (const auto& body : bodies) {
    adjacency_.push_back(VertexAdjacency::from_edges(body.node_count(), body.distance_terms().edges));
  }
}

ContactStatistics ContactResponse::apply(std::vector<DeformableBody>& bodies) {
  ContactStatistics stats;
  if (bodies.size() < 2 || stiffness_ <= 0.0) return stats;
  const std::vector<CollisionBodyView> views = views_of(bodies);
  const std::vector<VertexInTet> contacts = hash_.detect(views, false);

  // Contacts come sorted by (vertex body, vertex, tet body, tet): walk them in runs of one
  // (vertex body, tet body) pair.
  std::size_t begin = 0;
  while (begin < contacts.size()) {
    const int a = contacts[begin].vertex_body;
    std::size_t end = begin;
    std::vector<int> colliding;
    std::vector<const VertexInTet*> first_contact_of;
    // Points of body a inside any other body, each with the first tet that holds it. A point
    // inside two bodies at once is pushed out of the lower-numbered one first.
    while (end < contacts.size() && contacts[end].vertex_body == a) ++end;
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
      if (b == a) continue;
      colliding.clear();
      first_contact_of.clear();
      for (std::size_t c = begin; c < end; ++c) {
        if (contacts[c].tet_body != b) continue;
        if (!colliding.empty() && colliding.back() == contacts[c].vertex) continue;
        colliding.push_back(contacts[c].vertex);
        first_contact_of.push_back(&contacts[c]);
      }
      if (colliding.empty()) continue;
      const DeformableBody& penetrated = bodies[b];
      const PenetratedSurface surface{penetrated.positions(), penetrated.surface_faces()};
      const auto penetrations = penetration_depths(bodies[a].positions(), adjacency_[a], colliding, surface);
      stats.colliding_points += static_cast<int>(colliding.size());
      for (const auto& pen : penetrations) {
        const auto at = std::lower_bound(colliding.begin(), colliding.end(), pen.point) - colliding.begin();
        const VertexInTet& contact = *first_contact_of[static_cast<std::size_t>(at)];
        const core::Vec3 force = stiffness_ * pen.depth * pen.direction;
        bodies[a].add_force(pen.point, force);
        const auto& tet = penetrated.volume_terms().tets[contact.tet];
        for (int k = 0; k < 4; ++k) bodies[b].add_force(tet[k], -contact.barycentric[k] * force);
        stats.max_penetration = std::max(stats.max_penetration, pen.depth);
        stats.total_force += force.norm();
      }
    }
    begin = end;
  }
  return stats;
}

}  // namespace viscera::sim
