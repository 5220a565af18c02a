#pragma once
/// Template body of the Mesh_3 run (label_mesh_3.h); included by label_mesh_3_sequential.cpp and
/// label_mesh_3_parallel.cpp only: one Mesh_3 instantiation takes a minute to compile.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/ImageIO.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>

// After make_mesh_3.h: Slivers_exuder.h uses the worksharing types without including them.
#include <CGAL/exude_mesh_3.h>

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "importers/meshing/label_mesh_3.h"

namespace viscera::importers::detail {

using Mesh3Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh3Domain = CGAL::Labeled_mesh_domain_3<Mesh3Kernel>;

/// Mesh_3 sizing field: the label's own size inside a region (cells) and the smaller of the two
/// labels' sizes on the boundary between them (facets).
class LabelSizingField {
 public:
  using FT = Mesh3Kernel::FT;
  using Point_3 = Mesh3Kernel::Point_3;
  using Index = Mesh3Domain::Index;

  LabelSizingField(const Mesh3Domain& domain, double uniform, const std::map<int, double>& sizes,
                   bool facets)
      : domain_(&domain), uniform_(uniform), sizes_(&sizes), facets_(facets) {}

  FT operator()(const Point_3&, const int dimension, const Index& index) const {
    if (sizes_->empty()) return uniform_;
    if (dimension == 3) return size_of(domain_->subdomain_index(index));
    if (dimension == 2 && facets_) {
      const auto patch = domain_->surface_patch_index(index);
      return std::min(size_of(patch.first), size_of(patch.second));
    }
    return uniform_;
  }

 private:
  double size_of(int label) const {
    const auto it = sizes_->find(label);
    return it != sizes_->end() && it->second > 0.0 ? it->second : uniform_;
  }

  const Mesh3Domain* domain_;
  double uniform_;
  const std::map<int, double>* sizes_;
  bool facets_;
};

template <typename ConcurrencyTag>
Mesh3Output run_mesh_3(const Mesh3Input& input) {
  using Triangulation =
      typename CGAL::Mesh_triangulation_3<Mesh3Domain, CGAL::Default, ConcurrencyTag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
  using Criteria = CGAL::Mesh_criteria_3<Triangulation>;
  namespace params = CGAL::parameters;

  const LabelCrop& crop = *input.crop;
  // The image owns a copy of the labels (CGAL frees it with the image).
  _image* raw = _createImage(
      static_cast<std::size_t>(crop.dims[0]), static_cast<std::size_t>(crop.dims[1]),
      static_cast<std::size_t>(crop.dims[2]), 1, input.spacing_mm.x(), input.spacing_mm.y(),
      input.spacing_mm.z(), sizeof(std::uint16_t), WK_FIXED, SGN_UNSIGNED);
  std::memcpy(raw->data, crop.labels.data(), crop.labels.size() * sizeof(std::uint16_t));
  const CGAL::Image_3 image(raw);

  CGAL::Random random(input.seed);
  const Mesh3Domain domain = Mesh3Domain::create_labeled_image_mesh_domain(
      image, params::value_outside = 0, params::p_rng = &random);

  const LabelSizingField cell_size(domain, input.cell_size_mm, input.label_cell_size_mm, false);
  const LabelSizingField facet_size(domain, input.facet_size_mm, input.label_cell_size_mm, true);
  const Criteria criteria(
      params::facet_angle = input.facet_angle_degrees, params::facet_size = facet_size,
      params::facet_distance = input.facet_distance_mm,
      params::cell_radius_edge_ratio = input.cell_radius_edge_ratio, params::cell_size = cell_size);

  // Mesh_3 polls the stop flag between refinement steps (CGAL's own cancellation hook).
  CGAL::parameters::internal::Mesh_3_options options;
  options.pointer_to_stop_atomic_boolean = input.stop;
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude(),
                                      params::no_lloyd(), params::no_odt(), options);
  const bool stopped = input.stop != nullptr && input.stop->load();
  // No time limit: the result must not depend on the machine's speed.
  if (input.exude && !stopped)
    CGAL::exude_mesh_3(c3t3, params::time_limit = 0,
                       params::sliver_bound = input.exude_sliver_bound_degrees);

  const Triangulation& triangulation = c3t3.triangulation();
  const auto point_of = triangulation.geom_traits().construct_point_3_object();
  Mesh3Output output;
  output.tets.reserve(c3t3.number_of_cells_in_complex());
  output.labels.reserve(c3t3.number_of_cells_in_complex());
  std::unordered_map<const void*, int> node_of;
  for (auto cell = c3t3.cells_in_complex_begin(); cell != c3t3.cells_in_complex_end(); ++cell) {
    core::Tetrahedron tet{};
    for (int corner = 0; corner < 4; ++corner) {
      const auto vertex = cell->vertex(corner);
      const auto [it, inserted] =
          node_of.try_emplace(&*vertex, static_cast<int>(output.nodes_mm.size()));
      if (inserted) {
        const auto p = point_of(triangulation.point(vertex));
        output.nodes_mm.emplace_back(p.x(), p.y(), p.z());
      }
      tet[static_cast<std::size_t>(corner)] = it->second;
    }
    output.tets.push_back(tet);
    output.labels.push_back(static_cast<int>(c3t3.subdomain_index(cell)));
  }
  return output;
}

}  // namespace viscera::importers::detail
