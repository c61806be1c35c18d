// The floor of a Newmark-Newton step (the "roofline" of this problem): the same arithmetic as
// RunNewmark for one shear building on one isolator of components of one law (THM1's series
// slider, BHM2's parallel one), written by hand for that shape. Same predictor, same laws (their
// kernels called directly), same residual, tangent, convergence tests (force scale, displacement,
// round-off floor), factors kept while the tangent repeats, energies and recorded outputs;
// what is gone is what a general code pays for generality: the law variant and assembly loop, the
// sparse pattern with its index arrays, KLU's general sparse LU (a dense LDL^T of the small
// symmetric tangent here, or KLU itself with the KluDense solver) and dynamically sized vectors.
// Its per-step time is the bound integrators_benchmark compares RunNewmark with; its results must
// equal RunNewmark's.
#pragma once

#include <klu.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "isolab/hysteresis/elastic_spring.h"
#include "isolab/hysteresis/series_slider.h"
#include "isolab/integrators/excitation.h"

namespace isolab::benchmarks {

// LDL^T of the symmetric tangent and the solve K x = b (b overwritten by x): the floor's own
// factorisation, for fixed-size dense matrices.
template <int kDofs>
struct DenseLdlt {
  using Vector = std::array<double, kDofs>;
  using Matrix = std::array<Vector, kDofs>;

  void Factor(const Matrix& matrix) {
    k_ = matrix;
    for (int j = 0; j < kDofs; ++j) {
      for (int p = 0; p < j; ++p) k_[j][j] -= k_[j][p] * k_[j][p] * k_[p][p];
      for (int i = j + 1; i < kDofs; ++i) {
        for (int p = 0; p < j; ++p) k_[i][j] -= k_[i][p] * k_[j][p] * k_[p][p];
        k_[i][j] /= k_[j][j];
      }
    }
  }

  void Solve(Vector* b) const {
    Vector& x = *b;
    for (int i = 1; i < kDofs; ++i) {
      for (int p = 0; p < i; ++p) x[i] -= k_[i][p] * x[p];
    }
    for (int i = 0; i < kDofs; ++i) x[i] /= k_[i][i];
    for (int i = kDofs - 2; i >= 0; --i) {
      for (int p = i + 1; p < kDofs; ++p) x[i] -= k_[p][i] * x[p];
    }
  }

 private:
  Matrix k_{};
};

// KLU on every entry of the matrix, used as RunNewmark uses it (src/integrators/klu_solver.cpp):
// analysed once, refactored with the pivots of the first factorisation while its reciprocal
// condition number stays above 1e-12, then solved. With it the floor differs from RunNewmark
// only in what generality costs, not in the sparse LU the design prescribes.
template <int kDofs>
class KluDense {
 public:
  using Vector = std::array<double, kDofs>;
  using Matrix = std::array<Vector, kDofs>;

  KluDense() {
    klu_defaults(&common_);
    for (int j = 0; j <= kDofs; ++j) columns_[j] = j * kDofs;
    for (int k = 0; k < kDofs * kDofs; ++k) rows_[k] = k % kDofs;
    symbolic_ = klu_analyze(kDofs, columns_.data(), rows_.data(), &common_);
  }
  ~KluDense() {
    if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
    klu_free_symbolic(&symbolic_, &common_);
  }
  KluDense(const KluDense&) = delete;
  KluDense& operator=(const KluDense&) = delete;

  void Factor(const Matrix& matrix) {
    for (int j = 0; j < kDofs; ++j) {
      for (int i = 0; i < kDofs; ++i) values_[j * kDofs + i] = matrix[i][j];
    }
    if (numeric_ == nullptr ||
        !(klu_refactor(columns_.data(), rows_.data(), values_.data(), symbolic_, numeric_,
                       &common_) &&
          klu_rcond(symbolic_, numeric_, &common_) && common_.rcond > 1e-12)) {
      if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
      numeric_ = klu_factor(columns_.data(), rows_.data(), values_.data(), symbolic_, &common_);
    }
  }

  void Solve(Vector* b) { klu_solve(symbolic_, numeric_, kDofs, 1, b->data(), &common_); }

 private:
  klu_common common_;
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  std::array<int, kDofs + 1> columns_;
  std::array<int, kDofs * kDofs> rows_;
  std::array<double, kDofs * kDofs> values_;
};

template <int kStories, int kComponents, template <int> class Solver = DenseLdlt,
          class Isolator = hysteresis::SeriesSlider>
class NewmarkFloor {
 public:
  static constexpr int kDofs = kStories + 1;  // the base, then the floors bottom to top
  using Vector = std::array<double, kDofs>;
  using Matrix = std::array<Vector, kDofs>;

