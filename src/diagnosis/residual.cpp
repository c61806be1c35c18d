#include "isolab/diagnosis/residual.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "isolab/core/errors.h"

namespace isolab::diagnosis {
namespace {

using identification::CycleSpan;

constexpr int kBands = 4;   // |u| / u_a: 0-25, 25-50, 50-75, 75-100 %
constexpr int kPhases = 5;  // time since reversal, share of the half-cycle; the last: outside
constexpr double kPhaseEdges[] = {0.10, 0.25, 0.50};
const char* const kBandNames[kBands] = {"0-25 %", "25-50 %", "50-75 %", "75-100 %"};
const char* const kPhaseNames[kPhases] = {"0-10 %", "10-25 %", "25-50 %", "50-100 %",
                                          "outside half-cycles"};
const char* const kDirectionNames[2] = {"moving + (v > 0)", "moving - (v < 0)"};
const char* const kBranchNames[2] = {"loading (u v > 0)", "unloading"};

// Where a sample lies in the state of motion.
struct State {
  int direction = 0;  // 0: v > 0, 1: v <= 0
  int band = 0;
  int phase = 0;
  int branch = 0;  // 0: loading, 1: unloading
};

struct Cells {
  std::vector<double> sum, square;
  std::vector<long> count;
  explicit Cells(std::size_t n) : sum(n, 0.0), square(n, 0.0), count(n, 0) {}
  void Add(std::size_t cell, double r) { sum[cell] += r, square[cell] += r * r, ++count[cell]; }
};

ResidualTable Table(std::string title, std::vector<std::string> rows,
                    std::vector<std::string> columns, const Cells& cells) {
  ResidualTable table{std::move(title), std::move(rows), std::move(columns), {}, {}, {}};
  const std::size_t width = table.columns.size();
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    table.rms.emplace_back(), table.mean.emplace_back(), table.samples.emplace_back();
    for (std::size_t c = 0; c < width; ++c) {
      const std::size_t cell = r * width + c;
      const long n = cells.count[cell];
      table.samples.back().push_back(n);
      table.rms.back().push_back(n > 0 ? std::sqrt(cells.square[cell] / double(n)) : 0.0);
      table.mean.back().push_back(n > 0 ? cells.sum[cell] / double(n) : 0.0);
    }
  }
  return table;
}

// Each sample's half-cycle (-1 outside every one) and its phase: its share of the half-cycle's
// duration since the reversal that opened it, in kPhaseEdges' bins.
void HalfCyclePhases(const identification::CyclicTestData& test, std::vector<int>& phase,
                     std::vector<int>& half_index) {
  phase.assign(test.time.size(), kPhases - 1);
  half_index.assign(test.time.size(), -1);
  for (std::size_t h = 0; h < test.half_cycles.size(); ++h) {
    const CycleSpan& half = test.half_cycles[h];
    const double start = test.time[half.begin], length = test.time[half.end - 1] - start;
    for (std::size_t k = half.begin; k + 1 < half.end; ++k) {
      const double share = length > 0.0 ? (test.time[k] - start) / length : 0.0;
      int p = 0;
      while (p < 3 && share >= kPhaseEdges[p]) ++p;
      phase[k] = p;
      half_index[k] = static_cast<int>(h);
    }
  }
}

// The share of the residual the state explains, cross-validated: sum over cells of n_c times the
// product of the cell's means in the two sets of alternate cycles. Each mean is the cell's true
// mean plus its own error, and the two sets' errors are independent, so the product is unbiased
// for the squared true mean: near zero for a residual the state does not drive, however
// correlated. (The plain sum of squared means would add cells / n_eff of chance.) Also the share
// chance alone would give: the occupied cells over the effective samples.
void SetStateShare(const Cells& state, const Cells (&alternate)[2], double total_square,
                   double effective, ResidualVerdict& verdict) {
  double explained = 0.0;
  std::size_t occupied = 0;
  for (std::size_t c = 0; c < state.count.size(); ++c) {
    if (state.count[c] == 0) continue;
    ++occupied;
    if (alternate[0].count[c] == 0 || alternate[1].count[c] == 0) continue;
    explained += double(state.count[c]) * (alternate[0].sum[c] / double(alternate[0].count[c])) *
                 (alternate[1].sum[c] / double(alternate[1].count[c]));
  }
  verdict.state_share = total_square > 0.0 ? std::max(0.0, explained) / total_square : 0.0;
  verdict.state_share_noise = std::min(1.0, double(occupied) / std::max(effective, 1.0));
}

// The verdict's kind and headline: noise, a residual the state of motion drives, or one it does
// not.
void SetHeadline(const VerdictOptions& options, ResidualVerdict& verdict) {
  const double e2 = verdict.e2, noise_floor = verdict.floor;
  const bool above = !(verdict.ratio <= options.noise_margin);
  const bool follows_state = verdict.state_share >= options.state_share;
  if (!above) {
    verdict.kind = ResidualVerdict::Kind::kNoise;
    verdict.headline = fmt::format(
        "the residual is noise: e^2 = {:.4g} % is within {:g} x the noise floor ({:.4g} %)",
        100 * e2, options.noise_margin, 100 * noise_floor);
  } else if (follows_state) {
    verdict.kind = ResidualVerdict::Kind::kStructured;
    verdict.headline = fmt::format(
        "a structured residual remains: e^2 = {:.4g} % is {:.3g} times the noise floor "
        "({:.4g} %), and it follows the state of motion (direction, |u| and time since reversal "
        "explain {:.0f} % of it, alike in alternate cycles)",
        100 * e2, verdict.ratio, 100 * noise_floor, 100 * verdict.state_share);
  } else {
    verdict.kind = ResidualVerdict::Kind::kUnexplained;
    verdict.headline = fmt::format(
        "a structured residual remains: e^2 = {:.4g} % is {:.3g} times the noise floor "
        "({:.4g} %), but the state of motion explains only {:.1f} % of it: a disturbance the "
        "motion does not drive, or noise inside the device's own band that the floor cannot see "
        "(correlation time {:.3g} s)",
        100 * e2, verdict.ratio, 100 * noise_floor, 100 * verdict.state_share,
        verdict.correlation_time);
  }
}

// The cells that stand out: the largest mean residuals of direction x time since reversal and
// direction x |u|, as many as say something (at least 2 noise units of mean).
std::vector<std::string> WhereItStandsOut(const ResidualVerdict& verdict, long samples) {
  std::vector<std::string> where;
  struct Spot {
    double mean;
    std::string text;
  };
  std::vector<Spot> spots;
  for (const std::size_t t : {std::size_t{1}, std::size_t{0}}) {
    const ResidualTable& table = verdict.tables[t];
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      for (std::size_t c = 0; c < table.columns.size(); ++c) {
        // Cells of at least 1 % of the samples, so a stretch of a few samples does not lead.
        if (table.samples[r][c] < samples / 100 || std::abs(table.mean[r][c]) < 2.0) continue;
        spots.push_back(
            {table.mean[r][c],
             fmt::format("{}, {} {}: mean residual {:+.1f} x noise (RMS {:.1f}) over {} samples",
                         table.rows[r], t == 1 ? "time since reversal" : "|u| / u_a",
                         table.columns[c], table.mean[r][c], table.rms[r][c],
                         table.samples[r][c])});
      }
    }
  }
  std::stable_sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) {
    return std::abs(a.mean) > std::abs(b.mean);
  });
  for (std::size_t k = 0; k < spots.size() && k < 4; ++k) where.push_back(spots[k].text);
  return where;
}

}  // namespace

