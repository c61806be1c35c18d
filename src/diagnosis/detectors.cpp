#include "isolab/diagnosis/detectors.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace isolab::diagnosis {
namespace {

using identification::CycleSpan;

constexpr double kRateThreshold = 0.05;         // partial R^2
constexpr double kDissipationThreshold = 0.03;  // rise of ln(energy ratio)
constexpr double kHardeningThreshold = 0.03;    // rise of ln(secant ratio)
constexpr double kDegradationThreshold = 0.02;  // extra fall of ln(energy) in an amplitude group
constexpr double kAsymmetryThreshold = 0.05;    // partial R^2 of a constant per test
constexpr double kBacklashThreshold = 0.10;     // re-stiffening after reversal / initial stiffness

// Distance-since-reversal bins of the backlash detector: this share of the largest half-cycle's
// range each, as fine as the reversal band that splits half-cycles.

// A group of half-cycles of one test at one amplitude (within kGroupWidth of the group's
// smallest): a sinusoidal test at one amplitude is one group, a seismic history gives one group
// per amplitude class. For one specimen tested in order the groups span the tests, so a loop is
// compared with the loops at its amplitude earlier in the campaign. Means over the group's
// half-cycles, which are kept in time order.
constexpr double kGroupWidth = 0.10;

struct TestSummary {
  int test = 0;
  double amplitude = 0.0, period = 0.0;
  double measured_energy = 0.0, modelled_energy = 0.0;
  double measured_secant = 0.0, modelled_secant = 0.0;
  std::vector<const CycleRecord*> cycles;
};

std::vector<TestSummary> Summaries(const Discrepancy& d) {
  std::map<int, std::vector<const CycleRecord*>> by_test;
  for (const CycleRecord& c : d.cycles) by_test[d.data->one_specimen ? 0 : c.test].push_back(&c);
  std::vector<TestSummary> result;
  for (auto& [test, records] : by_test) {
    std::stable_sort(records.begin(), records.end(),
                     [](const auto* a, const auto* b) { return a->amplitude < b->amplitude; });
    for (std::size_t first = 0; first < records.size();) {
      std::size_t last = first;
      while (last < records.size() &&
             records[last]->amplitude <= (1.0 + kGroupWidth) * records[first]->amplitude) {
        ++last;
      }
      TestSummary s;
      s.test = test;
      s.cycles.assign(records.begin() + first, records.begin() + last);
      std::sort(s.cycles.begin(), s.cycles.end(), [](const auto* a, const auto* b) {
        return a->test != b->test ? a->test < b->test : a->cycle < b->cycle;
      });
      const double n = static_cast<double>(s.cycles.size());
      for (const CycleRecord* c : s.cycles) {
        s.amplitude += c->amplitude / n;
        s.period += c->period / n;
        s.measured_energy += c->measured.energy / n;
        s.modelled_energy += c->modelled.energy / n;
        s.measured_secant += c->measured.secant / n;
        s.modelled_secant += c->modelled.secant / n;
      }
      result.push_back(std::move(s));
      first = last;
    }
  }
  return result;
}

// The largest rise of y, read per half-cycle and averaged over a group, from a smaller amplitude
// (by more than 5 %) to a larger one, less twice its standard error (from the scatter of y within
// the two groups), and the two groups where it happens. The error term keeps the scatter of
// small, noisy half-cycles from passing for a trend; a group of one half-cycle has no scatter to
// judge by and is left out.
struct Rise {
  double value = 0.0;
  const TestSummary* from = nullptr;
  const TestSummary* to = nullptr;
};
template <typename Y>
Rise LargestRise(const std::vector<TestSummary>& tests, Y y) {
  struct Mean {
    double value = NAN, variance = NAN;  // of the mean
  };
  std::vector<Mean> means;
  for (const TestSummary& s : tests) {
    double sum = 0.0, square = 0.0;
    const double n = static_cast<double>(s.cycles.size());
    for (const CycleRecord* c : s.cycles) sum += y(*c), square += y(*c) * y(*c);
    Mean m;
    if (n >= 2 && std::isfinite(sum) && std::isfinite(square)) {
      m.value = sum / n;
      m.variance = std::max(square / n - m.value * m.value, 0.0) * n / (n - 1) / n;
    }
    means.push_back(m);
  }
  Rise rise;
  for (std::size_t i = 0; i < tests.size(); ++i) {
    for (std::size_t j = 0; j < tests.size(); ++j) {
      if (!(tests[j].amplitude > 1.05 * tests[i].amplitude)) continue;
      if (!std::isfinite(means[i].value) || !std::isfinite(means[j].value)) continue;
      const double value =
          means[j].value - means[i].value - 2.0 * std::sqrt(means[i].variance + means[j].variance);
      if (!rise.to || value > rise.value) rise = {value, &tests[i], &tests[j]};
    }
  }
  rise.value = std::max(rise.value, 0.0);
  return rise;
}

double Percent(double log_ratio) { return 100.0 * (std::exp(log_ratio) - 1.0); }

Evidence RateDependence(const Discrepancy& d, const std::vector<TestSummary>& tests) {
  Evidence e;
  e.statistic = "share of the residual explained by a viscous force c v (partial R^2)";
  e.threshold = kRateThreshold;
  double cross = 0.0, velocity_norm = 0.0, residual_norm = 0.0;
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    const auto& test = d.data->tests[i];
    std::vector<std::size_t> samples;
    double norm = 0.0;
    for (const CycleSpan& span : d.data->fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        samples.push_back(k);
        norm += test.force[k] * test.force[k];
      }
    }
    const Eigen::Index n = static_cast<Eigen::Index>(samples.size());
    Eigen::MatrixXd nuisance(n, 2);
    Eigen::VectorXd r(n), v(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::size_t k = samples[j];
      const double vk = d.velocity[i][k];
      nuisance(j, 0) = vk > 0.0 ? 1.0 : (vk < 0.0 ? -1.0 : 0.0);
      nuisance(j, 1) = test.displacement[k];
      r[j] = test.force[k] - d.model_force[i][k];
      v[j] = vk;
    }
    // Take out what a hysteretic model could still absorb in this test: loop width and slope.
    const Eigen::MatrixXd normal =
        nuisance.transpose() * nuisance +
        1e-12 * Eigen::MatrixXd::Identity(2, 2) * std::max(1.0, nuisance.squaredNorm());
    const Eigen::LDLT<Eigen::MatrixXd> solver(normal);
    r -= nuisance * solver.solve(nuisance.transpose() * r);
    v -= nuisance * solver.solve(nuisance.transpose() * v);
    const double w = norm > 0.0 ? 1.0 / norm : 1.0;  // the e^2 weights
    cross += w * r.dot(v);
    velocity_norm += w * v.squaredNorm();
    residual_norm += w * r.squaredNorm();
  }
  const double c = velocity_norm > 0.0 ? cross / velocity_norm : 0.0;
  e.value = c > 0.0 && residual_norm > 0.0 ? cross * cross / (velocity_norm * residual_norm) : 0.0;
  e.finding = fmt::format(
      "a viscous force c v with c = {:.4g} (force*time/length) explains {:.1f} % of the residual "
      "left after each test's own loop-width and stiffness corrections",
      c, 100.0 * e.value);
  e.supporting.push_back({"viscous coefficient from the residual", c});

  // Equal amplitude, different frequency: the loop energy's change, measured against modelled.
  double worst = 0.0;
  const TestSummary *slow_test = nullptr, *fast_test = nullptr;
  for (const TestSummary& slow : tests) {
    for (const TestSummary& fast : tests) {
      if (std::abs(fast.amplitude / slow.amplitude - 1.0) > 0.02 ||
          !(slow.period > 1.2 * fast.period))
        continue;
      const double change = std::log(fast.measured_energy / slow.measured_energy) -
                            std::log(fast.modelled_energy / slow.modelled_energy);
      if (std::isfinite(change) && std::abs(change) > std::abs(worst)) {
        worst = change;
        slow_test = &slow;
        fast_test = &fast;
      }
    }
  }
  if (slow_test) {
    e.supporting.push_back(
        {"loop energy change with frequency, measured less modelled (%)", Percent(worst)});
    e.finding += fmt::format(
        "; at amplitude {:.4g} the loop at period {:.3g} dissipates {:+.1f} % relative to the "
        "loop at period {:.3g} beyond what the model predicts",
        fast_test->amplitude, fast_test->period, Percent(worst), slow_test->period);
  }
  return e;
}

