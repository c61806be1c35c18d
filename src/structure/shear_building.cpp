#include "isolab/structure/shear_building.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tridiagonal_pencil.h"

namespace isolab::structure {
namespace {

// Modal damping couples every floor with every other: its matrix is dense, and so would the
// tangent be. Beyond this size Rayleigh damping (sparse) is the sensible choice.
constexpr int kMaxModalDampingStories = 500;

Eigen::VectorXd FloorMasses(const std::vector<Story>& stories) {
  Eigen::VectorXd mass(stories.size());
  for (std::size_t i = 0; i < stories.size(); ++i) mass[i] = stories[i].floor_mass;
  return mass;
}

// Tridiagonal stiffness of the fixed-base superstructure with initial story stiffnesses: story i
// joins floor i to floor i - 1 (to the ground for i = 0).
TridiagonalPencil StoryPencil(const std::vector<Story>& stories) {
  const int n = static_cast<int>(stories.size());
  TridiagonalPencil pencil{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(std::max(n - 1, 0)),
                           FloorMasses(stories)};
  for (int i = 0; i < n; ++i) {
    const double k = InitialStiffness(stories[i].assembly);
    pencil.diagonal[i] += k;
    if (i > 0) {
      pencil.diagonal[i - 1] += k;
      pencil.off_diagonal[i - 1] = -k;
    }
  }
  return pencil;
}

SparseMatrix StoryStiffness(const TridiagonalPencil& pencil) {
  const Eigen::Index n = pencil.diagonal.size();
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < n; ++i) {
    entries.emplace_back(i, i, pencil.diagonal[i]);
    if (i > 0) {
      entries.emplace_back(i - 1, i, pencil.off_diagonal[i - 1]);
      entries.emplace_back(i, i - 1, pencil.off_diagonal[i - 1]);
    }
  }
  SparseMatrix k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

// Classical damping of the fixed-base superstructure, in floor coordinates relative to the base.
SparseMatrix SuperstructureDampingMatrix(const std::vector<Story>& stories,
                                         const SuperstructureDamping& damping) {
  const int n = static_cast<int>(stories.size());
  if (damping.kind == SuperstructureDamping::Kind::kNone) return SparseMatrix(n, n);
  if (damping.kind == SuperstructureDamping::Kind::kModal && n > kMaxModalDampingStories) {
    throw std::invalid_argument(
        "damping: modal damping couples every floor (a dense matrix); with more than " +
        std::to_string(kMaxModalDampingStories) + " stories use rayleigh");
  }
  const TridiagonalPencil pencil = StoryPencil(stories);
  const Eigen::VectorXd& mass = pencil.mass;

  if (damping.kind == SuperstructureDamping::Kind::kRayleigh) {
    const int m1 = damping.rayleigh_modes[0], m2 = damping.rayleigh_modes[1];
    if (m1 < 1 || m2 < 1 || m1 > n || m2 > n || m1 == m2) {
      throw std::invalid_argument("damping.modes: two different modes between 1 and " +
                                  std::to_string(n));
    }
    // Two frequencies, each by bisection in O(n): no dense eigensolution of every mode.
    const double w1 = std::sqrt(std::max(pencil.Eigenvalue(m1), 0.0));
    const double w2 = std::sqrt(std::max(pencil.Eigenvalue(m2), 0.0));
    const double z1 = damping.rayleigh_ratios[0], z2 = damping.rayleigh_ratios[1];
    // zeta(w) = a0 / (2 w) + a1 w / 2 through both points.
    const double a1 = 2.0 * (z2 * w2 - z1 * w1) / (w2 * w2 - w1 * w1);
    const double a0 = 2.0 * z1 * w1 - a1 * w1 * w1;
    if (a0 < 0.0 || a1 < 0.0) {
      throw std::invalid_argument(
          "damping.ratios: these ratios give a negative Rayleigh "
          "coefficient (a0 = " +
          std::to_string(a0) + ", a1 = " + std::to_string(a1) + ")");
    }
    SparseMatrix m(n, n);
    m.reserve(Eigen::VectorXi::Constant(n, 1));
    for (int i = 0; i < n; ++i) m.insert(i, i) = mass[i];
    return a0 * m + a1 * StoryStiffness(pencil);
  }

  // Modal: C = M Phi diag(2 zeta_n w_n) Phi^T M with mass-normalised Phi, which needs every mode.
  const Modes modes = FixedBaseModes(stories);
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
  return (m_phi * diagonal.asDiagonal() * m_phi.transpose()).sparseView(0.0, 0.0);
}

}  // namespace

double InitialStiffness(const hysteresis::ParallelAssembly& assembly) {
  std::vector<hysteresis::LawState> rest(assembly.state_size()), trial(assembly.state_size());
  std::vector<hysteresis::LawResponse> responses(assembly.size());
  return assembly.Update(rest, {0.0, 0.0}, trial, responses).stiffness;
}

Modes FixedBaseModes(const std::vector<Story>& stories) {
  const TridiagonalPencil pencil = StoryPencil(stories);
  const Eigen::VectorXd& mass = pencil.mass;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      Eigen::MatrixXd(StoryStiffness(pencil)), Eigen::MatrixXd(mass.asDiagonal()));
  if (solver.info() != Eigen::Success) throw std::runtime_error("modal analysis failed");
  Modes modes;
  modes.circular_frequencies = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  modes.periods = (2.0 * std::numbers::pi) * modes.circular_frequencies.cwiseInverse();
  modes.shapes = solver.eigenvectors();                           // M-orthonormal
  const Eigen::VectorXd gamma = modes.shapes.transpose() * mass;  // L_n with M_n = 1
  modes.effective_mass_ratios = gamma.cwiseAbs2() / mass.sum();
  return modes;
}