  struct Output {  // one row per step, as ResponseHistory records them
    std::vector<double> time, displacement, velocity, acceleration, absolute_acceleration,
        connection_force, law_force, energies;
  };

  // `damping` is the dense viscous damping matrix; the stories are linear springs.
  NewmarkFloor(Vector mass, Matrix damping, std::array<Isolator, kComponents> isolator,
               std::array<hysteresis::ElasticSpring, kStories> stories)
      : mass_(mass), damping_(damping), isolator_(isolator), stories_(stories) {}

  // Factorisations of the last Run (the repeated tangents left out, as RunSummary counts them).
  long factorisations() const { return factorisations_; }

  // Average acceleration from rest, full Newton; returns the linear solves made.
  long Run(const integrators::SampledHistory& ground, double h, int steps, Output* out) {
    Reset(ground, steps, out);
    long solves = 0;
    const double beta = 0.25, gamma = 0.5, c0 = 1.0 / (beta * h * h), c1 = gamma / (beta * h);
    for (int step = 1; step <= steps; ++step) {
      const double ag = ground.At(step * h);
      for (int i = 0; i < kDofs; ++i) load_trial_[i] = -ag * mass_[i];
      Vector u{}, v{}, a{};
      for (int i = 0; i < kDofs; ++i) u[i] = u_[i] + h * v_[i] + (0.5 * h * h) * a_[i];
      bool displacement_converged = false;
      for (int iteration = 0;; ++iteration) {
        for (int i = 0; i < kDofs; ++i) {
          v[i] = c1 * (u[i] - u_[i]) + (1.0 - gamma / beta) * v_[i] +
                 (h * (1.0 - gamma / (2.0 * beta))) * a_[i];
          a[i] =
              c0 * (u[i] - u_[i]) - (1.0 / (beta * h)) * v_[i] - (1.0 / (2.0 * beta) - 1.0) * a_[i];
        }
        Vector force = Evaluate(u, v);
        Matrix tangent = Tangent(c0, c1);
        double residual = 0.0, scale = 0.0;
        for (int i = 0; i < kDofs; ++i) {
          residual_[i] = load_trial_[i] - mass_[i] * a[i] - force[i];
          residual = std::max(residual, std::abs(residual_[i]));
          scale = std::max(
              {scale, std::abs(load_trial_[i]), std::abs(force[i]), std::abs(mass_[i] * a[i])});
        }
        if (residual <= 1e-10 * scale || displacement_converged ||
            (iteration > 0 && residual <= 2.0 * RoundoffResidual(tangent, u))) {
          Commit(u, v, a, step * h, step, ground, out);
          break;
        }
        // Factorised again only when the tangent's values changed, bit for bit, as
        // RunNewmark's TangentSolver does.
        if (factorisations_ == 0 ||
            std::memcmp(&tangent, &factored_tangent_, sizeof(Matrix)) != 0) {
          solver_.Factor(tangent);
          factored_tangent_ = tangent;
          ++factorisations_;
        }
        solver_.Solve(&residual_);
        ++solves;
        double correction = 0.0, size = 0.0;
        for (int i = 0; i < kDofs; ++i) {
          u[i] += residual_[i];
          correction = std::max(correction, std::abs(residual_[i]));
          size = std::max(size, std::abs(u[i]));
        }
        displacement_converged = correction <= 1e-12 * std::max(size, 1e-300);
      }
    }
    return solves;
  }

 private:
  static constexpr int kLaws = kComponents + kStories;

  void Reset(const integrators::SampledHistory& ground, int steps, Output* out) {
    u_ = v_ = viscous_ = Vector{};
    for (int i = 0; i < kDofs; ++i) load_[i] = -ground.At(0.0) * mass_[i];
    for (int i = 0; i < kDofs; ++i) a_[i] = load_[i] / mass_[i];
    committed_ = trial_ = std::array<hysteresis::LawState, kLaws>{};
    factorisations_ = 0;
    input_ = viscous_energy_ = 0.0;
    const std::size_t rows = steps + 1;
    out->time.assign(rows, 0.0);
    for (auto* x :
         {&out->displacement, &out->velocity, &out->acceleration, &out->absolute_acceleration}) {
      x->assign(rows * kDofs, 0.0);
    }
    out->connection_force.assign(rows * (kStories + 1), 0.0);
    out->law_force.assign(rows * kLaws, 0.0);
    out->energies.assign(rows * 5, 0.0);
  }

