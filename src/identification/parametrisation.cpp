#include "isolab/identification/parametrisation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "parallel_for.h"

namespace isolab::identification {

using hysteresis::LawType;

double CoordinateRange::At(double x) const {
  x = std::clamp(x, 0.0, 1.0);
  return log ? low * std::pow(high / low, x) : low + x * (high - low);
}

double CoordinateRange::Inverse(double value) const {
  const double x =
      log ? std::log(value / low) / std::log(high / low) : (value - low) / (high - low);
  return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.5;
}

std::vector<std::string> CoordinateNames(LawType type) {
  switch (type) {
    case LawType::kThm1:
      return {"k1_ratio", "k2_ratio", "uy", "uyh_gap"};
    case LawType::kBhm1:
      return {"k1_ratio", "uy"};
    case LawType::kThm2:
      return {"uy", "uyh"};
    case LawType::kBhm2:
    case LawType::kElastoplastic:
      return {"uy"};
    case LawType::kTrilinearElastic:
      return {"uyh"};
    case LawType::kDegradingBhm2:
      return {"uy", "loss", "slip_scale"};
    case LawType::kLinearSpring:
    case LawType::kDashpot:
      return {};
    case LawType::kAsymmetricElastoplastic:
      return {"uy_pos", "uy_neg"};
    case LawType::kBacklashElastoplastic:
      return {"uy", "gap"};
    case LawType::kBoucWen:
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      break;
  }
  throw std::invalid_argument(std::string(hysteresis::LawName(type)) +
                              " components cannot be identified (yet)");
}

namespace {

// What each amplitude of a law type is, in the law's mathematical parameters.
std::vector<const char*> AmplitudeKeys(LawType type) {
  switch (type) {
    case LawType::kThm2:
      return {"k0-k1", "k1", "k2"};
    case LawType::kBhm2:
    case LawType::kDegradingBhm2:
      return {"k0-k1", "k1"};
    case LawType::kTrilinearElastic:
      return {"k1", "k2"};
    case LawType::kLinearSpring:
      return {"k"};
    case LawType::kDashpot:
      return {"c"};
    default:
      return {"k0"};
  }
}

// Amplitudes of a law type and whether each must be >= 0: THM2 and BHM2 (k0 - k1, k1, [k2]),
// trilinear (k1, k2), and one stiffness (or c) for the others.
std::vector<bool> AmplitudeSigns(LawType type) {
  switch (type) {
    case LawType::kThm2:
      return {true, true, false};
    case LawType::kBhm2:
    case LawType::kDegradingBhm2:
      return {true, true};
    case LawType::kTrilinearElastic:
      return {true, false};
    default:
      return {true};
  }
}

CoordinateRange DefaultRange(const std::string& name, const DataScales& s) {
  const double u = s.displacement;
  if (name == "k1_ratio") return {1e-5, 0.99, true};
  if (name == "k2_ratio") return {-3.0, 0.99, false};
  if (name == "uy" || name == "uy_pos" || name == "uy_neg") return {1e-4 * u, u, true};
  if (name == "gap") return {1e-3 * u, u, true};
  if (name == "uyh" || name == "uyh_gap") return {1e-2 * u, 2 * u, true};
  if (name == "loss") return {0.0, 0.95, false};
  // A cycle of amplitude u slips about 4 u: from a fraction of a cycle to many cycles.
  if (name == "slip_scale") return {1e-2 * u, 1e2 * u, true};
  throw std::logic_error("no default range for " + name);
}

double Clamp(double u, double limit) { return std::clamp(u, -limit, limit); }

// One law with unit amplitude driven through tests [first, last) into column `column` of each
// test's basis: each from rest, or, for one specimen, in order from the state the previous test
// left (then the range is all tests).
void UnitLawForce(const hysteresis::ParallelAssembly& law, std::span<const CyclicTestData> tests,
                  std::size_t first, std::size_t last, bool one_specimen, Eigen::Index column,
                  std::vector<Eigen::MatrixXd>* bases) {
  std::vector<hysteresis::LawState> state(law.state_size());
  for (std::size_t i = first; i < last; ++i) {
    if (!one_specimen) std::fill(state.begin(), state.end(), hysteresis::LawState{});
    Eigen::MatrixXd& basis = (*bases)[i];
    // Column-major storage: a column is contiguous.
    SimulateForceFrom(law, tests[i], state,
                      std::span<double>(basis.col(column).data(), basis.rows()));
  }
}

}  // namespace

ModelParametrisation::ModelParametrisation(std::vector<ComponentSpec> components,
                                           const DataScales& scales)
    : components_(std::move(components)) {
  first_amplitude_.push_back(0);
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const ComponentSpec& spec = components_[i];
    const std::vector<std::string> names = CoordinateNames(spec.type);
    const auto check = [&](const auto& map, const char* what) {
      for (const auto& entry : map) {
        if (std::find(names.begin(), names.end(), entry.first) == names.end()) {
          throw std::invalid_argument(
              spec.name + ": '" + entry.first + "' is not a shape coordinate of " +
              std::string(hysteresis::LawName(spec.type)) + " (" + what + ")");
        }
      }
    };
    check(spec.ranges, "bounds");
    check(spec.fixed, "fixed");
    check(spec.start, "start");
    fixed_values_.emplace_back(names.size(), NAN);
    for (std::size_t c = 0; c < names.size(); ++c) {
      if (const auto it = spec.fixed.find(names[c]); it != spec.fixed.end()) {
        fixed_values_[i][c] = it->second;
        continue;
      }
      CoordinateRange range = DefaultRange(names[c], scales);
      if (const auto it = spec.ranges.find(names[c]); it != spec.ranges.end()) {
        range.low = it->second.low;
        range.high = it->second.high;
        range.log = range.log && range.low > 0.0;
      }
      if (!(range.high > range.low)) {
        throw std::invalid_argument(spec.name + "." + names[c] + ": empty range");
      }
      free_.push_back({static_cast<int>(i), static_cast<int>(c), range});
    }
    for (const bool sign : AmplitudeSigns(spec.type)) nonnegative_.push_back(sign);
    first_amplitude_.push_back(static_cast<int>(nonnegative_.size()));
  }
}

