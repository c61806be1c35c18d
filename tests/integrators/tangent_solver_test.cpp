// The linear solvers of Newmark's effective tangent (src/integrators/tangent_solver.h):
//  * dense and banded LU against Eigen's dense LU on unsymmetric matrices whose small diagonals
//    need row exchanges, factorised twice (the storage is reused); the factors kept for a
//    matrix repeated bit for bit, and only for it;
//  * a matrix singular or singular to working precision refused by every solver, KLU included,
//    and a well-conditioned one with rows of very different scales accepted;
//  * symmetric matrices (the dense solver's LDL^T): positive definite, scaled by dofs of very
//    different units, indefinite (its LU instead) and singular to working precision;
//  * the automatic choice on the patterns of an SDOF, the five-story building, the bundled plan
//    building and 150-story shear buildings with and without relative Rayleigh damping;
//  * whole Newmark runs with each solver forced against the same run on KLU: the displacement
//    histories agree to 1e-10 of their peak, with the same Newton iterations.
#include "tangent_solver.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/integrators/newmark.h"
#include "isolab/model/model_file.h"
#include "isolab/structure/plan_building.h"
#include "isolab/structure/shear_building.h"

namespace isolab::integrators {
namespace {

using LinearSolver = NewmarkOptions::LinearSolver;
using hysteresis::LawType;
using structure::SparseMatrix;

// An n x n matrix with random entries in [-1, 1] where `in_pattern(i, j)`, diagonal entries of
// `diagonal` size (small ones make partial pivoting exchange rows).
SparseMatrix RandomMatrix(int n, const std::function<bool(int, int)>& in_pattern, double diagonal,
                          unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (i == j) {
        entries.emplace_back(i, j, diagonal * (1.0 + 0.5 * uniform(generator)));
      } else if (in_pattern(i, j)) {
        entries.emplace_back(i, j, uniform(generator));
      }
    }
  }
  SparseMatrix matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  return matrix;
}

struct PatternCase {
  std::string name;
  int n;
  std::function<bool(int, int)> in_pattern;
};

std::vector<PatternCase> Patterns() {
  return {
      {"tridiagonal", 40, [](int i, int j) { return std::abs(i - j) <= 1; }},
      {"two below, one above", 30, [](int i, int j) { return i - j <= 2 && j - i <= 1; }},
      {"pentadiagonal", 30, [](int i, int j) { return std::abs(i - j) <= 2; }},
      {"heptadiagonal", 9, [](int i, int j) { return std::abs(i - j) <= 3; }},
      {"arrowhead", 12, [](int i, int j) { return std::abs(i - j) <= 1 || i == 0 || j == 0; }},
      // Border dofs (banded_lu.h): 0 and 70 coupled to every other, a band of 2 and 1 between.
      {"two borders", 90,
       [](int i, int j) {
         return (i - j <= 2 && j - i <= 1) || i == 0 || j == 0 || i == 70 || j == 70;
       }},
      {"full", 7, [](int, int) { return true; }},
  };
}

TEST(TangentSolver, EverySolverSolvesLikeEigensDenseLu) {
  for (const PatternCase& pattern : Patterns()) {
    for (const LinearSolver kind :
         {LinearSolver::kDense, LinearSolver::kBanded, LinearSolver::kKlu}) {
      SparseMatrix matrix = RandomMatrix(pattern.n, pattern.in_pattern, 1e-3, 1);
      TangentSolver solver(matrix, kind);
      ASSERT_EQ(solver.kind(), kind);
      for (unsigned seed : {2u, 3u}) {  // twice: the second factorisation reuses the storage
        matrix = RandomMatrix(pattern.n, pattern.in_pattern, seed == 2 ? 1e-3 : 5.0, seed);
        const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(pattern.n, -1.0, 2.0);
        const Eigen::VectorXd expected = Eigen::MatrixXd(matrix).partialPivLu().solve(b);
        ASSERT_TRUE(solver.Factorize(matrix)) << pattern.name;
        Eigen::VectorXd x = b;
        solver.Solve(&x);
        EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-11 * expected.cwiseAbs().maxCoeff())
            << pattern.name << ", solver " << static_cast<int>(kind) << ", seed " << seed;
      }
    }
  }
}

