#include "isolab/io/fitted_model_file.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "isolab/io/atomic_file.h"

namespace isolab::io {

void WriteFittedModel(const std::string& path, const FittedModel& model) {
  WriteTextFileAtomically(path, [&](std::ostream& out) {
    for (const std::string& line : model.comment) fmt::print(out, "# {}\n", line);
    fmt::print(out, "description: \"{}\"\n", model.description);
    fmt::print(out, "units: {{force: {}, length: {}, time: {}}}\nisolation:\n  components:\n",
               model.units.force(), model.units.length(), model.units.time());
    for (std::size_t c = 0; c < model.components.size(); ++c) {
      const auto type = model.components[c].type;
      const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
      fmt::print(out, "    - {{name: {}, type: {}", model.components[c].name,
                 hysteresis::LawName(type));
      for (std::size_t k = 0; k < keys.size(); ++k) {
        fmt::print(out, ", {}: {:.9g}", keys[k], model.mathematical[c][k]);
      }
      fmt::print(out, "}}\n");
    }
  });
}

}  // namespace isolab::io
