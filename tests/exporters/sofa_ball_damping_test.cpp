// The exported ball comes to rest: its scene stepped with the equations of SOFA's
// EulerImplicitSolver (EulerImplicitSolver.cpp, solve(): A = M (1 + h r_m) − h (h + r_s) K,
// b = h (f + (h + r_s) K v − r_m M v)) on linear tetrahedral FEM of the scene's E and ν (the
// corotational "large" method at small displacement), from rest under gravity, with the Rayleigh
// β where the scene puts it (on the solver) and where the first exporter put it (on the force
// field, which SOFA only adds to the matrix).
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <set>

#include "tests/exporters/sofa_scene_reader.h"
#include "tests/exporters/sofa_template_cases.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Linear elastic stiffness (positive) of the tets, 3 dofs per node.
Eigen::SparseMatrix<double> fem_stiffness(const core::TetMesh& mesh,
                                          const std::vector<double>& young,
                                          const std::vector<double>& poisson) {
  Triplets triplets;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& tet = mesh.tets[t];
    Eigen::Matrix3d edges;
    for (int k = 0; k < 3; ++k)
      edges.col(k) = mesh.nodes[static_cast<std::size_t>(tet[k + 1])] -
                     mesh.nodes[static_cast<std::size_t>(tet[0])];
    const double volume = std::abs(edges.determinant()) / 6.0;
    const Eigen::Matrix3d inverse = edges.inverse();  // rows: gradients of N1..N3
    Eigen::Matrix<double, 4, 3> gradient;
    gradient.row(1) = inverse.row(0);
    gradient.row(2) = inverse.row(1);
    gradient.row(3) = inverse.row(2);
    gradient.row(0) = -(gradient.row(1) + gradient.row(2) + gradient.row(3));
    Eigen::Matrix<double, 6, 12> b = Eigen::Matrix<double, 6, 12>::Zero();
    for (int a = 0; a < 4; ++a) {
      const double gx = gradient(a, 0), gy = gradient(a, 1), gz = gradient(a, 2);
      b(0, 3 * a) = gx, b(1, 3 * a + 1) = gy, b(2, 3 * a + 2) = gz;
      b(3, 3 * a) = gy, b(3, 3 * a + 1) = gx;
      b(4, 3 * a + 1) = gz, b(4, 3 * a + 2) = gy;
      b(5, 3 * a) = gz, b(5, 3 * a + 2) = gx;
    }
    const double e = young.size() == 1 ? young[0] : young[t];
    const double nu = poisson.size() == 1 ? poisson[0] : poisson[t];
    const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d.topLeftCorner<3, 3>().setConstant(lambda);
    for (int k = 0; k < 3; ++k)
      d(k, k) += 2 * mu, d(k + 3, k + 3) = mu;
    const Eigen::Matrix<double, 12, 12> k = volume * b.transpose() * d * b;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        triplets.emplace_back(3 * tet[i / 3] + i % 3, 3 * tet[j / 3] + j % 3, k(i, j));
  }
  Eigen::SparseMatrix<double> stiffness(3 * static_cast<Eigen::Index>(mesh.nodes.size()),
                                        3 * static_cast<Eigen::Index>(mesh.nodes.size()));
  stiffness.setFromTriplets(triplets.begin(), triplets.end());
  return stiffness;
}

struct Motion {
  double peak_kinetic = 0.0;   ///< J, largest kinetic energy
  double final_kinetic = 0.0;  ///< J, largest kinetic energy over the last 0.1 s
};