// The factors are kept for a matrix whose values are those factorised last, and only for it:
// solving again after refactorising the same values gives the same solution without a
// factorisation, one changed entry (the last of the values: the end of the comparison) is
// factorised, a refused matrix is refused again rather than solved with stale factors, and the
// matrix factorised before a refusal is factorised again.
TEST(TangentSolver, KeepsTheFactorsOfARepeatedMatrixOnly) {
  for (const PatternCase& pattern : Patterns()) {
    for (const LinearSolver kind :
         {LinearSolver::kDense, LinearSolver::kBanded, LinearSolver::kKlu}) {
      const std::string name = pattern.name + ", solver " + std::to_string(static_cast<int>(kind));
      SparseMatrix matrix = RandomMatrix(pattern.n, pattern.in_pattern, 5.0, 4);
      TangentSolver solver(matrix, kind);
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(pattern.n, -1.0, 2.0);
      const auto solve = [&] {
        Eigen::VectorXd x = b;
        solver.Solve(&x);
        return x;
      };
      ASSERT_TRUE(solver.Factorize(matrix)) << name;
      const Eigen::VectorXd first = solve();
      ASSERT_TRUE(solver.Factorize(matrix)) << name;
      EXPECT_EQ(solver.factorisations(), 1) << name;
      EXPECT_EQ(solve(), first) << name;

      matrix.valuePtr()[matrix.nonZeros() - 1] *= 1.5;
      const Eigen::VectorXd expected = Eigen::MatrixXd(matrix).partialPivLu().solve(b);
      ASSERT_TRUE(solver.Factorize(matrix)) << name;
      EXPECT_EQ(solver.factorisations(), 2) << name;
      EXPECT_LT((solve() - expected).cwiseAbs().maxCoeff(), 1e-11 * expected.cwiseAbs().maxCoeff())
          << name;

      const SparseMatrix last = matrix;
      std::fill_n(matrix.valuePtr(), matrix.nonZeros(), 0.0);  // the pattern kept: singular
      EXPECT_FALSE(solver.Factorize(matrix)) << name;
      EXPECT_FALSE(solver.Factorize(matrix)) << name;
      EXPECT_EQ(solver.factorisations(), 4) << name;
      // The matrix factorised before the refusals: the refused one's work overwrote its factors.
      matrix = last;
      ASSERT_TRUE(solver.Factorize(matrix)) << name;
      EXPECT_EQ(solver.factorisations(), 5) << name;
      EXPECT_LT((solve() - expected).cwiseAbs().maxCoeff(), 1e-11 * expected.cwiseAbs().maxCoeff())
          << name;
    }
  }
}

// A tridiagonal matrix whose first two rows are (1, 1, 0) and (1, 1 + delta, 0) and whose third
// starts (0, 0, ...): singular for delta = 0, singular to working precision for delta = 1e-14
// (the block is decoupled below, so its small pivot is one of the factorisation's).
SparseMatrix NearlySingular(double delta) {
  SparseMatrix matrix = RandomMatrix(
      6, [](int i, int j) { return std::abs(i - j) <= 1; }, 4.0, 7);
  matrix.coeffRef(0, 0) = 1.0;
  matrix.coeffRef(0, 1) = 1.0;
  matrix.coeffRef(1, 0) = 1.0;
  matrix.coeffRef(1, 1) = 1.0 + delta;
  matrix.coeffRef(1, 2) = 0.0;  // stored: the pattern keeps them
  matrix.coeffRef(2, 1) = 0.0;
  return matrix;
}

TEST(TangentSolver, RefusesMatricesSingularToWorkingPrecision) {
  for (const LinearSolver kind :
       {LinearSolver::kDense, LinearSolver::kBanded, LinearSolver::kKlu}) {
    for (const double delta : {0.0, 1e-14}) {
      SparseMatrix matrix = NearlySingular(delta);
      TangentSolver solver(matrix, kind);
      EXPECT_FALSE(solver.Factorize(matrix)) << static_cast<int>(kind) << ", delta " << delta;
    }
    SparseMatrix zero_row = NearlySingular(0.5);
    zero_row.coeffRef(3, 2) = zero_row.coeffRef(3, 3) = zero_row.coeffRef(3, 4) = 0.0;
    TangentSolver solver(zero_row, kind);
    EXPECT_FALSE(solver.Factorize(zero_row)) << static_cast<int>(kind) << ", a zero row";
    // Well conditioned once each row is scaled: rows of 1e-10 and 1e10 next to rows of 1.
    SparseMatrix scaled = NearlySingular(0.5);
    for (int j = 0; j < 6; ++j) {
      for (SparseMatrix::InnerIterator it(scaled, j); it; ++it) {
        if (it.row() == 2) it.valueRef() *= 1e-10;
        if (it.row() == 4) it.valueRef() *= 1e10;
      }
    }
    TangentSolver scaled_solver(scaled, kind);
    EXPECT_TRUE(scaled_solver.Factorize(scaled)) << static_cast<int>(kind) << ", scaled rows";
  }
}