void VerdictOptions::Validate() const {
  if (!(noise_margin >= 1.0)) {
    throw InvalidParameter({"noise_margin", noise_margin, "must be >= 1"});
  }
  if (!(state_share > 0.0 && state_share < 1.0)) {
    throw InvalidParameter({"state_share", state_share, "must be in (0, 1)"});
  }
}

std::string_view VerdictName(ResidualVerdict::Kind kind) {
  switch (kind) {
    case ResidualVerdict::Kind::kNoise:
      return "noise";
    case ResidualVerdict::Kind::kStructured:
      return "structured";
    case ResidualVerdict::Kind::kUnexplained:
      return "unexplained";
  }
  return "?";
}

ResidualVerdict JudgeResidual(const Discrepancy& d, double e2, double noise_floor,
                              const VerdictOptions& options) {
  options.Validate();
  ResidualVerdict verdict;
  verdict.e2 = e2;
  verdict.floor = noise_floor;
  verdict.ratio = noise_floor > 0.0 ? e2 / noise_floor : INFINITY;

  const auto& data = *d.data;
  constexpr std::size_t kStateCells = 2 * kBands * kPhases;
  // The state cells of each test twice, from alternate whole cycles (half-cycles 1-2, 5-6, ...
  // and 3-4, 7-8, ...): a pattern the state drives shows in both, a disturbance in neither in the
  // same way. Per test, since what a model misses may differ from test to test (a force in phase
  // with the acceleration is a stiffness that changes with the test's frequency).
  const std::size_t test_cells = kStateCells * data.tests.size();
  Cells state(test_cells), alternate[2] = {Cells(test_cells), Cells(test_cells)},
                           direction_band(2 * kBands), direction_phase(2 * kPhases),
                           branch_band(2 * kBands);
  const std::vector<double> times = CorrelationTimes(d);
  double seconds = 0.0, total_square = 0.0;
  long samples = 0;
  double effective = 0.0;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    const double noise = d.force_noise[i] > 0.0 ? d.force_noise[i] : 1.0;
    double amplitude = 0.0;
    long test_samples = 0;
    for (const CycleSpan& span : data.fitted[i]) {
      amplitude = std::max(amplitude, identification::SpanAmplitude(test.displacement, span));
      test_samples += long(span.end - span.begin);
    }
    if (!(amplitude > 0.0)) amplitude = 1.0;
    const double dt = test.time.size() > 1
                          ? (test.time.back() - test.time.front()) / double(test.time.size() - 1)
                          : 0.0;
    seconds += double(test_samples) * times[i] * dt;
    samples += test_samples;
    effective += double(test_samples) / times[i];
    std::vector<int> phase, half_index;
    HalfCyclePhases(test, phase, half_index);
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double r = (test.force[k] - d.model_force[i][k]) / noise;
        const double u = test.displacement[k], v = d.velocity[i][k];
        State s;
        s.direction = v > 0.0 ? 0 : 1;
        s.band = std::min(kBands - 1, static_cast<int>(kBands * std::abs(u) / amplitude));
        s.phase = phase[k];
        s.branch = u * v > 0.0 ? 0 : 1;
        const std::size_t cell =
            i * kStateCells + (s.direction * kBands + s.band) * kPhases + s.phase;
        state.Add(cell, r);
        // Pairs of half-cycles alternate between the sets; the stretch before the first
        // reversal counts as pair -1, the one after the last as the pair after it.
        const int h = half_index[k] >= 0 ? half_index[k]
                      : k < test.half_cycles.front().begin
                          ? -2
                          : static_cast<int>(test.half_cycles.size());
        alternate[((h >= 0 ? h / 2 : -1) % 2 + 2) % 2].Add(cell, r);
        direction_band.Add(s.direction * kBands + s.band, r);
        direction_phase.Add(s.direction * kPhases + s.phase, r);
        branch_band.Add(s.branch * kBands + s.band, r);
        total_square += r * r;
      }
    }
  }
  verdict.correlation_time = samples > 0 ? seconds / double(samples) : 0.0;
  verdict.whiteness = samples > 0 ? effective / double(samples) : 1.0;
  SetStateShare(state, alternate, total_square, effective, verdict);

  const std::vector<std::string> directions(std::begin(kDirectionNames), std::end(kDirectionNames));
  const std::vector<std::string> bands(std::begin(kBandNames), std::end(kBandNames));
  verdict.tables.push_back(
      Table("by direction of motion and |u| / u_a", directions, bands, direction_band));
  verdict.tables.push_back(
      Table("by direction of motion and time since the last reversal (share of the half-cycle)",
            directions, std::vector<std::string>(std::begin(kPhaseNames), std::end(kPhaseNames)),
            direction_phase));
  verdict.tables.push_back(
      Table("by branch and |u| / u_a",
            std::vector<std::string>(std::begin(kBranchNames), std::end(kBranchNames)), bands,
            branch_band));

  SetHeadline(options, verdict);
  if (verdict.Structured()) verdict.where = WhereItStandsOut(verdict, samples);
  return verdict;
}

}  // namespace isolab::diagnosis
