#include "fit_data_checks.h"

#include <fmt/format.h>

#include "isolab/core/errors.h"

namespace isolab::cli {

void RequireMoreSamplesThanParameters(const identification::FitData& data,
                                      const identification::ModelParametrisation& model,
                                      const std::string& spec_path) {
  std::size_t samples = 0;
  for (const auto& spans : data.fitted) {
    for (const auto& span : spans) samples += span.end - span.begin;
  }
  const auto parameters = static_cast<std::size_t>(model.dimension() + model.amplitude_count());
  if (samples <= parameters) {
    throw InputError(
        {spec_path},
        fmt::format("{} parameters to identify ({} shape coordinates and {} stiffnesses) from {} "
                    "samples: the data cannot determine them; give more data or fewer components",
                    parameters, model.dimension(), model.amplitude_count(), samples));
  }
}

}  // namespace isolab::cli