// (A + A^T) / 2 of a random matrix on a symmetric pattern, its diagonal set to `diagonal`.
SparseMatrix RandomSymmetric(int n, const std::function<bool(int, int)>& in_pattern,
                             const Eigen::VectorXd& diagonal, unsigned seed) {
  const SparseMatrix random = RandomMatrix(n, in_pattern, 1.0, seed);
  SparseMatrix symmetric = 0.5 * (random + SparseMatrix(random.transpose()));
  for (int i = 0; i < n; ++i) symmetric.coeffRef(i, i) = diagonal[i];
  symmetric.makeCompressed();
  return symmetric;
}

TEST(TangentSolver, DenseSolvesSymmetricMatricesDefiniteOrNot) {
  const auto in_pattern = [](int i, int j) { return std::abs(i - j) <= 1 || i == 0 || j == 0; };
  const int n = 9;
  const Eigen::VectorXd dominant = Eigen::VectorXd::Constant(n, 6.0);
  Eigen::VectorXd indefinite = dominant;
  indefinite[4] = -6.0;
  // Units: a dof in m next to dofs in mm and rotations, D S D with D from 1e-4 to 1e4.
  const Eigen::VectorXd units = Eigen::VectorXd::LinSpaced(n, -4.0, 4.0).unaryExpr([](double e) {
    return std::pow(10.0, e);
  });
  const SparseMatrix definite_matrix = RandomSymmetric(n, in_pattern, dominant, 11);
  SparseMatrix cases[] = {
      definite_matrix,
      RandomSymmetric(n, in_pattern, indefinite, 12),
      SparseMatrix(units.asDiagonal() * definite_matrix * units.asDiagonal()),
  };
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (SparseMatrix& matrix : cases) {
    TangentSolver solver(matrix, LinearSolver::kDense);
    const Eigen::VectorXd expected = Eigen::MatrixXd(matrix).partialPivLu().solve(b);
    ASSERT_TRUE(solver.Factorize(matrix));
    Eigen::VectorXd x = b;
    solver.Solve(&x);
    // Each unknown to its own scale: the scaled case's span 1e-8 to 1e8.
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(x[i], expected[i], 1e-11 * std::abs(expected[i]) + 1e-300) << i;
    }
  }
  // A positive semi-definite block [[1, 1], [1, 1 + delta]], decoupled from the rest: singular
  // for delta = 0, singular to working precision for 1e-14, like every solver's refusal above.
  for (const double delta : {0.0, 1e-14}) {
    SparseMatrix matrix = NearlySingular(delta);
    SparseMatrix symmetric = 0.5 * (matrix + SparseMatrix(matrix.transpose()));
    TangentSolver solver(symmetric, LinearSolver::kDense);
    EXPECT_FALSE(solver.Factorize(symmetric)) << "delta " << delta;
  }
}

TEST(TangentSolver, RejectsAnUnknownSolver) {
  NewmarkOptions options;
  options.linear_solver = static_cast<LinearSolver>(9);
  EXPECT_THROW(options.Validate(), InvalidParameter);
}

hysteresis::ParallelAssembly Table9() {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                              "/models/paper/table9_thm1_system.yaml")
      .isolation;
}

structure::Structure Sdof() {
  return structure::BuildSdof(0.0317, 0.0,
                              hysteresis::SingleLaw(LawType::kThm1, {1.0, 0.2, 0.45, 20, 120}))
      .structure;
}

// `stories` floors of 25 t and 76 kN/mm on the Table 9 isolator (kN, mm, s), with 2 % relative
// Rayleigh damping on modes 1 and 2 or none.
structure::Structure IsolatedBuilding(int stories, bool rayleigh) {
  structure::ShearBuilding building;
  for (int i = 0; i < stories; ++i) {
    building.stories.push_back(
        {"story", 0.025, 3200.0, hysteresis::SingleLaw(LawType::kLinearSpring, {76.0})});
  }
  building.isolated = true;
  building.base_mass = 0.025;
  building.isolation = Table9();
  if (rayleigh) {
    building.damping.kind = structure::SuperstructureDamping::Kind::kRayleigh;
    building.damping.rayleigh_ratios[0] = building.damping.rayleigh_ratios[1] = 0.02;
  }
  return structure::BuildShearBuilding(building).structure;
}

structure::LaidOutStructure PlanBuilding() {
  return structure::BuildPlanBuilding(
      model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                           "/models/plan/five_story_table9_plan.yaml")
          .structure->plan);
}