std::vector<std::string> ModelParametrisation::FreeNames() const {
  std::vector<std::string> names;
  for (const Slot& slot : free_) {
    const ComponentSpec& spec = components_[slot.component];
    names.push_back(spec.name + "." + CoordinateNames(spec.type)[slot.coordinate]);
  }
  return names;
}

std::vector<std::vector<double>> ModelParametrisation::ShapeValues(
    std::span<const double> x) const {
  std::vector<std::vector<double>> values = fixed_values_;
  for (std::size_t k = 0; k < free_.size(); ++k) {
    values[free_[k].component][free_[k].coordinate] = free_[k].range.At(x[k]);
  }
  return values;
}

void ModelParametrisation::Basis(std::span<const double> x, std::span<const CyclicTestData> tests,
                                 bool one_specimen, std::vector<Eigen::MatrixXd>* bases,
                                 int threads) const {
  const auto shapes = ShapeValues(x);
  bases->resize(tests.size());
  for (std::size_t i = 0; i < tests.size(); ++i) {
    (*bases)[i].resize(static_cast<Eigen::Index>(tests[i].displacement.size()), amplitude_count());
  }
  // The laws' runs through the tests, the costly part, are collected first and shared among the
  // threads; each writes its own column. A run carries state from test to test for one specimen,
  // so it then covers every test; else each test is a run of its own.
  struct Run {
    hysteresis::ParallelAssembly law;
    Eigen::Index column;
  };
  std::vector<Run> runs;
  const auto unit = [&](LawType type, std::vector<double> mathematical, Eigen::Index column) {
    runs.push_back({hysteresis::SingleLaw(type, std::move(mathematical)), column});
  };
  // Columns that are a function of each sample's displacement (and rate) alone.
  const auto each_test = [&](auto fill) {
    for (std::size_t i = 0; i < tests.size(); ++i) {
      const Eigen::Index n = static_cast<Eigen::Index>(tests[i].displacement.size());
      fill(tests[i], Eigen::Map<const Eigen::VectorXd>(tests[i].displacement.data(), n),
           (*bases)[i]);
    }
  };
  // Columns formed from others once every run is done.
  std::vector<std::function<void()>> afterwards;
  for (std::size_t c = 0; c < components_.size(); ++c) {
    const std::vector<double>& s = shapes[c];
    const int a = first_amplitude_[c];
    const auto clamped = [&](double limit, Eigen::Index column) {
      each_test([&](const CyclicTestData&, const auto& u, Eigen::MatrixXd& basis) {
        for (Eigen::Index k = 0; k < u.size(); ++k) basis(k, column) = Clamp(u[k], limit);
      });
    };
    switch (components_[c].type) {
      case LawType::kThm1:
        unit(LawType::kThm1, {1.0, s[0], s[1], s[2], s[2] + s[3]}, a);
        break;
      case LawType::kBhm1:
        unit(LawType::kBhm1, {1.0, s[0], s[1]}, a);
        break;
      case LawType::kThm2:
        unit(LawType::kElastoplastic, {1.0, s[0]}, a);
        clamped(s[1], a + 1);
        each_test([&](const CyclicTestData&, const auto& u, Eigen::MatrixXd& basis) {
          basis.col(a + 2) = u - basis.col(a + 1);
        });
        break;
      case LawType::kBhm2:
        unit(LawType::kElastoplastic, {1.0, s[0]}, a);
        each_test([&](const CyclicTestData&, const auto& u, Eigen::MatrixXd& basis) {
          basis.col(a + 1) = u;
        });
        break;
      case LawType::kElastoplastic:
        unit(LawType::kElastoplastic, {1.0, s[0]}, a);
        break;
      case LawType::kAsymmetricElastoplastic:
      case LawType::kBacklashElastoplastic:
        unit(components_[c].type, {1.0, s[0], s[1]}, a);
        break;
      case LawType::kDegradingBhm2:
        // phi(kappa) x [elastoplastic, k0 = 1] and phi(kappa) u; the slip, so phi, does not
        // depend on the stiffnesses, and the second column is 2 f(k1 = 1/2) - f(k1 = 0).
        unit(LawType::kDegradingBhm2, {1.0, 0.0, s[0], s[1], s[2]}, a);
        unit(LawType::kDegradingBhm2, {1.0, 0.5, s[0], s[1], s[2]}, a + 1);
        afterwards.push_back([bases, a] {
          for (Eigen::MatrixXd& basis : *bases) {
            basis.col(a + 1) = 2.0 * basis.col(a + 1) - basis.col(a);
          }
        });
        break;
      case LawType::kTrilinearElastic:
        clamped(s[0], a);
        each_test([&](const CyclicTestData&, const auto& u, Eigen::MatrixXd& basis) {
          basis.col(a + 1) = u - basis.col(a);
        });
        break;
      case LawType::kLinearSpring:
        each_test([&](const CyclicTestData&, const auto& u, Eigen::MatrixXd& basis) {
          basis.col(a) = u;
        });
        break;
      case LawType::kDashpot:
        each_test([&](const CyclicTestData& test, const auto& u, Eigen::MatrixXd& basis) {
          for (Eigen::Index k = 0; k < u.size(); ++k) {
            const double dt = k > 0 ? test.time[k] - test.time[k - 1] : 0.0;
            basis(k, a) = dt > 0.0 ? (u[k] - u[k - 1]) / dt : 0.0;
          }
        });
        break;
      case LawType::kBoucWen:
      case LawType::kFrictionPendulum:
      case LawType::kLeadRubber:
      case LawType::kHdrBearing:
      case LawType::kDoubleFrictionPendulum:
      case LawType::kTripleFrictionPendulum:
        throw std::logic_error("no basis: CoordinateNames refuses this law");
    }
  }
  const std::size_t per_run = one_specimen ? 1 : tests.size();
  ParallelFor(runs.size() * per_run, threads, [&](std::size_t task) {
    const Run& run = runs[task / per_run];
    const std::size_t first = one_specimen ? 0 : task % per_run;
    const std::size_t last = one_specimen ? tests.size() : first + 1;
    UnitLawForce(run.law, tests, first, last, one_specimen, run.column, bases);
  });
  for (const auto& step : afterwards) step();
}

