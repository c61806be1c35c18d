// Buildings isolab generates with known, hidden parameters, for the building-level fit and
// diagnosis tests: a three-story building on an isolation layer given as YAML
// (analysis/three_story_building.h), a table motion over its bands, its response at every level as
// measurements, and white noise on a channel.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "analysis/three_story_building.h"
#include "isolab/building/building_fit.h"
#include "isolab/model/model_file.h"

namespace isolab::building::synthetic {

using testing::BuildingText;
using testing::kBilinear;
using testing::Model;

// A table motion: decaying sines over the isolated and the superstructure's bands (mm/s^2).
inline BuildingMotion TableMotion(const std::string& name, double amplitude, double seconds,
                                  double phase = 0.0) {
  BuildingMotion motion;
  motion.name = name;
  const double dt = 0.01;
  const std::size_t n = std::size_t(seconds / dt) + 1;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = double(k) * dt;
    const double envelope = t < 2.0 ? t / 2.0 : std::exp(-(t - 2.0) / 6.0);
    motion.measured.time.push_back(t);
    motion.measured.table_acceleration.push_back(amplitude * envelope *
                                                 (std::sin(2 * M_PI * 0.45 * t + phase) +
                                                  0.6 * std::sin(2 * M_PI * 1.3 * t) +
                                                  0.3 * std::sin(2 * M_PI * 3.1 * t + 2 * phase)));
  }
  return motion;
}

// The model's response at every level, as measurements (noise added by the caller).
inline void Measure(const model::ModelFile& model, std::vector<BuildingMotion>* motions,
                    bool sequential = false) {
  std::vector<BuildingChannel> channels;
  const int levels = 4;
  for (int l = 1; l <= levels; ++l) channels.push_back({BuildingChannel::Kind::kDisplacement, l});
  for (int l = 1; l <= levels; ++l) channels.push_back({BuildingChannel::Kind::kAcceleration, l});
  const ChannelHistories h = SimulateChannels(model, *motions, channels, sequential, 0.0);
  for (std::size_t m = 0; m < motions->size(); ++m) {
    BuildingMeasurements& measured = (*motions)[m].measured;
    measured.displacement.assign(h[m].begin(), h[m].begin() + levels);
    measured.acceleration.assign(h[m].begin() + levels, h[m].end());
  }
}

inline double RootMeanSquare(const Signal& x) {
  double sum = 0.0;
  for (const double v : x) sum += v * v;
  return std::sqrt(sum / double(x.size()));
}

inline void AddNoise(Signal* x, double share, std::mt19937* random) {
  std::normal_distribution<double> noise(0.0, share * RootMeanSquare(*x));
  for (double& v : *x) v += noise(*random);
}

inline identification::FitOptions Options(long budget) {
  identification::FitOptions options;
  options.budget = budget;
  options.threads = 2;
  return options;
}

}  // namespace isolab::building::synthetic
