#include "isolab/design/equivalent_lateral_force.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <variant>

#include "isolab/core/errors.h"
#include "isolab/cyclic/path_replay.h"
#include "isolab/model/build_structure.h"

namespace isolab::design {
namespace {

constexpr int kCycles = 3;
constexpr double kFourPiSquared = 4.0 * std::numbers::pi * std::numbers::pi;
constexpr double kAccidentalRatio = 0.05;  // Eq. 17.5-3's accidental eccentricity, of the plan
constexpr double kTotalDisplacementFloor = 1.15;  // D_TM >= 1.15 D_M
constexpr int kStepsPerCycle = 400;               // a multiple of 4: u = +-D are samples

// u = D sin(2 pi t / T) along x for kCycles cycles, and where each cycle starts.
io::DisplacementPath SinePath(double amplitude, double period, std::vector<std::size_t>* starts) {
  io::DisplacementPath path;
  path.name = "elf";
  const int samples = kCycles * kStepsPerCycle;
  for (int k = 0; k <= samples; ++k) {
    const double phase = 2.0 * std::numbers::pi * (k % kStepsPerCycle) / kStepsPerCycle;
    path.time.push_back(k * period / kStepsPerCycle);
    path.displacement.push_back({amplitude * std::sin(phase), 0.0});
  }
  starts->clear();
  for (int c = 0; c <= kCycles; ++c)
    starts->push_back(static_cast<std::size_t>(c * kStepsPerCycle));
  return path;
}

// The last cycle of a replay along SinePath: forces at u = +D and -D, and the energy.
template <typename Assembly>
EffectiveProperties LastCycle(const Assembly& assembly, double displacement, double period) {
  std::vector<std::size_t> starts;
  const io::DisplacementPath path = SinePath(displacement, period, &starts);
  const cyclic::ReplayResult replay = cyclic::Replay(assembly, path, starts);
  const std::size_t first = starts[kCycles - 1];
  const double positive = replay.force[first + kStepsPerCycle / 4].x;
  const double negative = replay.force[first + 3 * kStepsPerCycle / 4].x;
  EffectiveProperties p;
  p.displacement = displacement;
  p.stiffness = (std::abs(positive) + std::abs(negative)) / (2.0 * displacement);
  p.dissipated = replay.cycles.back().dissipated;
  return p;
}

// What makes two isolators' laws the same, bit for bit: each component's law and its values (an
// uncoupled pair's y law too).
void Sign(const hysteresis::LawParameters& law, std::vector<std::uint64_t>* signature) {
  signature->push_back(static_cast<std::uint64_t>(law.type()));
  for (const double v : law.Values(hysteresis::ParameterForm::kMathematical)) {
    signature->push_back(std::bit_cast<std::uint64_t>(v));
  }
}
std::vector<std::uint64_t> Signature(const hysteresis::ParallelAssembly& assembly) {
  std::vector<std::uint64_t> signature = {0};
  for (const hysteresis::Component& c : assembly.components()) Sign(c.parameters, &signature);
  return signature;
}
std::vector<std::uint64_t> Signature(const hysteresis::PlanAssembly& assembly) {
  std::vector<std::uint64_t> signature = {1};
  for (const hysteresis::PlanComponent& c : assembly.components()) {
    Sign(c.law, &signature);
    signature.push_back(c.law_y ? 1 : 0);
    if (c.law_y) Sign(*c.law_y, &signature);
  }
  return signature;
}

void SetDamping(EffectiveProperties* p) {
  p->damping = p->stiffness > 0.0 ? p->dissipated / (2.0 * std::numbers::pi * p->stiffness *
                                                     p->displacement * p->displacement)
                                  : 0.0;
}

}  // namespace

double DampingCoefficient(double beta) {
  static constexpr std::array<std::pair<double, double>, 7> kTable = {
      {{0.02, 0.8}, {0.05, 1.0}, {0.10, 1.2}, {0.20, 1.5}, {0.30, 1.7}, {0.40, 1.9}, {0.50, 2.0}}};
  if (beta <= kTable.front().first) return kTable.front().second;
  for (std::size_t i = 1; i < kTable.size(); ++i) {
    if (beta <= kTable[i].first) {
      const auto [b0, c0] = kTable[i - 1];
      const auto [b1, c1] = kTable[i];
      return c0 + (c1 - c0) * (beta - b0) / (b1 - b0);
    }
  }
  return kTable.back().second;
}

IsolationSystem::IsolationSystem(const model::ModelFile& model) {
  const structure::LaidOutStructure laid_out = model::BuildStructure(model);
  const structure::Structure& s = laid_out.structure;
  if (!laid_out.layout.isolated()) {
    throw InputError({model.path},
                     "the model has no isolation: the equivalent lateral force procedure is for "
                     "an isolation system");
  }
  // The weights the runs load the pendulums with: under axial_load, each at its static share N_0
  // (its response is N_0 / W times its law's, as Structure::Evaluate scales it at rest).
  std::vector<double> scales(s.slots(), 1.0);
  for (const structure::AxialBearing& bearing : s.axial_loads().bearings) {
    scales[bearing.slot] = bearing.static_load / bearing.weight;
  }
  // Bearings of one type (a group's, or every bearing of a layer) are one law evaluated once: the
  // cycles at D are the same for each, and each takes them times its own scale.
  std::vector<std::vector<std::uint64_t>> signatures;
  for (const structure::IsolatorLayout& isolator : laid_out.layout.isolators) {
    positions_.push_back(isolator.position);
    const auto slot = static_cast<std::size_t>(isolator.slot);
    const std::optional<double> law = s.VisitSlotAssembly(
        slot, [](const auto& assembly) { return hysteresis::PendulumWeight(assembly); });
    const double w = law.value_or(std::numeric_limits<double>::quiet_NaN());
    bearing_weights_.push_back({isolator.name, w, w * scales[slot]});
    const std::vector<std::uint64_t> signature =
        s.VisitSlotAssembly(slot, [](const auto& assembly) { return Signature(assembly); });
    const auto same = std::find(signatures.begin(), signatures.end(), signature);
    bearings_.push_back({static_cast<std::size_t>(same - signatures.begin()), scales[slot]});
    if (same != signatures.end()) continue;
    signatures.push_back(signature);
    laws_.push_back(s.VisitSlotAssembly(
        slot, [](const auto& assembly) -> std::function<EffectiveProperties(double, double)> {
          return [assembly](double d, double t) { return LastCycle(assembly, d, t); };
        }));
  }
  gravity_ = model.units.Convert(1.0, "g", dimension::kAcceleration);
  double mass = 0.0;
  for (const structure::Level& level : laid_out.layout.levels) {
    mass += s.mass()[level.dofs[structure::kX]];
  }
  weight_ = mass * gravity_;
}

std::vector<EffectiveProperties> IsolationSystem::BearingProperties(double displacement,
                                                                    double period) const {
  std::vector<EffectiveProperties> laws;
  for (const auto& law : laws_) laws.push_back(law(displacement, period));
  std::vector<EffectiveProperties> bearings;
  for (const Bearing& bearing : bearings_) {
    EffectiveProperties p = laws[bearing.law];
    p.stiffness *= bearing.scale;
    p.dissipated *= bearing.scale;
    SetDamping(&p);
    bearings.push_back(p);
  }
  return bearings;
}

EffectiveProperties IsolationSystem::At(double displacement, double period) const {
  EffectiveProperties sum;
  sum.displacement = displacement;
  for (const EffectiveProperties& p : BearingProperties(displacement, period)) {
    sum.stiffness += p.stiffness;
    sum.dissipated += p.dissipated;
  }
  SetDamping(&sum);
  return sum;
}

ElfResult SolveElf(const IsolationSystem& system, const DisplacementDemand& demand, double metre) {
  const double mass = system.weight() / system.gravity();
  const auto period_of = [&](const EffectiveProperties& p) {
    return 2.0 * std::numbers::pi * std::sqrt(mass / p.stiffness);
  };
  ElfResult result;
  double cycle_period = 2.0;  // of the cycles, for rate-dependent laws: T_M once found
  for (int pass = 0; pass < 50; ++pass) {
    const auto excess = [&](double d) {
      const EffectiveProperties p = system.At(d, cycle_period);
      return demand(period_of(p), p.damping) - d;
    };
    // Scan down for the largest D where demand - D turns from negative to positive.
    constexpr int kScan = 120;
    const double high = 50.0 * metre, low = 1e-5 * metre;
    const double ratio = std::pow(low / high, 1.0 / kScan);
    double upper = high, f_upper = excess(high);
    double lower = 0.0;
    for (int i = 1; i <= kScan && lower == 0.0; ++i) {
      const double d = high * std::pow(ratio, i);
      const double f = excess(d);
      if (f_upper < 0.0 && f >= 0.0) {
        lower = d;
      } else {
        upper = d;
        f_upper = f;
      }
    }
    if (lower == 0.0) {
      throw std::runtime_error(
          fmt::format("no displacement from {:g} to {:g} balances the design demand (the "
                      "isolation system's effective period and damping never meet it)",
                      low, high));
    }
    while (upper - lower > 1e-12 * upper) {
      const double middle = 0.5 * (lower + upper);
      (excess(middle) >= 0.0 ? lower : upper) = middle;
      ++result.iterations;
    }
    result.displacement = 0.5 * (lower + upper);
    result.at_design = system.At(result.displacement, cycle_period);
    result.period = period_of(result.at_design);
    const bool settled = std::abs(result.period - cycle_period) <= 1e-9 * result.period;
    cycle_period = result.period;
    if (settled) break;
  }
  result.base_shear = result.at_design.stiffness * result.displacement;
  return result;
}

double CodeDampingCoefficient(const spectra::TargetSpectrum& target, double beta) {
  if (std::holds_alternative<spectra::Eurocode8Spectrum>(target)) {
    return 1.0 / spectra::DampingCorrection(beta);
  }
  return DampingCoefficient(beta);
}

DisplacementDemand CodeDemand(const spectra::TargetSpectrum& target, const UnitSystem& units) {
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);  // length/time^2
  const double second = 1.0 / units.SiFactor(dimension::kTime);        // model time per s
  return [target, g, second](double period, double beta) {
    const double t = period / second;  // s
    const double b = CodeDampingCoefficient(target, beta);
    if (const auto* asce = std::get_if<spectra::Asce7Spectrum>(&target)) {
      return g * asce->sm1 * second * period / (kFourPiSquared * b);
    }
    return spectra::ContinuedSpectralAcceleration(target, t) * g * period * period /
           (kFourPiSquared * b);
  };
}

