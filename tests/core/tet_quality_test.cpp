#include "core/mesh/tet_quality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/tet_block.h"

namespace viscera::core {
namespace {

const double kRegularDihedral = std::acos(1.0 / 3.0) * 180.0 / std::numbers::pi;  // 70.53°

TetMesh regular_tet(double edge) {
  TetMesh mesh;
  const double s = edge / std::sqrt(8.0);  // corners of a cube of side edge/√2
  mesh.nodes = {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s), Vec3(-s, -s, s)};
  mesh.tets = {{0, 1, 2, 3}};
  orient_tets_positively(mesh);
  return mesh;
}

TEST(TetQuality, regular_tet_has_the_textbook_measures) {
  const TetQualityReport report = tet_quality(regular_tet(0.01));
  EXPECT_EQ(report.tets, 1u);
  EXPECT_EQ(report.inverted, 0u);
  EXPECT_EQ(report.slivers, 0u);
  EXPECT_NEAR(report.min_dihedral_degrees, kRegularDihedral, 1e-9);
  EXPECT_NEAR(report.max_dihedral_degrees, kRegularDihedral, 1e-9);
  EXPECT_NEAR(report.max_radius_edge_ratio, std::sqrt(6.0) / 4.0, 1e-12);
  EXPECT_NEAR(report.max_aspect_ratio, 1.0, 1e-12);
  EXPECT_NEAR(report.total_volume, std::pow(0.01, 3) / (6.0 * std::sqrt(2.0)), 1e-18);
  EXPECT_TRUE(report.valid());
}

TEST(TetQuality, kuhn_cube_tets_have_45_to_90_degree_dihedrals) {
  // Each Kuhn simplex of a unit cube: dihedral angles 45°, 60° and 90°, circumradius = half
  // the cube diagonal, inradius 1/(2(1+√2)).
  const TetMesh block = testing::tet_block(3, 2, 2, 1.0);
  const TetQualityReport report = tet_quality(block);
  EXPECT_EQ(report.tets, 3u * 2u * 2u * 6u);
  EXPECT_NEAR(report.min_dihedral_degrees, 45.0, 1e-9);
  EXPECT_NEAR(report.max_dihedral_degrees, 90.0, 1e-9);
  EXPECT_NEAR(report.min_radius_edge_ratio, std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(report.max_radius_edge_ratio, std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(report.mean_aspect_ratio, (1.0 + std::sqrt(2.0)) / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(report.total_volume, 12.0, 1e-12);
  EXPECT_EQ(report.min_dihedral_histogram[4], report.tets);
}

TEST(TetQuality, counts_inverted_and_flat_tets_and_keeps_them_out_of_the_shape_statistics) {
  TetMesh mesh = regular_tet(1.0);
  mesh.nodes.push_back(Vec3(2.0, 0.0, 0.0));
  mesh.nodes.push_back(Vec3(3.0, 0.0, 0.0));
  mesh.nodes.push_back(Vec3(2.0, 1.0, 0.0));
  mesh.nodes.push_back(Vec3(2.0, 0.0, 1.0));
  mesh.nodes.push_back(Vec3(2.5, 0.5, 0.0));  // coplanar with 4, 5, 6
  mesh.tets.push_back({4, 6, 5, 7});          // negative orientation
  mesh.tets.push_back({4, 5, 6, 8});          // flat
  const TetQualityReport report = tet_quality(mesh);
  EXPECT_EQ(report.inverted, 2u);
  EXPECT_FALSE(report.valid());
  EXPECT_LT(report.min_volume, 0.0);
  EXPECT_NEAR(report.min_dihedral_degrees, kRegularDihedral, 1e-9);
  EXPECT_EQ(report.worst_tet, 0);
}

TEST(TetQuality, a_flattened_square_is_a_sliver_with_a_small_radius_edge_ratio) {
  // Four corners of a square lifted alternately by ±h: the classic sliver of Delaunay meshes
  // (Cheng et al. 2000): well-shaped edges, near-zero volume, dihedral angles near 0° and 180°.
  const double h = 0.01;
  const TetShape shape = tet_shape(Vec3(1, 0, h), Vec3(0, 1, -h), Vec3(-1, 0, h), Vec3(0, -1, -h));
  EXPECT_LT(shape.min_dihedral_degrees, 5.0);
  EXPECT_GT(shape.max_dihedral_degrees, 175.0);
  EXPECT_LT(shape.radius_edge_ratio, 0.75);
  EXPECT_GT(shape.aspect_ratio, 20.0);

  TetMesh mesh;
  mesh.nodes = {Vec3(1, 0, h), Vec3(0, 1, -h), Vec3(-1, 0, h), Vec3(0, -1, -h)};
  mesh.tets = {{0, 1, 2, 3}};
  orient_tets_positively(mesh);
  const TetQualityReport report = tet_quality(mesh);
  EXPECT_EQ(report.slivers, 1u);
  EXPECT_EQ(report.inverted, 0u);
  EXPECT_EQ(report.min_dihedral_histogram[0], 1u);
}

TEST(TetQuality, json_report_names_every_measure_and_writes_null_for_an_empty_mesh) {
  const nlohmann::json filled = tet_quality(regular_tet(1.0));
  EXPECT_EQ(filled.at("tets"), 1);
  EXPECT_EQ(filled.at("inverted"), 0);
  EXPECT_NEAR(filled.at("min_dihedral_degrees").get<double>(), kRegularDihedral, 1e-9);
  EXPECT_TRUE(filled.at("valid").get<bool>());

  const nlohmann::json empty = tet_quality(TetMesh{});
  EXPECT_TRUE(empty.at("min_dihedral_degrees").is_null());
  EXPECT_TRUE(empty.at("max_aspect_ratio").is_null());
  EXPECT_EQ(empty.at("tets"), 0);
}

}  // namespace
}  // namespace viscera::core