  // Resisting force C v + connection forces; the laws' trial states and tangents.
  Vector Evaluate(const Vector& u, const Vector& v) {
    Vector force{};
    for (int i = 0; i < kDofs; ++i) {
      for (int j = 0; j < kDofs; ++j) force[i] += damping_[i][j] * v[j];
    }
    isolation_stiffness_ = 0.0;
    double isolation_force = 0.0;
    for (int c = 0; c < kComponents; ++c) {
      isolator_[c].Update(committed_[c], {u[0], v[0]}, &trial_[c], &responses_[c]);
      isolation_force += responses_[c].force;
      isolation_stiffness_ += responses_[c].stiffness;
    }
    connection_force_[0] = isolation_force;
    force[0] += isolation_force;
    for (int s = 0; s < kStories; ++s) {
      const int law = kComponents + s;
      stories_[s].Update(committed_[law], {u[s + 1] - u[s], v[s + 1] - v[s]}, &trial_[law],
                         &responses_[law]);
      connection_force_[s + 1] = responses_[law].force;
      force[s + 1] += responses_[law].force;
      force[s] -= responses_[law].force;
    }
    return force;
  }

  // K_eff = K_t + c1 C + c0 M, dense.
  Matrix Tangent(double c0, double c1) const {
    Matrix k{};
    for (int i = 0; i < kDofs; ++i) {
      for (int j = 0; j < kDofs; ++j) k[i][j] = c1 * damping_[i][j];
      k[i][i] += c0 * mass_[i];
    }
    k[0][0] += isolation_stiffness_;
    for (int s = 0; s < kStories; ++s) {
      const double ks = responses_[kComponents + s].stiffness;
      k[s][s] += ks;
      k[s + 1][s + 1] += ks;
      k[s][s + 1] -= ks;
      k[s + 1][s] -= ks;
    }
    return k;
  }

  double RoundoffResidual(const Matrix& k, const Vector& u) const {
    double largest = 0.0;
    for (int i = 0; i < kDofs; ++i) {
      double row = 0.0;
      for (int j = 0; j < kDofs; ++j) row += std::abs(k[i][j]) * std::abs(u[j]);
      largest = std::max(largest, row);
    }
    return std::numeric_limits<double>::epsilon() * largest;
  }

  void Commit(const Vector& u, const Vector& v, const Vector& a, double t, int row,
              const integrators::SampledHistory& ground, Output* out) {
    Vector viscous{};
    for (int i = 0; i < kDofs; ++i) {
      for (int j = 0; j < kDofs; ++j) viscous[i] += damping_[i][j] * v[j];
    }
    for (int i = 0; i < kDofs; ++i) {
      const double du = u[i] - u_[i];
      input_ += 0.5 * (load_[i] + load_trial_[i]) * du;
      viscous_energy_ += 0.5 * (viscous_[i] + viscous[i]) * du;
    }
    std::swap(committed_, trial_);
    u_ = u;
    v_ = v;
    a_ = a;
    load_ = load_trial_;
    viscous_ = viscous;
    double kinetic = 0.0, elastic = 0.0, hysteretic = 0.0;
    for (int i = 0; i < kDofs; ++i) kinetic += 0.5 * v_[i] * mass_[i] * v_[i];
    for (int c = 0; c < kComponents; ++c) {
      elastic += isolator_[c].StoredEnergy(committed_[c]);
      hysteretic += committed_[c].dissipated;
    }
    for (int s = 0; s < kStories; ++s)
      elastic += stories_[s].StoredEnergy(committed_[kComponents + s]);

    const double ag = ground.At(t);
    out->time[row] = t;
    for (int i = 0; i < kDofs; ++i) {
      out->displacement[row * kDofs + i] = u_[i];
      out->velocity[row * kDofs + i] = v_[i];
      out->acceleration[row * kDofs + i] = a_[i];
      out->absolute_acceleration[row * kDofs + i] = a_[i] + ag;
    }
    for (int k = 0; k <= kStories; ++k) {
      out->connection_force[row * (kStories + 1) + k] = connection_force_[k];
    }
    for (int l = 0; l < kLaws; ++l) out->law_force[row * kLaws + l] = responses_[l].force;
    const double energies[] = {input_, kinetic, viscous_energy_, elastic, hysteretic};
    std::copy(energies, energies + 5, out->energies.begin() + row * 5);
  }

  Solver<kDofs> solver_;
  Matrix factored_tangent_{};  // the tangent last factorised, once factorisations_ > 0
  long factorisations_ = 0;
  Vector mass_;
  Matrix damping_;
  std::array<Isolator, kComponents> isolator_;
  std::array<hysteresis::ElasticSpring, kStories> stories_;
  std::array<hysteresis::LawState, kLaws> committed_{}, trial_{};
  std::array<hysteresis::LawResponse, kLaws> responses_{};
  std::array<double, kStories + 1> connection_force_{};
  double isolation_stiffness_ = 0.0;
  Vector u_{}, v_{}, a_{}, load_{}, load_trial_{}, viscous_{}, residual_{};
  double input_ = 0.0, viscous_energy_ = 0.0;
};

}  // namespace isolab::benchmarks