Evidence AmplitudeDissipation(const std::vector<TestSummary>& tests) {
  Evidence e;
  e.statistic = "largest rise with amplitude of ln(measured / modelled energy per half-cycle)";
  e.threshold = kDissipationThreshold;
  const Rise rise = LargestRise(
      tests, [](const CycleRecord& c) { return std::log(c.measured.energy / c.modelled.energy); });
  e.value = rise.value;
  if (rise.to) {
    e.finding = fmt::format(
        "measured energy per half-cycle is {:+.1f} % of the model's at amplitude {:.4g} and "
        "{:+.1f} % "
        "at {:.4g}: it grows {:.1f} % faster between them, beyond twice the scatter",
        Percent(std::log(rise.from->measured_energy / rise.from->modelled_energy)),
        rise.from->amplitude,
        Percent(std::log(rise.to->measured_energy / rise.to->modelled_energy)), rise.to->amplitude,
        Percent(rise.value));
  }
  return e;
}

Evidence Hardening(const Discrepancy& d, const std::vector<TestSummary>& tests) {
  Evidence e;
  e.statistic = "largest rise with amplitude of ln(measured / modelled secant stiffness)";
  e.threshold = kHardeningThreshold;
  const Rise rise = LargestRise(
      tests, [](const CycleRecord& c) { return std::log(c.measured.secant / c.modelled.secant); });
  e.value = rise.value;
  if (rise.to) {
    e.finding = fmt::format(
        "measured secant stiffness is {:+.1f} % of the model's at amplitude {:.4g} and {:+.1f} % "
        "at {:.4g}",
        Percent(std::log(rise.from->measured_secant / rise.from->modelled_secant)),
        rise.from->amplitude,
        Percent(std::log(rise.to->measured_secant / rise.to->modelled_secant)), rise.to->amplitude);
  }
  // Where the residual lies: loading branches at large displacement of the larger tests.
  double largest = 0.0;
  for (const TestSummary& s : tests) largest = std::max(largest, s.amplitude);
  double residual_there = 0.0, residual_all = 0.0;
  long samples_there = 0, samples_all = 0;
  for (const TestSummary& s : tests) {
    if (s.amplitude < 0.5 * largest) continue;
    for (const CycleRecord* c : s.cycles) {
      const auto& test = d.data->tests[c->test];
      const CycleSpan span = test.half_cycles[c->cycle - 1];
      // Displacements about the half-cycle's centre: its amplitude is half its range.
      const double centre = 0.5 * (test.displacement[span.begin] + test.displacement[span.end - 1]);
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double u = test.displacement[k] - centre;
        const double r2 = std::pow(test.force[k] - d.model_force[c->test][k], 2);
        const bool there = std::abs(u) > 0.7 * s.amplitude && u * d.velocity[c->test][k] > 0.0;
        residual_all += r2;
        ++samples_all;
        if (there) residual_there += r2, ++samples_there;
      }
    }
  }
  if (samples_there > 0 && residual_all > 0.0) {
    const double concentration =
        (residual_there / residual_all) / (static_cast<double>(samples_there) / samples_all);
    e.supporting.push_back(
        {"residual concentration at |u| > 0.7 u_a on loading branches (1 = uniform)",
         concentration});
    e.finding += fmt::format("; the residual there is {:.2f} times its average", concentration);
  }
  return e;
}