TEST(TangentSolver, ChoosesFromThePattern) {
  const auto choice = [](const structure::Structure& s) {
    return ChooseLinearSolver(s.tangent_pattern(), LinearSolver::kAuto);
  };
  EXPECT_EQ(choice(Sdof()), LinearSolver::kDense);
  EXPECT_EQ(choice(IsolatedBuilding(5, true)), LinearSolver::kDense);
  EXPECT_EQ(choice(IsolatedBuilding(9, true)), LinearSolver::kDense);  // 10 dofs
  EXPECT_EQ(choice(IsolatedBuilding(10, true)), LinearSolver::kBanded);
  // The plan building's dofs are level by level (x, y, rotation) and its base x dof, coupled to
  // the floors' x dofs, is no border: a band of 15 each side, left to KLU.
  const structure::Structure plan = PlanBuilding().structure;
  EXPECT_EQ(plan.dofs(), 18);
  EXPECT_EQ(choice(plan), LinearSolver::kKlu);

  // Without superstructure damping a shear building's tangent is tridiagonal; relative Rayleigh
  // damping's mass-proportional part couples every floor to the base: a full base row and column.
  const structure::Structure bare = IsolatedBuilding(150, false);
  const BandStructure tridiagonal = BandStructureOf(bare.tangent_pattern());
  EXPECT_EQ(tridiagonal.lower, 1);
  EXPECT_EQ(tridiagonal.upper, 1);
  EXPECT_TRUE(tridiagonal.border.empty());
  EXPECT_EQ(choice(bare), LinearSolver::kBanded);
  const structure::Structure damped = IsolatedBuilding(150, true);
  EXPECT_EQ(damped.tangent_pattern().col(0).nonZeros(), 151);  // the base couples to every floor
  const BandStructure arrow = BandStructureOf(damped.tangent_pattern());
  EXPECT_EQ(arrow.lower, 1);
  EXPECT_EQ(arrow.upper, 1);
  EXPECT_EQ(arrow.border, std::vector<int>{0});
  EXPECT_EQ(choice(damped), LinearSolver::kBanded);

  for (const LinearSolver forced :
       {LinearSolver::kKlu, LinearSolver::kDense, LinearSolver::kBanded}) {
    EXPECT_EQ(ChooseLinearSolver(bare.tangent_pattern(), forced), forced);
    EXPECT_EQ(TangentSolver(bare.tangent_pattern(), forced).kind(), forced);
  }
}

// A ground acceleration with two frequencies (mm/s^2), 6 s at 0.01 s: the Table 9 isolator yields.
SampledHistory Shaking(double amplitude, double f1, double f2) {
  SampledHistory history{0.01, {}};
  for (int k = 0; k <= 600; ++k) {
    const double t = 0.01 * k;
    history.values.push_back(
        amplitude * std::sin(std::numbers::pi * t / 6) *
        (std::sin(2 * std::numbers::pi * f1 * t) + 0.5 * std::sin(2 * std::numbers::pi * f2 * t)));
  }
  return history;
}

// Runs `structure` with each solver forced and automatically, against KLU.
void ExpectSameRuns(const std::string& name, const structure::Structure& structure,
                    const Excitation& excitation) {
  NewmarkOptions options;
  options.linear_solver = LinearSolver::kKlu;
  ResponseHistory reference;
  const RunSummary klu = RunNewmark(structure, excitation, {0.01, 800}, options, &reference);
  ASSERT_TRUE(klu.ok()) << name << ": " << klu.message;
  const double peak = reference.displacement.cwiseAbs().maxCoeff();
  ASSERT_GT(peak, 0.0);
  for (const LinearSolver kind :
       {LinearSolver::kDense, LinearSolver::kBanded, LinearSolver::kAuto}) {
    options.linear_solver = kind;
    ResponseHistory response;
    const RunSummary summary = RunNewmark(structure, excitation, {0.01, 800}, options, &response);
    ASSERT_TRUE(summary.ok()) << name << ", solver " << static_cast<int>(kind) << ": "
                              << summary.message;
    EXPECT_EQ(summary.newton_iterations, klu.newton_iterations) << name;
    EXPECT_LT((response.displacement - reference.displacement).cwiseAbs().maxCoeff(), 1e-10 * peak)
        << name << ", solver " << static_cast<int>(kind);
  }
}

TEST(TangentSolver, RunsAgreeWithKlu) {
  ExpectSameRuns("SDOF", Sdof(), Excitation::Uniform(Shaking(3000.0, 0.5, 1.7)));
  ExpectSameRuns("five stories", IsolatedBuilding(5, true),
                 Excitation::Uniform(Shaking(3000.0, 0.5, 1.7)));
  ExpectSameRuns("150 stories, banded", IsolatedBuilding(150, false),
                 Excitation::Uniform(Shaking(3000.0, 0.3, 1.1)));
  ExpectSameRuns("150 stories, Rayleigh, banded with a border", IsolatedBuilding(150, true),
                 Excitation::Uniform(Shaking(3000.0, 0.3, 1.1)));
  const structure::LaidOutStructure plan = PlanBuilding();
  ExpectSameRuns(
      "plan", plan.structure,
      Excitation::Horizontal(plan.layout, Shaking(3000.0, 0.5, 1.7), Shaking(2000.0, 0.4, 1.3)));
}

}  // namespace
}  // namespace isolab::integrators
