#include "isolab/analysis/model_summary.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "isolab/hysteresis/friction_pendulum.h"
#include "isolab/hysteresis/law_kernel.h"
#include "isolab/structure/shear_building.h"
#include "tridiagonal_eigenvalues.h"

namespace isolab::analysis {
namespace {

using hysteresis::Vec2;
using structure::kGround;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double PeriodOf(double eigenvalue) {
  return eigenvalue > 0.0 ? 2.0 * std::numbers::pi / std::sqrt(eigenvalue) : kInfinity;
}

// Which of x, y and rotation each dof is, from the layout's levels.
std::vector<int> DofDirections(const structure::Layout& layout, int dofs) {
  std::vector<int> directions(dofs, structure::kX);
  for (const structure::Level& level : layout.levels) {
    for (int d = 0; d < 3; ++d) {
      if (level.dofs[d] != kGround) directions[level.dofs[d]] = d;
    }
  }
  return directions;
}

const char* DirectionName(int direction) {
  return direction == structure::kX ? "x" : direction == structure::kY ? "y" : "torsion";
}

Vec2 InitialStiffness(const hysteresis::PlanAssembly& assembly) {
  std::vector<hysteresis::PlanLawState> rest(assembly.state_size()), trial(assembly.state_size());
  std::vector<hysteresis::PlanLawResponse> responses(assembly.size());
  const hysteresis::PlanResponse r = assembly.Update(rest, {}, trial, responses);
  return {r.stiffness.xx, r.stiffness.yy};
}

// A slot's stiffness along x and y (a one-direction member's along its own row, y zero): its
// initial stiffness, or an isolator's secant stiffness at `displacement`.
Vec2 SlotStiffness(const hysteresis::ParallelAssembly& assembly, bool isolator,
                   double displacement) {
  return {
      isolator ? SecantStiffness(assembly, displacement) : structure::InitialStiffness(assembly),
      0.0};
}
Vec2 SlotStiffness(const hysteresis::PlanAssembly& assembly, bool isolator, double displacement) {
  return isolator ? SecantStiffness(assembly, displacement) : InitialStiffness(assembly);
}

// The stiffness matrix as triplets: every member at its initial stiffness, the isolators at their
// secant stiffness at `displacement`; or the isolators alone.
enum class Members { kAll, kIsolatorsOnly };

std::vector<Eigen::Triplet<double>> StiffnessEntries(const structure::Structure& s,
                                                     const structure::Layout& layout,
                                                     double displacement, Members which) {
  std::vector<bool> isolators(s.slots(), false);
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    isolators[isolator.slot] = true;
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t slot = 0; slot < s.slots(); ++slot) {
    const bool isolator = isolators[slot];
    if (which == Members::kIsolatorsOnly && !isolator) continue;
    const Vec2 k = s.VisitSlotAssembly(slot, [&](const auto& assembly) {
      return SlotStiffness(assembly, isolator, displacement);
    });
    const structure::Structure::Influence influence = s.SlotInfluence(slot);
    for (int a = 0; a < influence.count; ++a) {
      for (int b = 0; b < influence.count; ++b) {
        const Vec2 ta = influence.columns[a], tb = influence.columns[b];
        entries.emplace_back(influence.dofs[a], influence.dofs[b],
                             ta.x * k.x * tb.x + ta.y * k.y * tb.y);
      }
    }
  }
  return entries;
}

// M^-1/2 K M^-1/2 of a chain in one direction (a shear building): tridiagonal. Nullopt for any
// other structure.
std::optional<SymmetricTridiagonal> ChainMatrix(
    const structure::Structure& s, const structure::Layout& layout,
    const std::vector<Eigen::Triplet<double>>& entries) {
  const bool chain = std::all_of(entries.begin(), entries.end(),
                                 [](const auto& e) { return std::abs(e.row() - e.col()) <= 1; });
  if (!chain || layout.directions != 1 || layout.rotations) return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(s.dofs());
  const Eigen::VectorXd& m = s.mass();
  SymmetricTridiagonal t{std::vector<double>(n, 0.0), std::vector<double>(n > 0 ? n - 1 : 0, 0.0)};
  for (const auto& e : entries) {
    if (e.row() == e.col()) {
      t.diagonal[e.row()] += e.value() / m[e.row()];
    } else if (e.row() > e.col()) {
      t.off_diagonal[e.col()] += e.value() / std::sqrt(m[e.row()] * m[e.col()]);
    }
  }
  return t;
}

// Every mode of K x = w^2 M x with its direction, longest first, by a dense solve: none beyond
// kMaxDenseModalDofs, or where the solve fails.
std::vector<Mode> DenseModes(const structure::Structure& s, const structure::Layout& layout,
                             const std::vector<Eigen::Triplet<double>>& entries) {
  const int n = s.dofs();
  const Eigen::VectorXd& m = s.mass();
  std::vector<Mode> modes;
  if (n > kMaxDenseModalDofs) return modes;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : entries) k(e.row(), e.col()) += e.value();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      k, Eigen::MatrixXd(m.asDiagonal()));
  if (solver.info() != Eigen::Success) return modes;
  const std::vector<int> directions = DofDirections(layout, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    double share[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < n; ++i) {
      share[directions[i]] += m[i] * solver.eigenvectors()(i, j) * solver.eigenvectors()(i, j);
    }
    const int direction = static_cast<int>(std::max_element(share, share + 3) - share);
    modes.push_back({PeriodOf(solver.eigenvalues()[j]), DirectionName(direction)});
  }
  return modes;
}

