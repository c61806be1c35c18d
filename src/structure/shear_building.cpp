#include "isolab/structure/shear_building.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace isolab::structure {
namespace {

// Classical damping of the fixed-base superstructure, in floor coordinates relative to the base.
Eigen::MatrixXd SuperstructureDampingMatrix(const std::vector<Story>& stories,
                                            const SuperstructureDamping& damping) {
  const int n = static_cast<int>(stories.size());
  if (damping.kind == SuperstructureDamping::Kind::kNone) return Eigen::MatrixXd::Zero(n, n);
  const Modes modes = FixedBaseModes(stories);
  Eigen::VectorXd mass(n);
  for (int i = 0; i < n; ++i) mass[i] = stories[i].floor_mass;

  if (damping.kind == SuperstructureDamping::Kind::kRayleigh) {
    const int m1 = damping.rayleigh_modes[0], m2 = damping.rayleigh_modes[1];
    if (m1 < 1 || m2 < 1 || m1 > n || m2 > n || m1 == m2) {
      throw std::invalid_argument("damping.modes: two different modes between 1 and " +
                                  std::to_string(n));
    }
    const double w1 = modes.circular_frequencies[m1 - 1], w2 = modes.circular_frequencies[m2 - 1];
    const double z1 = damping.rayleigh_ratios[0], z2 = damping.rayleigh_ratios[1];
    // zeta(w) = a0 / (2 w) + a1 w / 2 through both points.
    const double a1 = 2.0 * (z2 * w2 - z1 * w1) / (w2 * w2 - w1 * w1);
    const double a0 = 2.0 * z1 * w1 - a1 * w1 * w1;
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      const double ki = InitialStiffness(stories[i].assembly);
      k(i, i) += ki;
      if (i > 0) {
        k(i - 1, i - 1) += ki;
        k(i - 1, i) -= ki;
        k(i, i - 1) -= ki;
      }
    }
    return a0 * Eigen::MatrixXd(mass.asDiagonal()) + a1 * k;
  }

  // Modal: C = M Phi diag(2 zeta_n w_n) Phi^T M with mass-normalised Phi.
  const auto& ratios = damping.modal_ratios;
  if (ratios.size() != 1 && ratios.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("damping.ratios: give one ratio or one per mode (" +
                                std::to_string(n) + ")");
  }
  Eigen::VectorXd diagonal(n);
  for (int i = 0; i < n; ++i) {
    diagonal[i] = 2.0 * ratios[ratios.size() == 1 ? 0 : i] * modes.circular_frequencies[i];
  }
  const Eigen::MatrixXd m_phi = mass.asDiagonal() * modes.shapes;
  return m_phi * diagonal.asDiagonal() * m_phi.transpose();
}

}  // namespace

double InitialStiffness(const hysteresis::ParallelAssembly& assembly) {
  std::vector<hysteresis::LawState> rest(assembly.size()), trial(assembly.size());
  std::vector<hysteresis::LawResponse> responses(assembly.size());
  return assembly.Update(rest, {0.0, 0.0}, trial, responses).stiffness;
}

Modes FixedBaseModes(const std::vector<Story>& stories) {
  const int n = static_cast<int>(stories.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n), m = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const double ki = InitialStiffness(stories[i].assembly);
    m(i, i) = stories[i].floor_mass;
    k(i, i) += ki;
    if (i > 0) {
      k(i - 1, i - 1) += ki;
      k(i - 1, i) -= ki;
      k(i, i - 1) -= ki;
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m);
  if (solver.info() != Eigen::Success) throw std::runtime_error("modal analysis failed");
  Modes modes;
  modes.circular_frequencies = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  modes.periods = (2.0 * std::numbers::pi) * modes.circular_frequencies.cwiseInverse();
  modes.shapes = solver.eigenvectors();                                   // M-orthonormal
  const Eigen::VectorXd gamma = modes.shapes.transpose() * m.diagonal();  // L_n with M_n = 1
  modes.effective_mass_ratios = gamma.cwiseAbs2() / m.diagonal().sum();
  return modes;
}

Structure BuildShearBuilding(const ShearBuilding& building) {
  const int stories = static_cast<int>(building.stories.size());
  if (stories == 0) throw std::invalid_argument("structure.stories: at least one story");
  const int first_floor = building.isolated ? 1 : 0;
  const int n = stories + first_floor;

  Eigen::VectorXd mass(n);
  if (building.isolated) mass[0] = building.base_mass;
  std::vector<Connection> connections;
  if (building.isolated) connections.push_back({"isolation", kGround, 0, building.isolation});
  for (int s = 0; s < stories; ++s) {
    const Story& story = building.stories[s];
    mass[first_floor + s] = story.floor_mass;
    const int below = s == 0 ? (building.isolated ? 0 : kGround) : first_floor + s - 1;
    connections.push_back({story.name, below, first_floor + s, story.assembly});
  }

  // C_full = T^T C_s T with x_s = u_s - u_base 1 (isolated) or x_s = u_s (fixed base).
  const Eigen::MatrixXd cs = SuperstructureDampingMatrix(building.stories, building.damping);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  c.bottomRightCorner(stories, stories) = cs;
  if (building.isolated) {
    const Eigen::VectorXd column_sums = cs.colwise().sum().transpose();
    c.block(1, 0, stories, 1) = -cs.rowwise().sum();
    c.block(0, 1, 1, stories) = -column_sums.transpose();
    c(0, 0) = column_sums.sum();
  }
  const SparseMatrix sparse_c = c.sparseView(0.0, 0.0);
  return Structure(std::move(mass), std::move(connections), sparse_c);
}

Structure BuildSdof(double mass, double damping_coefficient,
                    hysteresis::ParallelAssembly restoring) {
  SparseMatrix c(1, 1);
  if (damping_coefficient != 0.0) c.insert(0, 0) = damping_coefficient;
  std::vector<Connection> connections;
  connections.push_back({"restoring", kGround, 0, std::move(restoring)});
  return Structure(Eigen::VectorXd::Constant(1, mass), std::move(connections), c);
}

}  // namespace isolab::structure