std::vector<std::string> ModelParametrisation::AmplitudeNames() const {
  std::vector<std::string> names;
  for (const ComponentSpec& spec : components_) {
    for (const char* amplitude : AmplitudeKeys(spec.type)) {
      names.push_back(spec.name + "." + amplitude);
    }
  }
  return names;
}

std::vector<std::vector<double>> ModelParametrisation::Mathematical(
    std::span<const double> x, const Eigen::VectorXd& amplitudes) const {
  const auto shapes = ShapeValues(x);
  std::vector<std::vector<double>> result;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const std::vector<double>& s = shapes[i];
    const double* a = amplitudes.data() + first_amplitude_[i];
    switch (components_[i].type) {
      case LawType::kThm1:
        result.push_back({a[0], a[0] * s[0], a[0] * s[1], s[2], s[2] + s[3]});
        break;
      case LawType::kBhm1:
        result.push_back({a[0], a[0] * s[0], s[1]});
        break;
      case LawType::kThm2:
        result.push_back({a[0] + a[1], a[1], a[2], s[0], s[1]});
        break;
      case LawType::kBhm2:
        result.push_back({a[0] + a[1], a[1], s[0]});
        break;
      case LawType::kDegradingBhm2:
        result.push_back({a[0] + a[1], a[1], s[0], s[1], s[2]});
        break;
      case LawType::kElastoplastic:
        result.push_back({a[0], s[0]});
        break;
      case LawType::kAsymmetricElastoplastic:
      case LawType::kBacklashElastoplastic:
        result.push_back({a[0], s[0], s[1]});
        break;
      case LawType::kTrilinearElastic:
        result.push_back({a[0], a[1], s[0]});
        break;
      default:
        result.push_back({a[0]});
    }
  }
  return result;
}