// K x = w^2 M x of a structure, its isolators at their secant stiffness at `displacement`.
struct ModalProblem {
  const structure::Structure* structure;
  const structure::Layout* layout;
  double displacement;
};

// Every mode of each problem, longest first: a chain's periods from its tridiagonal matrix (any
// size; the chains solved together), any other structure's modes densely.
std::vector<std::vector<Mode>> Modes(const std::vector<ModalProblem>& problems) {
  std::vector<std::vector<Mode>> modes(problems.size());
  std::vector<SymmetricTridiagonal> chains;
  std::vector<std::size_t> chain_problems;
  for (std::size_t k = 0; k < problems.size(); ++k) {
    const ModalProblem& problem = problems[k];
    const std::vector<Eigen::Triplet<double>> entries =
        StiffnessEntries(*problem.structure, *problem.layout, problem.displacement, Members::kAll);
    if (std::optional<SymmetricTridiagonal> chain =
            ChainMatrix(*problem.structure, *problem.layout, entries)) {
      chains.push_back(std::move(*chain));
      chain_problems.push_back(k);
    } else {
      modes[k] = DenseModes(*problem.structure, *problem.layout, entries);
    }
  }
  const std::vector<std::vector<double>> eigenvalues = TridiagonalEigenvalues(std::move(chains));
  for (std::size_t c = 0; c < eigenvalues.size(); ++c) {
    for (const double eigenvalue : eigenvalues[c]) {
      modes[chain_problems[c]].push_back({PeriodOf(eigenvalue), "x"});
    }
  }
  return modes;
}

}  // namespace

double ModelSummary::LongestPeriod() const {
  double longest = isolated_period;
  if (!fixed_base_modes.empty()) longest = std::max(longest, fixed_base_modes.front().period);
  return longest;
}

