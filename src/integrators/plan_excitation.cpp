#include "isolab/integrators/plan_excitation.h"

#include "isolab/structure/plan_structure.h"

namespace isolab::integrators {

void PlanExcitation::EffectiveLoad(double t, const Eigen::VectorXd& mass,
                                   Eigen::VectorXd* load) const {
  const double ax = x.At(t), ay = y.At(t);
  for (Eigen::Index i = 0; i < mass.size(); i += structure::kPlanDofsPerFloor) {
    (*load)[i] = -ax * mass[i];
    (*load)[i + 1] = -ay * mass[i + 1];
    (*load)[i + 2] = 0.0;
  }
}

void PlanExcitation::AddGroundAcceleration(double t,
                                           Eigen::Ref<Eigen::VectorXd> acceleration) const {
  const double ax = x.At(t), ay = y.At(t);
  for (Eigen::Index i = 0; i < acceleration.size(); i += structure::kPlanDofsPerFloor) {
    acceleration[i] += ax;
    acceleration[i + 1] += ay;
  }
}

}  // namespace isolab::integrators
