#include "blow_up.h"

#include <fmt/format.h>

namespace isolab::integrators {

std::string DescribeBlowUp(const Energies& e, double max_input) {
  if (!EnergiesFinite(e)) {
    return fmt::format(
        "the response is not finite (energies: input {:.3g}, kinetic {:.3g}, damping {:.3g}, "
        "elastic {:.3g}, hysteretic {:.3g})",
        e.input, e.kinetic, e.damping, e.elastic, e.hysteretic);
  }
  return fmt::format(
      "the kinetic energy {:.3g} exceeds {} times the input energy {:.3g}: the model creates "
      "energy (negative stiffnesses?)",
      e.kinetic, kBlowUpKineticToInput, max_input);
}

}  // namespace isolab::integrators
