#include "model.h"

#include <fmt/format.h>

#include <cctype>
#include <stdexcept>
#include <vector>

#include "isolab/core/errors.h"

namespace isolab::python {
namespace {

// "isolation.components[0].qd" -> isolation, components, [0], qd: each step a map key, an index
// ("[0]") or the name of an entry in a list of maps with a "name".
std::vector<std::string> SplitKeyPath(const std::string& key_path) {
  std::vector<std::string> steps;
  std::string step;
  const auto flush = [&] {
    if (!step.empty()) steps.push_back(step);
    step.clear();
  };
  for (const char c : key_path) {
    if (c == '.') {
      flush();
    } else if (c == '[') {
      flush();
      step = "[";
    } else if (c == ']') {
      step += c;
      flush();
    } else {
      step += c;
    }
  }
  flush();
  if (steps.empty()) throw std::out_of_range("an empty key path");
  return steps;
}

// The child of `node` at `step`, or an undefined node. `create`: a missing map key is added.
YAML::Node Child(YAML::Node node, const std::string& step, const std::string& where, bool create) {
  if (node.IsSequence()) {
    if (step.front() == '[') {
      const std::string digits = step.substr(1, step.size() - 2);
      std::size_t index = 0;
      try {
        index = std::stoul(digits);
      } catch (const std::exception&) {
        throw std::out_of_range(fmt::format("{}: '{}' is not an index", where, step));
      }
      if (index >= node.size()) {
        throw std::out_of_range(fmt::format("{}{} is past the end (the list has {} entries)", where,
                                            step, node.size()));
      }
      return node[index];
    }
    for (YAML::Node entry : node) {
      if (entry.IsMap() && entry["name"] && entry["name"].Scalar() == step) return entry;
    }
    throw std::out_of_range(fmt::format("{} has no entry named '{}'", where, step));
  }
  if (step.front() == '[') throw std::out_of_range(fmt::format("{} is not a list", where));
  if (!node.IsMap()) {
    if (create && node.IsNull()) {
      node = YAML::Node(YAML::NodeType::Map);
    } else {
      throw std::out_of_range(fmt::format("{} has no keys ('{}' asked for)", where, step));
    }
  }
  if (!node[step]) {
    if (!create) throw std::out_of_range(fmt::format("{} has no key '{}'", where, step));
    node[step] = YAML::Node(YAML::NodeType::Null);
  }
  return node[step];
}

std::string Describe(const std::string& where) { return where.empty() ? "the model" : where; }

}  // namespace

Model Model::Load(const std::string& path) {
  model::ModelFile model = model::LoadModelFile(path);
  YAML::Node tree = YAML::Load(model.text);
  return Model(std::move(tree), std::move(model));
}

Model Model::FromTree(const YAML::Node& tree, const std::string& name) {
  YAML::Emitter emitter;
  emitter << tree;
  model::ModelFile model = model::LoadModelText(std::string(emitter.c_str()) + "\n", name);
  return Model(YAML::Clone(tree), std::move(model));
}

YAML::Node Model::Get(const std::string& key_path) const {
  YAML::Node node = tree_;
  std::string where;
  for (const std::string& step : SplitKeyPath(key_path)) {
    node.reset(Child(node, step, Describe(where), false));  // rebinds; `=` would assign
    where += (where.empty() || step.front() == '[' ? "" : ".") + step;
  }
  return node;
}

void Model::Set(const std::string& key_path, const YAML::Node& value) {
  YAML::Node tree = YAML::Clone(tree_);
  YAML::Node node = tree;
  std::string where;
  const std::vector<std::string> steps = SplitKeyPath(key_path);
  for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
    node.reset(Child(node, steps[i], Describe(where), true));
    where += (where.empty() || steps[i].front() == '[' ? "" : ".") + steps[i];
  }
  const std::string& last = steps.back();
  if (node.IsSequence() || last.front() == '[') {
    Child(node, last, Describe(where), false) = value;
  } else {
    Child(node, last, Describe(where), true) = value;
  }
  try {
    *this = FromTree(tree, model_.path);
  } catch (const InputError& error) {
    // The reader located the error in the YAML written for the changed tree, which nobody sees
    // and whose lines are not the original file's: name the key path set from Python instead.
    const std::string where = error.location().Describe() + ": ";
    std::string what = error.what();
    if (what.rfind(where, 0) == 0) what.erase(0, where.size());
    throw InputError({fmt::format("{}, set(\"{}\")", model_.path, key_path)}, what);
  }
}

}  // namespace isolab::python