double TotalDisplacement(const model::ModelFile& model, const IsolationSystem& system,
                         const ElfResult& elf) {
  const double floor = kTotalDisplacementFloor * elf.displacement;
  if (!model.structure || model.structure->kind != model::StructureSection::Kind::kPlanBuilding) {
    return floor;
  }
  const structure::PlanBuilding& plan = model.structure->plan;
  double mass = plan.base.mass;
  hysteresis::Vec2 mass_centre = plan.base.mass * plan.base.centre_of_mass;
  for (const structure::PlanStory& story : plan.stories) {
    mass += story.floor.mass;
    mass_centre = mass_centre + story.floor.mass * story.floor.centre_of_mass;
  }
  mass_centre = (1.0 / mass) * mass_centre;
  std::vector<double> k;
  for (const EffectiveProperties& b : system.BearingProperties(elf.displacement, elf.period)) {
    k.push_back(b.stiffness);
  }
  const std::vector<hysteresis::Vec2>& p = system.positions();
  hysteresis::Vec2 rigidity;
  double k_sum = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    rigidity = rigidity + k[i] * p[i];
    k_sum += k[i];
  }
  rigidity = (1.0 / k_sum) * rigidity;
  double y_max[2] = {0.0, 0.0}, r2 = 0.0;
  for (const hysteresis::Vec2& q : p) {
    const hysteresis::Vec2 from_rigidity = q - rigidity, from_mass = q - mass_centre;
    r2 += from_mass.x * from_mass.x + from_mass.y * from_mass.y;
    y_max[0] = std::max(y_max[0], std::abs(from_rigidity.y));  // motion along x: across is y
    y_max[1] = std::max(y_max[1], std::abs(from_rigidity.x));
  }
  const double b = model.structure->footprint_size.x, d = model.structure->footprint_size.y;
  const double plan_gyration = std::sqrt((b * b + d * d) / 12.0);
  const double pt = std::sqrt(r2 / static_cast<double>(p.size())) / plan_gyration;
  const double e[2] = {std::abs(mass_centre.y - rigidity.y) + kAccidentalRatio * d,
                       std::abs(mass_centre.x - rigidity.x) + kAccidentalRatio * b};
  double total = floor;
  for (int dir = 0; dir < 2; ++dir) {
    total = std::max(
        total, elf.displacement * (1.0 + y_max[dir] / (pt * pt) * 12.0 * e[dir] / (b * b + d * d)));
  }
  return total;
}

}  // namespace isolab::design
