#include "isolab/model/fitted_model_file.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <sstream>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/model/model_file.h"

namespace isolab::model {
namespace {

// A YAML double-quoted string: a data file named with a quote stays one string.
std::string Quoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + '"';
}

std::string FittedModelText(const FittedModel& model) {
  std::ostringstream out;
  for (const std::string& line : model.comment) fmt::print(out, "# {}\n", line);
  fmt::print(out, "description: {}\n", Quoted(model.description));
  fmt::print(out, "units: {{force: {}, length: {}, time: {}}}\nisolation:\n", model.units.force(),
             model.units.length(), model.units.time());
  if (model.range) {
    std::vector<std::string> names;
    for (const std::string& name : model.range->data) names.push_back(Quoted(name));
    fmt::print(out,
               "  identified_range: {{displacement: {:.9g}, velocity: {:.9g}, cycles: {:g}, "
               "data: [{}]}}  # {}, {}/{}\n",
               model.range->displacement, model.range->velocity, model.range->cycles,
               fmt::join(names, ", "), model.units.length(), model.units.length(),
               model.units.time());
  }
  fmt::print(out, "  components:\n");
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
  return out.str();
}

}  // namespace

void WriteFittedModel(const std::string& path, const FittedModel& model) {
  const std::string text = FittedModelText(model);
  try {
    LoadModelText(text, path);
  } catch (const InputError& error) {
    // The location is in a file not written: name what is wrong and where it was asked for.
    const std::string what = error.what();
    const std::string prefix = error.location().Describe() + ": ";
    throw InputError(
        {model.specification},
        fmt::format("the identified model is not one isolab can use ({}): the data do not call "
                    "for every component asked for; remove it, or give data that exercise it. "
                    "{} was not written",
                    what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what, path));
  }
  io::WriteTextFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace isolab::model