std::vector<double> ModelSummary::FixedBasePeriods() const {
  std::vector<double> periods;
  for (const Mode& mode : fixed_base_modes) periods.push_back(mode.period);
  return periods;
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

Vec2 SecantStiffness(const hysteresis::PlanAssembly& assembly, double displacement) {
  constexpr int kIncrements = 200;
  Vec2 secant;
  for (const Vec2 direction : {Vec2{1.0, 0.0}, Vec2{0.0, 1.0}}) {
    std::vector<hysteresis::PlanLawState> committed(assembly.state_size()),
        trial(assembly.state_size());
    std::vector<hysteresis::PlanLawResponse> responses(assembly.size());
    double force = 0.0;
    for (int i = 1; i <= kIncrements; ++i) {
      const hysteresis::PlanLawInput in{(displacement * i / kIncrements) * direction, {}, 0.0};
      force = Dot(direction, assembly.Update(committed, in, trial, responses).force);
      committed.swap(trial);
    }
    (direction.x == 1.0 ? secant.x : secant.y) = force / displacement;
  }
  return secant;
}

std::vector<Mode> RigidModes(const structure::Structure& s, const structure::Layout& layout,
                             double displacement) {
  // The rigid body's dofs: the base's x (y, rotation); R carries them to every level's dofs.
  const int rigid = layout.directions + (layout.rotations ? 1 : 0);
  const int theta = layout.directions;  // the rotation's column of R
  const Vec2 base = layout.levels.front().centre_of_mass;
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(s.dofs(), rigid);
  for (const structure::Level& level : layout.levels) {
    const Vec2 arm = level.centre_of_mass - base;
    if (level.dofs[structure::kX] != kGround) {
      r(level.dofs[structure::kX], 0) = 1.0;
      if (layout.rotations) r(level.dofs[structure::kX], theta) = -arm.y;
    }
    if (level.dofs[structure::kY] != kGround) {
      r(level.dofs[structure::kY], 1) = 1.0;
      if (layout.rotations) r(level.dofs[structure::kY], theta) = arm.x;
    }
    if (level.dofs[structure::kRotation] != kGround)
      r(level.dofs[structure::kRotation], theta) = 1.0;
  }
  // R^T K R summed over K's few entries (the isolators') rather than with K formed densely: dofs x
  // dofs, 8 MB at 1000 stories, zeroed and multiplied at every call.
  Eigen::MatrixXd k_rigid = Eigen::MatrixXd::Zero(rigid, rigid);
  for (const auto& e : StiffnessEntries(s, layout, displacement, Members::kIsolatorsOnly)) {
    for (int a = 0; a < rigid; ++a) {
      const double row = r(e.row(), a) * e.value();
      for (int b = 0; b < rigid; ++b) k_rigid(a, b) += row * r(e.col(), b);
    }
  }
  const Eigen::MatrixXd m_rigid = r.transpose() * s.mass().asDiagonal() * r;
  std::vector<Mode> modes;
  if (rigid == 1) {
    modes.push_back({PeriodOf(k_rigid(0, 0) / m_rigid(0, 0)), "x"});
    return modes;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k_rigid, m_rigid);
  for (int j = 0; j < rigid; ++j) {
    int direction = 0;
    double largest = -1.0;
    for (int i = 0; i < rigid; ++i) {
      const double share =
          m_rigid(i, i) * solver.eigenvectors()(i, j) * solver.eigenvectors()(i, j);
      if (share > largest) {
        largest = share;
        direction = i == theta ? structure::kRotation : i;
      }
    }
    modes.push_back({PeriodOf(solver.eigenvalues()[j]), DirectionName(direction)});
  }
  return modes;
}

namespace {

bool Outside(double value, const double (&range)[2]) {
  return !(value >= range[0] && value <= range[1]);
}

// Friction pendulums among a component's laws, with the name to warn about.
void WarnAboutPendulum(const std::string& name, const hysteresis::LawParameters& parameters,
                       const UnitSystem& units, double total_weight,
                       std::vector<std::string>* warnings) {
  const hysteresis::LawKernel kernel = parameters.Kernel();
  const auto* pendulum = std::get_if<hysteresis::FrictionPendulum>(&kernel);
  if (pendulum == nullptr) return;
  if (pendulum->weight > 1.5 * total_weight) {
    warnings->push_back(fmt::format(
        "friction pendulum '{}' carries W = {:.4g} {}, more than the whole structure weighs "
        "({:.4g} {}): check its units",
        name, pendulum->weight, units.force(), total_weight, units.force()));
  }
  if (pendulum->stiffness == 0.0) return;  // a flat slider
  const double radius_m =
      pendulum->weight / pendulum->stiffness / units.Convert(1.0, "m", dimension::kLength);
  if (Outside(radius_m, kPlausiblePendulumRadius)) {
    warnings->push_back(fmt::format(
        "friction pendulum '{}' has a radius of {:.4g} m, outside the {:g} to {:g} m of "
        "bearings built: check its units",
        name, radius_m, kPlausiblePendulumRadius[0], kPlausiblePendulumRadius[1]));
  }
}

// Story heights, level masses and pendulum bearings no real building has: almost always a value
// given without its unit, read in the model's.
void WarnAboutDimensions(const structure::Structure& s, const structure::Layout& layout,
                         const UnitSystem& units, double total_weight,
                         std::vector<std::string>* warnings) {
  const double metre = units.Convert(1.0, "m", dimension::kLength);
  const double tonne = units.Convert(1.0, "t", dimension::kMass);
  if (!layout.stories.empty()) {
    for (std::size_t i = 0; i < layout.stories.size(); ++i) {
      const double height = layout.stories[i].height;
      if (height > 0.0 && Outside(height / metre, kPlausibleStoryHeight)) {
        warnings->push_back(fmt::format(
            "story {}'s height, {:g} {} ({:.3g} m), is outside the {:g} to {:g} m of real "
            "stories: a height without a unit is in {}",
            i + 1, height, units.length(), height / metre, kPlausibleStoryHeight[0],
            kPlausibleStoryHeight[1], units.length()));
        break;
      }
    }
    for (const structure::Level& level : layout.levels) {
      const double mass = s.mass()[level.dofs[structure::kX]] / tonne;
      if (Outside(mass, kPlausibleLevelMass)) {
        warnings->push_back(fmt::format(
            "the mass of {}, {:.4g} t, is outside the {:g} to {:g} t of real floors: a mass "
            "without a unit is in force*time^2/length of the model's units ({}*{}^2/{})",
            level.name, mass, kPlausibleLevelMass[0], kPlausibleLevelMass[1], units.force(),
            units.time(), units.length()));
        break;
      }
    }
  }
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    s.VisitSlotAssembly(isolator.slot, [&](const auto& assembly) {
      for (const auto& component : assembly.components()) {
        WarnAboutPendulum(component.name, hysteresis::LawAlongX(component), units, total_weight,
                          warnings);
      }
    });
  }
}

// Bearings that are all pendulums at their own W (no axial_load) carry the weight their laws were
// given, not the building's: when the two differ by more than kWeightMismatch, every friction and
// restoring force of the runs is off by that ratio.
void WarnAboutBearingWeights(const structure::Structure& s, const structure::Layout& layout,
                             const UnitSystem& units, double total_weight,
                             std::vector<std::string>* warnings) {
  constexpr double kWeightMismatch = 0.05;
  if (!s.axial_loads().empty() || layout.isolators.empty() || !(total_weight > 0.0)) return;
  double carried = 0.0;
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    const std::optional<double> w = s.VisitSlotAssembly(
        isolator.slot, [](const auto& assembly) { return hysteresis::PendulumWeight(assembly); });
    if (!w) return;
    carried += *w;
  }
  if (std::abs(carried / total_weight - 1.0) <= kWeightMismatch) return;
  warnings->push_back(fmt::format(
      "the friction pendulums' weights w sum to {:.5g} {}, the structure weighs {:.5g} {} ({:+.1f} "
      "%): their friction and restoring forces are those of {:.5g} {}. Give each bearing its "
      "share of the weight, or axial_load: {{}} to load them with the structure's own "
      "(docs/axial_load.md)",
      carried, units.force(), total_weight, units.force(), 100.0 * (carried / total_weight - 1.0),
      carried, units.force()));
}

}  // namespace

