#include "isolab/hysteresis/plan_law_kernel.h"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace isolab::hysteresis {

bool HasCoupledForm(LawType type) {
  // The play sliders' direction-dependent strength and clearance have no 2-D form yet.
  return type != LawType::kDegradingBhm2 && type != LawType::kAsymmetricElastoplastic &&
         type != LawType::kBacklashElastoplastic;
}

PlanLawKernel CoupledKernel(const LawParameters& law) {
  if (!HasCoupledForm(law.type())) {
    throw std::invalid_argument(std::string(LawName(law.type())) +
                                " has no coupled bidirectional form (use it as an uncoupled pair)");
  }
  return std::visit(
      [](const auto& kernel) -> PlanLawKernel {
        using Kernel = std::decay_t<decltype(kernel)>;
        if constexpr (std::is_same_v<Kernel, SeriesSlider>) return PlanSeriesSlider{kernel};
        if constexpr (std::is_same_v<Kernel, ParallelSlider>) return PlanParallelSlider{kernel};
        if constexpr (std::is_same_v<Kernel, ElasticSpring>) return PlanElasticSpring{kernel};
        if constexpr (std::is_same_v<Kernel, Dashpot>) return PlanDashpot{kernel};
        if constexpr (std::is_same_v<Kernel, BoucWen>) return PlanBoucWen{kernel};
        if constexpr (std::is_same_v<Kernel, FrictionPendulum>) return PlanFrictionPendulum{kernel};
        if constexpr (std::is_same_v<Kernel, LeadRubber>) return PlanLeadRubber{kernel};
        if constexpr (std::is_same_v<Kernel, SeriesArrangement>) {
          return PlanSeriesArrangement{kernel};
        }
        // DegradingSlider: excluded by HasCoupledForm above.
        throw std::logic_error("a 1-D kernel without a coupled form passed HasCoupledForm");
      },
      law.Kernel());
}

PlanLawKernel UncoupledKernel(const LawParameters& along_x, const LawParameters& along_y) {
  UncoupledPair pair{along_x.Kernel(), along_y.Kernel()};
  for (const LawKernel* kernel : {&pair.x, &pair.y}) {
    if (StateSlots(*kernel) > 1) {
      const LawType type = kernel == &pair.x ? along_x.type() : along_y.type();
      throw std::invalid_argument(std::string(LawName(type)) +
                                  " cannot be one direction of an uncoupled pair (its sliders in "
                                  "series keep several states): use its coupled form");
    }
  }
  return pair;
}

bool HasConstantTangent(const PlanLawKernel& kernel) {
  if (const auto* elastic = std::get_if<PlanElasticSpring>(&kernel)) {
    return HasConstantTangent(LawKernel{elastic->law});
  }
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    return HasConstantTangent(pair->x) && HasConstantTangent(pair->y);
  }
  return std::holds_alternative<PlanDashpot>(kernel);
}

double PlanViscousEnergy(const PlanLawKernel& kernel, PlanLawStateView state) {
  if (std::holds_alternative<PlanDashpot>(kernel)) return Dissipated(state);
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    return (std::holds_alternative<Dashpot>(pair->x) ? state.x.dissipated : 0.0) +
           (std::holds_alternative<Dashpot>(pair->y) ? state.y.dissipated : 0.0);
  }
  return 0.0;
}

}  // namespace isolab::hysteresis