Evidence Degradation(const Discrepancy& d, const std::vector<TestSummary>& tests) {
  Evidence e;
  e.statistic =
      "extra fall of ln(energy) from first to last half-cycle at one amplitude, measured less "
      "modelled";
  e.threshold = kDegradationThreshold;
  double energy_fall = 0.0, secant_fall = 0.0, change_to_noise = 0.0;
  int count = 0;
  for (const TestSummary& s : tests) {
    if (s.cycles.size() < 2) continue;
    const CycleRecord& first = *s.cycles.front();
    const CycleRecord& last = *s.cycles.back();
    // A loop with no area (an elastic test) has no energy to lose.
    if (!(std::min({first.measured.energy, last.measured.energy, first.modelled.energy,
                    last.modelled.energy}) > 0.0)) {
      continue;
    }
    energy_fall += std::log(last.modelled.energy / first.modelled.energy) -
                   std::log(last.measured.energy / first.measured.energy);
    secant_fall += std::log(last.modelled.secant / first.modelled.secant) -
                   std::log(last.measured.secant / first.measured.secant);
    // Residual of the last half-cycle against the first, sample by sample (over the shorter).
    const auto& test_a = d.data->tests[first.test];
    const auto& test_b = d.data->tests[last.test];
    const CycleSpan a = test_a.half_cycles[first.cycle - 1];
    const CycleSpan b = test_b.half_cycles[last.cycle - 1];
    const std::size_t length = std::min(a.end - a.begin, b.end - b.begin);
    double square = 0.0;
    for (std::size_t k = 0; k < length; ++k) {
      const double ra = test_a.force[a.begin + k] - d.model_force[first.test][a.begin + k];
      const double rb = test_b.force[b.begin + k] - d.model_force[last.test][b.begin + k];
      square += (rb - ra) * (rb - ra);
    }
    const double noise = 0.5 * (d.force_noise[first.test] + d.force_noise[last.test]);
    if (length > 0 && noise > 0.0) {
      change_to_noise += std::sqrt(square / length) / (std::sqrt(2.0) * noise);
    }
    ++count;
  }
  if (count == 0) {
    e.finding = "no test has two half-cycles at one amplitude to compare";
    return e;
  }
  e.value = energy_fall / count;
  e.finding = fmt::format(
      "from the first to the last half-cycle at one amplitude the measured energy falls {:.1f} % "
      "more than the model's and the secant stiffness {:.1f} % more (mean over {} amplitude "
      "groups); the residual changes between those half-cycles by {:.2f} times what noise "
      "explains",
      100.0 * (1.0 - std::exp(-e.value)), 100.0 * (1.0 - std::exp(-secant_fall / count)), count,
      change_to_noise / count);
  e.supporting.push_back(
      {"extra fall of ln(secant stiffness), first to last half-cycle", secant_fall / count});
  e.supporting.push_back({"residual change first to last half-cycle / noise (1 = noise only)",
                          change_to_noise / count});
  return e;
}