namespace {

// The isolators' secant stiffnesses at D, summed (along x in plan).
double IsolatorsSecantStiffness(const structure::Structure& s, const structure::Layout& layout,
                                double displacement) {
  double stiffness = 0.0;
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    stiffness += s.VisitSlotAssembly(isolator.slot, [&](const auto& assembly) {
                    return SlotStiffness(assembly, true, displacement);
                  }).x;
  }
  return stiffness;
}

double Longest(const std::vector<Mode>& modes) {
  double period = 0.0;
  for (const Mode& mode : modes) period = std::max(period, mode.period);
  return period;
}

}  // namespace

SecantIsolation IsolationAt(const structure::Structure& s, const structure::Layout& layout,
                            double displacement) {
  return {IsolatorsSecantStiffness(s, layout, displacement),
          Longest(RigidModes(s, layout, displacement))};
}

ModelSummary SummariseModel(const structure::Structure& s, const structure::Layout& layout,
                            const structure::LaidOutStructure* fixed_base, const UnitSystem& units,
                            double pga, double trial_displacement) {
  ModelSummary summary;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  const double seconds = units.Convert(1.0, "s", dimension::kTime);
  for (const structure::Level& level : layout.levels) {
    summary.total_mass += s.mass()[level.dofs[structure::kX]];
  }
  summary.total_weight = summary.total_mass * g;
  summary.pga = pga;
  summary.trial_displacement = trial_displacement;
  summary.isolated = layout.isolated();
  // The fixed-base modes first, then the isolated ones: solved together.
  std::vector<ModalProblem> problems;
  if (fixed_base) {
    problems.push_back({&fixed_base->structure, &fixed_base->layout, 0.0});
  } else if (!summary.isolated) {
    problems.push_back({&s, &layout, 0.0});
  }
  const bool has_fixed_base = !problems.empty();
  if (summary.isolated) problems.push_back({&s, &layout, trial_displacement});
  std::vector<std::vector<Mode>> modes = Modes(problems);
  if (has_fixed_base) summary.fixed_base_modes = std::move(modes.front());
  if (summary.isolated) {
    summary.secant_stiffness = IsolatorsSecantStiffness(s, layout, trial_displacement);
    summary.rigid_modes = RigidModes(s, layout, trial_displacement);
    summary.isolated_period = Longest(summary.rigid_modes);
    summary.isolated_modes = std::move(modes.back());
  }

  const std::string check = "check the units of the masses and stiffnesses";
  if (pga > kMaxPlausiblePga * g) {
    summary.warnings.push_back(fmt::format(
        "the record's peak ground acceleration, {:.3g} g, exceeds {:g} g, more than any "
        "earthquake has produced: check the record's units and the scale",
        pga / g, kMaxPlausiblePga));
  }
  if (!summary.fixed_base_modes.empty() &&
      summary.fixed_base_modes.front().period > kMaxPlausiblePeriod * seconds) {
    summary.warnings.push_back(fmt::format(
        "the superstructure's fixed-base first period, {:.4g} {}, exceeds {:g} s, longer than "
        "any building's: {}",
        summary.fixed_base_modes.front().period, units.time(), kMaxPlausiblePeriod, check));
  }
  WarnAboutDimensions(s, layout, units, summary.total_weight, &summary.warnings);
  WarnAboutBearingWeights(s, layout, units, summary.total_weight, &summary.warnings);
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

double IdentifiedRangeFactor(const identification::IdentifiedRange& range, double displacement,
                             double velocity) {
  return std::max(displacement / range.displacement, velocity / range.velocity);
}

std::string IdentifiedRangeWarning(const identification::IdentifiedRange& range,
                                   double displacement, double velocity, const UnitSystem& units) {
  const std::string velocity_unit = fmt::format("{}/{}", units.length(), units.time());
  std::vector<std::string> beyond;
  const double farthest = IdentifiedRangeFactor(range, displacement, velocity);
  for (const auto& [reached, identified, unit] :
       {std::tuple{displacement, range.displacement, std::string(units.length())},
        std::tuple{velocity, range.velocity, velocity_unit}}) {
    const double ratio = reached / identified;
    if (ratio > kIdentifiedRangeMargin) {
      beyond.push_back(fmt::format("{:.4g} {} ({:.2f} times)", reached, unit, ratio));
    }
  }
  if (beyond.empty()) return "";
  const std::string grade =
      farthest > kFarBeyondIdentifiedRange
          ? fmt::format(
                "far beyond the range the fit saw (more than {:g} times it): the response "
                "there rests on the law's form alone, not on the data",
                kFarBeyondIdentifiedRange)
          : "beyond the range the fit saw, the model extrapolates";
  return fmt::format(
      "the isolation was identified up to {:.4g} {} and {:.4g} {} over {:g} cycles ({}); this "
      "run reaches {}: {}",
      range.displacement, units.length(), range.velocity, velocity_unit, range.cycles,
      fmt::join(range.data, ", "), fmt::join(beyond, " and "), grade);
}

}  // namespace isolab::analysis