LaidOutStructure BuildShearBuilding(const ShearBuilding& building) {
  const int stories = static_cast<int>(building.stories.size());
  if (stories == 0 && !building.isolated) {
    throw std::invalid_argument("structure.stories: a building on a fixed base needs a story");
  }
  const int first_floor = building.isolated ? 1 : 0;
  const int n = stories + first_floor;

  Layout layout;
  Eigen::VectorXd mass(n);
  std::vector<Member> members;
  if (building.isolated) {
    mass[0] = building.base_mass;
    const std::vector<std::string> bearings =
        building.bearings.empty() ? std::vector<std::string>{"isolation"} : building.bearings;
    for (const std::string& bearing : bearings) {
      const int member = static_cast<int>(members.size());
      members.push_back(Member::Between(bearing, kGround, 0, building.isolation));
      layout.isolators.push_back({bearing, member, 0, {}});
      layout.base_shear.push_back({member, kX});
    }
    layout.levels.push_back({"base", {0, kGround, kGround}, {}});
  }
  for (int s = 0; s < stories; ++s) {
    const Story& story = building.stories[s];
    const int dof = first_floor + s;
    mass[dof] = story.floor_mass;
    const int below = s == 0 ? (building.isolated ? 0 : kGround) : dof - 1;
    layout.stories.push_back(
        {story.name, dof, story.height, {static_cast<int>(members.size()), -1, -1}});
    members.push_back(Member::Between(story.name, below, dof, story.assembly));
    layout.levels.push_back({"floor " + std::to_string(s + 1), {dof, kGround, kGround}, {}});
  }
  // The force into the ground: the isolators' (above), or the first story's on a fixed base.
  if (!building.isolated) layout.base_shear.push_back({0, kX});

  // C = T^T C_s T, where T maps the DOFs to floor motion relative to the base,
  // x_s = u_s - u_base 1 (isolated), or x_s = u_s (fixed base).
  SparseMatrix c(n, n);
  if (stories > 0) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int s = 0; s < stories; ++s) {
      entries.emplace_back(s, first_floor + s, 1.0);
      if (building.isolated) entries.emplace_back(s, 0, -1.0);
    }
    SparseMatrix t(stories, n);
    t.setFromTriplets(entries.begin(), entries.end());
    const SparseMatrix cs = SuperstructureDampingMatrix(building.stories, building.damping);
    c = SparseMatrix(t.transpose()) * cs * t;
    c.prune(0.0);
  }
  return {Structure(std::move(mass), std::move(members), {}, std::move(c)), std::move(layout)};
}

LaidOutStructure BuildSdof(double mass, double damping_coefficient,
                           hysteresis::ParallelAssembly restoring,
                           const std::vector<std::string>& bearings) {
  SparseMatrix c(1, 1);
  if (damping_coefficient != 0.0) c.insert(0, 0) = damping_coefficient;
  std::vector<Member> members;
  Layout layout;
  layout.levels.push_back({"mass", {0, kGround, kGround}, {}});
  for (const std::string& bearing :
       bearings.empty() ? std::vector<std::string>{"restoring"} : bearings) {
    const int member = static_cast<int>(members.size());
    members.push_back(Member::Between(bearing, kGround, 0, restoring));
    layout.isolators.push_back({bearing, member, 0, {}});
    layout.base_shear.push_back({member, kX});
  }
  return {Structure(Eigen::VectorXd::Constant(1, mass), std::move(members), {}, c),
          std::move(layout)};
}

}  // namespace isolab::structure