// A per-test constant force: what no odd-symmetric law can make. Each test's residual mean, as a
// share of its residual (the e^2 weights), summed over tests. Read over whole cycles between
// reversals, an even number of half-cycles from the first: every test starts from rest moving
// one way, so a model whose virgin loading differs from the device's leaves a residual of one
// sign there in every test, and an odd number of half-cycles leaves half a cycle's odd residual
// unpaired; neither is a strength that differs by direction.
Evidence AsymmetricStrength(const Discrepancy& d) {
  Evidence e;
  e.statistic = "share of the residual explained by a constant force per test (partial R^2)";
  e.threshold = kAsymmetryThreshold;
  double explained = 0.0, total = 0.0, offset = 0.0, weights = 0.0;
  int positive = 0, tests = 0;
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    const auto& test = d.data->tests[i];
    std::vector<double> r;
    const std::size_t pairs = test.half_cycles.size() / 2;
    if (pairs == 0) continue;
    for (const CycleSpan& span : d.data->fitted[i]) {
      const std::size_t first = std::max(span.begin, test.half_cycles.front().begin);
      const std::size_t last = std::min(span.end, test.half_cycles[2 * pairs - 1].end - 1);
      for (std::size_t k = first; k < last; ++k) r.push_back(test.force[k] - d.model_force[i][k]);
    }
    if (r.empty()) continue;
    double norm = 0.0;
    for (const CycleSpan& span : d.data->fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        norm += std::pow(d.data->tests[i].force[k], 2);
      }
    }
    const double w = norm > 0.0 ? 1.0 / norm : 1.0;
    double sum = 0.0, square = 0.0;
    for (const double v : r) sum += v, square += v * v;
    const double mean = sum / double(r.size());
    explained += w * double(r.size()) * mean * mean;
    total += w * square;
    offset += w * double(r.size()) * mean;
    weights += w * double(r.size());
    positive += mean > 0.0;
    ++tests;
  }
  e.value = total > 0.0 ? explained / total : 0.0;
  const double mean_offset = weights > 0.0 ? offset / weights : 0.0;
  // The reversal forces: mean force at the top and at the bottom reversals, measured and modelled.
  double top[2] = {0, 0}, bottom[2] = {0, 0};
  int tops = 0, bottoms = 0;
  for (const CycleRecord& c : d.cycles) {
    const auto& test = d.data->tests[c.test];
    const CycleSpan span = test.half_cycles[c.cycle - 1];
    const bool rising = test.displacement[span.end - 1] > test.displacement[span.begin];
    if (rising) {
      top[0] += c.measured.end_force, top[1] += c.modelled.end_force, ++tops;
    } else {
      bottom[0] += c.measured.end_force, bottom[1] += c.modelled.end_force, ++bottoms;
    }
  }
  e.finding = fmt::format(
      "a constant force per test explains {:.1f} % of the residual; the mean offset is {:+.4g} "
      "(force), of one sign in {} of {} tests",
      100 * e.value, mean_offset, mean_offset >= 0 ? positive : tests - positive, tests);
  e.supporting.push_back({"mean residual offset (force)", mean_offset});
  if (tops > 0 && bottoms > 0) {
    const double measured = 0.5 * (top[0] / tops + bottom[0] / bottoms);
    const double modelled = 0.5 * (top[1] / tops + bottom[1] / bottoms);
    e.finding += fmt::format(
        "; at the reversals the measured force is {:+.4g} and {:+.4g} on average (midpoint "
        "{:+.4g}), the model's {:+.4g} and {:+.4g}",
        top[0] / tops, bottom[0] / bottoms, measured, top[1] / tops, bottom[1] / bottoms);
    e.supporting.push_back(
        {"midpoint of the reversal forces, measured less modelled (force)", measured - modelled});
  }
  return e;
}

