#include "isolab/io/model_summary.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "isolab/structure/shear_building.h"

namespace isolab::io {
namespace {

// Periods of the fixed-base shear building, longest first. K is tridiagonal, so M^-1/2 K M^-1/2
// is too and its eigenvalues cost O(n^2): cheap for thousands of stories.
std::vector<double> FixedBasePeriods(const std::vector<structure::Story>& stories) {
  const auto n = static_cast<Eigen::Index>(stories.size());
  if (n == 0) return {};
  Eigen::VectorXd k(n), m(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    k[i] = structure::InitialStiffness(stories[i].assembly);
    m[i] = stories[i].floor_mass;
  }
  Eigen::VectorXd diagonal(n), off_diagonal(std::max<Eigen::Index>(n - 1, 0));
  for (Eigen::Index i = 0; i < n; ++i) {
    diagonal[i] = (k[i] + (i + 1 < n ? k[i + 1] : 0.0)) / m[i];
    if (i + 1 < n) off_diagonal[i] = -k[i + 1] / std::sqrt(m[i] * m[i + 1]);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off_diagonal, Eigen::EigenvaluesOnly);
  std::vector<double> periods;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double omega_squared = solver.eigenvalues()[i];  // ascending
    periods.push_back(omega_squared > 0.0 ? 2.0 * std::numbers::pi / std::sqrt(omega_squared)
                                          : INFINITY);
  }
  return periods;
}

}  // namespace

double ModelSummary::LongestPeriod() const {
  double longest = isolated_period;
  if (!fixed_base_periods.empty()) longest = std::max(longest, fixed_base_periods.front());
  return longest;
}

double SecantStiffness(const hysteresis::ParallelAssembly& assembly, double displacement) {
  // Piecewise-linear laws update exactly in one call; the increments are for Bouc-Wen.
  constexpr int kIncrements = 200;
  std::vector<hysteresis::LawState> committed(assembly.state_size()), trial(assembly.state_size());
  std::vector<hysteresis::LawResponse> responses(assembly.size());
  double force = 0.0;
  for (int i = 1; i <= kIncrements; ++i) {
    force =
        assembly.Update(committed, {displacement * i / kIncrements, 0.0}, trial, responses).force;
    committed.swap(trial);
  }
  return force / displacement;
}

ModelSummary SummariseModel(const ModelFile& model, bool fixed_base, double pga,
                            double trial_displacement) {
  ModelSummary summary;
  const UnitSystem& units = model.units;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  const double seconds = units.Convert(1.0, "s", dimension::kTime);
  const StructureSection& structure = *model.structure;
  if (structure.kind == StructureSection::Kind::kSdof) {
    summary.total_mass = structure.mass;
    summary.isolated = true;
  } else {
    const structure::ShearBuilding& building = structure.building;
    for (const structure::Story& story : building.stories) summary.total_mass += story.floor_mass;
    summary.isolated = !fixed_base && model.isolation.size() > 0;
    if (summary.isolated) summary.total_mass += building.base_mass;
    summary.fixed_base_periods = FixedBasePeriods(building.stories);
  }
  summary.total_weight = summary.total_mass * g;
  summary.pga = pga;
  summary.trial_displacement = trial_displacement;
  if (summary.isolated) {
    summary.secant_stiffness = SecantStiffness(model.isolation, trial_displacement);
    summary.isolated_period =
        summary.secant_stiffness > 0.0
            ? 2.0 * std::numbers::pi * std::sqrt(summary.total_mass / summary.secant_stiffness)
            : INFINITY;
  }

  const std::string check = "check the units of the masses and stiffnesses";
  if (pga > kMaxPlausiblePga * g) {
    summary.warnings.push_back(fmt::format(
        "the record's peak ground acceleration, {:.3g} g, exceeds {:g} g, more than any "
        "earthquake has produced: check the record's units and the scale",
        pga / g, kMaxPlausiblePga));
  }
  if (!summary.fixed_base_periods.empty() &&
      summary.fixed_base_periods.front() > kMaxPlausiblePeriod * seconds) {
    summary.warnings.push_back(fmt::format(
        "the superstructure's fixed-base first period, {:.4g} {}, exceeds {:g} s, longer than "
        "any building's: {}",
        summary.fixed_base_periods.front(), units.time(), kMaxPlausiblePeriod, check));
  }
  if (summary.isolated && summary.isolated_period > kMaxPlausiblePeriod * seconds) {
    summary.warnings.push_back(fmt::format(
        "the period at {:g} {}, {:.4g} {}, exceeds {:g} s, longer than any isolated structure's: "
        "{}",
        trial_displacement, units.length(), summary.isolated_period, units.time(),
        kMaxPlausiblePeriod, check));
  }
  return summary;
}

std::string IsolatorDisplacementWarning(double peak, const UnitSystem& units) {
  const double limit = units.Convert(kMaxBearingDisplacement, "m", dimension::kLength);
  if (!(peak > limit)) return "";
  return fmt::format(
      "the peak isolator displacement, {:g} {}, exceeds {:g} m, beyond any bearing built: "
      "check the record's units and scale, the masses and the isolator's stiffnesses",
      peak, units.length(), kMaxBearingDisplacement);
}

}  // namespace isolab::io
