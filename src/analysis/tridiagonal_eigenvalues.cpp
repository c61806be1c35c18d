#include "tridiagonal_eigenvalues.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>

namespace isolab::analysis {
namespace {

// One step of a rational QL sweep on rows i and i + 1: from their entries (e2 = e2[i],
// d = d[i]) and the sweep's carried g, h, s, the entries it leaves below (e2[i + 1], d[i + 1]).
// Value is double for one matrix, or a vector of two doubles for two matrices at once: the same
// operations on each lane, so each matrix's results are bit for bit those it gets alone.
template <typename Value>
inline void SweepStep(Value e2, Value d, Value zero_pivot, Value& g, Value& h, Value& s,
                      Value& e2_below, Value& d_below) {
  const Value p = g * h;
  const Value r = p + e2;
  e2_below = s * r;
  s = e2 / r;
  d_below = h + s * (h + d);
  g = d - e2 / g;
  g = g == 0.0 ? zero_pivot : g;
  h = g * p / r;
}

using Pair = double __attribute__((vector_size(16)));

// One matrix's rational QL iteration, stopped at the start of each sweep's steps so that two
// matrices' steps can run interleaved. The algorithm and its order of operations are TQLRAT's.
class RationalQl {
 public:
  // The state a sweep carries from step to step.
  struct Sweep {
    std::size_t i;  // the next step is on rows i - 1 and i
    double g, h, s;
  };

  RationalQl(std::vector<double> diagonal, const std::vector<double>& off_diagonal)
      : d_(std::move(diagonal)), n_(d_.size()) {
    // e2[i]: the squared coupling of rows i and i + 1; the last is zero, so the search for a
    // negligible coupling always ends.
    e2_.assign(n_, 0.0);
    for (std::size_t i = 0; i + 1 < n_; ++i) e2_[i] = off_diagonal[i] * off_diagonal[i];
    NextEigenvalue();
  }

  bool done() const { return l_ >= n_; }
  // The steps left in the current sweep (none when done).
  std::size_t steps_left() const { return done() ? 0 : sweep_.i - l_; }
  std::vector<double> eigenvalues() && { return std::move(d_); }

  // `count` steps of this sweep and of `other`'s, as one vector's two lanes.
  void StepWith(RationalQl& other, std::size_t count) {
    Sweep& a = sweep_;
    Sweep& b = other.sweep_;
    double *ad = d_.data(), *ae2 = e2_.data(), *bd = other.d_.data(), *be2 = other.e2_.data();
    const Pair zero_pivot = {b_, other.b_};
    Pair g = {a.g, b.g}, h = {a.h, b.h}, s = {a.s, b.s};
    std::size_t ai = a.i, bi = b.i;
    for (std::size_t step = 0; step < count; ++step) {
      --ai;
      --bi;
      const Pair e2 = {ae2[ai], be2[bi]}, d = {ad[ai], bd[bi]};
      Pair e2_below, d_below;
      SweepStep(e2, d, zero_pivot, g, h, s, e2_below, d_below);
      ae2[ai + 1] = e2_below[0];
      be2[bi + 1] = e2_below[1];
      ad[ai + 1] = d_below[0];
      bd[bi + 1] = d_below[1];
    }
    a = {ai, g[0], h[0], s[0]};
    b = {bi, g[1], h[1], s[1]};
  }

  // After a sweep's last step: the eigenvalue at l has converged, or another sweep starts.
  void EndSweep() {
    const double h = sweep_.h;
    e2_[l_] = sweep_.s * sweep_.g;
    d_[l_] = h;
    // Converged when the coupling is negligible (guarded against underflow).
    if (h == 0.0 || std::abs(e2_[l_]) <= std::abs(c_ / h)) return Converged();
    e2_[l_] *= h;
    if (e2_[l_] == 0.0) return Converged();
    StartSweep();
  }