// Backlash: a tangent stiffness that drops and then rises again before the loop's centre, at a
// distance from the reversal that does not grow with the amplitude. Per half-cycle, the slope of
// force against displacement over bins of distance d since the reversal (absolute, kBin of the
// largest range each), in the first half of the half-cycle (d < its amplitude): there every law
// of the rest of the catalogue stiffens monotonically less (a hardening spring stiffens again
// only past the centre). Averaged over half-cycles, the largest rise from a nearer bin to a
// farther one, less twice its standard error, measured less modelled, over the model's stiffness
// right after the reversal.
constexpr double kBin = 0.01;

Evidence Backlash(const Discrepancy& d) {
  Evidence e;
  e.statistic =
      "re-stiffening after a reversal: rise of the tangent before the loop's centre, measured "
      "less modelled, over the stiffness after the reversal";
  e.threshold = kBacklashThreshold;
  double largest = 0.0;
  for (const CycleRecord& c : d.cycles) largest = std::max(largest, 2.0 * c.amplitude);
  const double width = kBin * largest;
  if (!(width > 0.0)) return e;
  // Per bin: sum, sum of squares and count of the half-cycles' slopes, measured and modelled.
  struct Accumulator {
    double sum = 0, square = 0, count = 0;
    void Add(double v) { sum += v, square += v * v, count += 1; }
    double Mean() const { return sum / count; }
    double Variance() const {  // of the mean
      return count > 1 ? std::max(square / count - Mean() * Mean(), 0.0) / (count - 1) : INFINITY;
    }
  };
  std::map<int, Accumulator> measured, modelled;
  for (const CycleRecord& c : d.cycles) {
    const auto& test = d.data->tests[c.test];
    const CycleSpan span = test.half_cycles[c.cycle - 1];
    const double start = test.displacement[span.begin];
    const int bins = static_cast<int>(c.amplitude / width);  // the first half only
    for (int b = 0; b < bins; ++b) {
      // Least-squares slope of force on displacement over the bin's samples.
      double su = 0, sf = 0, sg = 0, suu = 0, suf = 0, sug = 0, n = 0;
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double distance = std::abs(test.displacement[k] - start);
        if (distance < b * width || distance >= (b + 1) * width) continue;
        const double u = test.displacement[k], f = test.force[k], g = d.model_force[c.test][k];
        su += u, sf += f, sg += g, suu += u * u, suf += u * f, sug += u * g, n += 1;
      }
      const double spread = suu - su * su / std::max(n, 1.0);
      if (n < 3 || !(spread > 0.0)) continue;
      measured[b].Add((suf - su * sf / n) / spread);
      modelled[b].Add((sug - su * sg / n) / spread);
    }
  }
  // The largest rise over bins with at least two half-cycles (a scatter to judge by).
  const auto largest_rise = [](const std::map<int, Accumulator>& slopes, bool with_error, int* from,
                               int* to) {
    double rise = 0.0;
    for (const auto& [i, a] : slopes) {
      if (a.count < 2) continue;
      for (const auto& [j, b] : slopes) {
        if (j <= i || b.count < 2) continue;
        const double value =
            b.Mean() - a.Mean() - (with_error ? 2.0 * std::sqrt(a.Variance() + b.Variance()) : 0.0);
        if (value > rise) rise = value, *from = i, *to = j;
      }
    }
    return rise;
  };
  int from = -1, to = -1, model_from = -1, model_to = -1;
  const double rise = largest_rise(measured, true, &from, &to);
  const double model_rise = largest_rise(modelled, false, &model_from, &model_to);
  const auto first = modelled.find(0);
  const double initial =
      first != modelled.end() && first->second.count > 0 ? std::abs(first->second.Mean()) : 0.0;
  if (!(initial > 0.0)) {
    e.finding = "no half-cycle long enough to read the stiffness after its reversal";
    return e;
  }
  e.value = std::max(0.0, (rise - model_rise) / initial);
  e.supporting.push_back({"stiffness after the reversal, modelled (force/length)", initial});
  if (from >= 0) {
    e.finding = fmt::format(
        "after reversals the measured tangent stiffness falls to {:.4g} at {:.3g}-{:.3g} from the "
        "reversal and rises again to {:.4g} at {:.3g}-{:.3g} (length), a rise of {:.1f} % of the "
        "stiffness after the reversal ({:.4g}) beyond twice its scatter; the model's rises by "
        "{:.4g}",
        measured[from].Mean(), from * width, (from + 1) * width, measured[to].Mean(), to * width,
        (to + 1) * width, 100 * rise / initial, initial, model_rise);
    e.supporting.push_back(
        {"distance from the reversal where it stiffens again (length)", to * width});
    // The contact re-engages at u_y + gap from the reversal: most of that distance is the gap.
    e.start = {{"gap", 0.8 * to * width}, {"uy", std::max(0.2 * to * width, 0.5 * width)}};
  } else {
    e.finding = fmt::format(
        "after reversals the measured tangent stiffness does not rise again before the loop's "
        "centre (bins of {:.3g} from the reversal)",
        width);
  }
  return e;
}

}  // namespace

Evidence Detect(Effect effect, const Discrepancy& discrepancy) {
  const std::vector<TestSummary> tests = Summaries(discrepancy);
  Evidence evidence;
  switch (effect) {
    case Effect::kRateDependence:
      evidence = RateDependence(discrepancy, tests);
      break;
    case Effect::kAmplitudeDependentDissipation:
      evidence = AmplitudeDissipation(tests);
      break;
    case Effect::kLargeAmplitudeHardening:
      evidence = Hardening(discrepancy, tests);
      break;
    case Effect::kCyclicDegradation:
      evidence = Degradation(discrepancy, tests);
      break;
    case Effect::kAsymmetricStrength:
      evidence = AsymmetricStrength(discrepancy);
      break;
    case Effect::kBacklash:
      evidence = Backlash(discrepancy);
      break;
  }
  evidence.effect = effect;
  return evidence;
}

}  // namespace isolab::diagnosis