/// Steps the free dofs for `duration` s. `solver_beta` enters A and b, `field_beta` only A.
Motion step(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
            const Eigen::VectorXd& gravity_force, double h, double solver_beta, double field_beta,
            double duration) {
  Eigen::SparseMatrix<double> a = h * (h + solver_beta + field_beta) * k;
  a += Eigen::SparseMatrix<double>(m.asDiagonal());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solve(a);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.size()), v = u;
  Motion motion;
  const int steps = static_cast<int>(std::lround(duration / h));
  for (int s = 0; s < steps; ++s) {
    const Eigen::VectorXd f = gravity_force - k * u;
    const Eigen::VectorXd b = h * (f - (h + solver_beta) * (k * v));
    v += solve.solve(b);
    u += h * v;
    const double kinetic = 0.5 * v.dot(m.cwiseProduct(v));
    motion.peak_kinetic = std::max(motion.peak_kinetic, kinetic);
    if (s >= steps - static_cast<int>(std::lround(0.1 / h)))
      motion.final_kinetic = std::max(motion.final_kinetic, kinetic);
  }
  return motion;
}

TEST(SofaBallDamping, the_exported_ball_comes_to_rest_within_two_seconds) {
  const testing::TemplateCase ball{"ball", "ball", "", nullptr};
  const fs::path package = testing::template_package(ball);
  const fs::path dir = testing::scratch_dir();
  ASSERT_EQ(testing::run_program("viscera",
                                 "export " + testing::shell_quote(package.string()) +
                                     " --format sofa -o " +
                                     testing::shell_quote((dir / "ball.scn").string()),
                                 dir)
                .exit_code,
            0);
  const testing::SofaSceneReader reader(dir / "ball.scn");
  const testing::SofaElement& node = *reader.body_node("ball");
  const core::TetMesh mesh = reader.loaded_mesh(node);
  const testing::SofaElement& fem = *node.child("TetrahedronFEMForceField");
  const Eigen::SparseMatrix<double> full =
      fem_stiffness(mesh, fem.numbers("youngModulus"), fem.numbers("poissonRatio"));
  // The free dofs (FixedProjectiveConstraint projects the others out).
  const auto fixed = reader.fixed(node);
  const std::set<int> held(fixed.begin(), fixed.end());
  std::vector<int> free;
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i)
    if (!held.contains(i))
      for (int c = 0; c < 3; ++c)
        free.push_back(3 * i + c);
  Eigen::VectorXi map = Eigen::VectorXi::Constant(full.rows(), -1);
  for (std::size_t i = 0; i < free.size(); ++i)
    map[free[i]] = static_cast<int>(i);
  Triplets triplets;
  for (int col = 0; col < full.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(full, col); it; ++it)
      if (map[it.row()] >= 0 && map[it.col()] >= 0)
        triplets.emplace_back(map[it.row()], map[it.col()], it.value());
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  const auto masses = reader.masses(node);
  const std::vector<double> g = reader.root().numbers("gravity");
  Eigen::VectorXd m(n), weight(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    m[i] = masses[static_cast<std::size_t>(free[static_cast<std::size_t>(i)] / 3)];
    weight[i] = m[i] * g[static_cast<std::size_t>(free[static_cast<std::size_t>(i)] % 3)];
  }
  const double h = std::stod(reader.root().attribute("dt"));
  const double beta =
      std::stod(reader.root().child("EulerImplicitSolver")->attribute("rayleighStiffness"));
  ASSERT_GT(beta, 0.0);
  const Motion exported = step(k, m, weight, h, beta, 0.0, 2.0);
  const Motion first = step(k, m, weight, h, 0.0, beta, 2.0);
  // The template's settle task counts the ball at rest below 1 µJ of kinetic energy.
  EXPECT_LT(exported.final_kinetic, 1e-6) << "peak " << exported.peak_kinetic;
  EXPECT_LT(exported.final_kinetic, 1e-3 * exported.peak_kinetic);
  EXPECT_LT(exported.final_kinetic, 0.1 * first.final_kinetic)
      << "β on the force field damps as much: the test shows nothing";
  RecordProperty("final_kinetic_exported", std::to_string(exported.final_kinetic));
  RecordProperty("final_kinetic_first_exporter", std::to_string(first.final_kinetic));
  std::printf("peak %.3g J; after 2 s: %.3g J with β on the solver, %.3g J on the force field\n",
              exported.peak_kinetic, exported.final_kinetic, first.final_kinetic);
}

}  // namespace
}  // namespace viscera
