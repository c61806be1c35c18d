// C v, the viscous damping forces of a structure at velocities v, evaluated once or twice a time
// step. For a few dofs (an SDOF, a shear building of up to 11 stories) C is held dense and
// multiplied by loops compiled for each size: a five-story building's 6 x 6 product is 36
// multiply-adds with no index arrays, about a third of the instructions of the sparse product,
// which serves larger structures. A structure without viscous damping (its damping all in its
// members' dashpots) has a C of zeros: its product is a vector of zeros, with no multiply (the
// +0.0 the product gives at finite velocities; a NaN velocity reaches the forces through the
// members instead).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace isolab::structure {

inline constexpr int kDenseDampingDofs = 12;

class DampingProduct {
 public:
  DampingProduct() = default;
  explicit DampingProduct(const Eigen::SparseMatrix<double>& damping);

  // *out = damping v; `damping` is the matrix given to the constructor.
  void Apply(const Eigen::SparseMatrix<double>& damping, const Eigen::VectorXd& v,
             Eigen::VectorXd* out) const {
    if (zero_) {
      out->setZero(damping.rows());
      return;
    }
    if (kernel_ == nullptr) {
      out->noalias() = damping * v;
      return;
    }
    out->resize(damping.rows());
    kernel_(dense_.data(), v.data(), out->data());
  }

  using Kernel = void (*)(const double* dense, const double* v, double* out);

 private:
  std::vector<double> dense_;  // column-major; empty when the sparse product serves, or none
  Kernel kernel_ = nullptr;
  bool zero_ = false;  // every stored value of C is 0.0
};

}  // namespace isolab::structure