  // All that is left, alone.
  void Finish() {
    for (; !done(); EndSweep()) {
      double g = sweep_.g, h = sweep_.h, s = sweep_.s;
      for (std::size_t i = sweep_.i; i-- > l_;) {
        SweepStep(e2_[i], d_[i], b_, g, h, s, e2_[i + 1], d_[i + 1]);
      }
      sweep_ = {l_, g, h, s};
    }
  }

 private:
  // Finds the next eigenvalue not yet split off and starts its first sweep; inserts those that
  // are split off already.
  void NextEigenvalue() {
    for (; l_ < n_; Insert()) {
      const double h = std::abs(d_[l_]) + std::sqrt(e2_[l_]);
      if (t_ <= h) {
        t_ = h;
        b_ = std::numeric_limits<double>::epsilon() * t_;
        c_ = b_ * b_;
      }
      m_ = l_;
      while (e2_[m_] > c_) ++m_;
      if (m_ != l_) {
        iteration_ = 0;
        return StartSweep();
      }
    }
  }

  void StartSweep() {
    if (iteration_++ == 30) {
      throw std::runtime_error("the tridiagonal eigenvalue iteration did not converge");
    }
    // The shift: the eigenvalue of the leading 2 x 2 block nearer d[l].
    const double s = std::sqrt(e2_[l_]);
    const double g = d_[l_];
    const double p = (d_[l_ + 1] - g) / (2.0 * s);
    const double r = std::hypot(p, 1.0);
    d_[l_] = s / (p + std::copysign(r, p));
    const double h = g - d_[l_];
    for (std::size_t i = l_ + 1; i < n_; ++i) d_[i] -= h;
    f_ += h;
    // One rational QL sweep from m up to l.
    double start = d_[m_];
    if (start == 0.0) start = b_;
    sweep_ = {m_, start, start, 0.0};
  }

  void Converged() {
    Insert();
    NextEigenvalue();
  }

  // The eigenvalue at l, inserted in order among those found.
  void Insert() {
    const double eigenvalue = d_[l_] + f_;
    std::size_t i = l_;
    for (; i > 0 && eigenvalue < d_[i - 1]; --i) d_[i] = d_[i - 1];
    d_[i] = eigenvalue;
    ++l_;
  }

  std::vector<double> d_, e2_;
  std::size_t n_, l_ = 0, m_ = 0;
  int iteration_ = 0;
  double f_ = 0.0;  // the shifts so far: d holds the eigenvalues less f
  // The tolerance's scale; b, its value, also replaces a zero pivot; c, its square.
  double t_ = 0.0, b_ = 0.0, c_ = 0.0;
  Sweep sweep_{};
};

void SolveTogether(RationalQl& first, RationalQl& second) {
  while (!first.done() && !second.done()) {
    first.StepWith(second, std::min(first.steps_left(), second.steps_left()));
    if (first.steps_left() == 0) first.EndSweep();
    if (second.steps_left() == 0) second.EndSweep();
  }
  first.Finish();
  second.Finish();
}

}  // namespace

std::vector<std::vector<double>> TridiagonalEigenvalues(
    std::vector<SymmetricTridiagonal> matrices) {
  std::vector<RationalQl> solvers;
  solvers.reserve(matrices.size());
  for (SymmetricTridiagonal& matrix : matrices) {
    solvers.emplace_back(std::move(matrix.diagonal), matrix.off_diagonal);
  }
  for (std::size_t k = 0; k < solvers.size(); k += 2) {
    if (k + 1 < solvers.size()) {
      SolveTogether(solvers[k], solvers[k + 1]);
    } else {
      solvers[k].Finish();
    }
  }
  std::vector<std::vector<double>> eigenvalues;
  for (RationalQl& solver : solvers) eigenvalues.push_back(std::move(solver).eigenvalues());
  return eigenvalues;
}

std::vector<double> TridiagonalEigenvalues(std::vector<double> diagonal,
                                           const std::vector<double>& off_diagonal) {
  RationalQl solver(std::move(diagonal), off_diagonal);
  solver.Finish();
  return std::move(solver).eigenvalues();
}

}  // namespace isolab::analysis