hysteresis::ParallelAssembly ModelParametrisation::Assembly(
    std::span<const double> x, const Eigen::VectorXd& amplitudes) const {
  // An amplitude at its bound (0) would break a rule (k0 > 0): keep it a hair inside.
  Eigen::VectorXd inside = amplitudes;
  const double floor = 1e-12 * std::max(1.0, amplitudes.cwiseAbs().maxCoeff());
  for (int k = 0; k < amplitude_count(); ++k) {
    if (nonnegative_[k]) inside[k] = std::max(inside[k], floor);
  }
  const auto mathematical = Mathematical(x, inside);
  std::vector<hysteresis::Component> components;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    components.push_back(
        {components_[i].name,
         hysteresis::LawParameters::Make(
             components_[i].type, hysteresis::ParameterForm::kMathematical, mathematical[i])});
  }
  return hysteresis::ParallelAssembly(std::move(components));
}

std::vector<double> ModelParametrisation::StartPoint() const {
  std::vector<double> x;
  for (const Slot& slot : free_) {
    const ComponentSpec& spec = components_[slot.component];
    const auto it = spec.start.find(CoordinateNames(spec.type)[slot.coordinate]);
    x.push_back(it != spec.start.end() ? slot.range.Inverse(it->second) : 0.5);
  }
  return x;
}

}  // namespace isolab::identification

namespace isolab::identification {

std::vector<std::string> SimplifyComponents(const std::vector<std::string>& names,
                                            std::vector<LawType>* types,
                                            std::vector<std::vector<double>>* mathematical) {
  std::vector<std::string> notes;
  for (std::size_t c = 0; c < types->size(); ++c) {
    std::vector<double>& m = (*mathematical)[c];
    const LawType type = (*types)[c];
    const bool slider_gone =
        (type == LawType::kBhm2 || type == LawType::kThm2 || type == LawType::kDegradingBhm2) &&
        m[0] == m[1];
    if (!slider_gone) continue;
    const LawType reduced =
        type == LawType::kThm2 ? LawType::kTrilinearElastic : LawType::kLinearSpring;
    notes.push_back(fmt::format(
        "{} ({}): the fit gave its slider no stiffness (k0 - k1 = 0), so it is written as the "
        "{} that remains",
        names[c], hysteresis::LawName(type), hysteresis::LawName(reduced)));
    m = reduced == LawType::kTrilinearElastic ? std::vector<double>{m[1], m[2], m[4]}
                                              : std::vector<double>{m[1]};
    (*types)[c] = reduced;
  }
  return notes;
}

}  // namespace isolab::identification
