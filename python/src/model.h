// A model as Python holds it: its YAML tree and what the model reader made of it. Every change
// goes through the reader again, so a dict or a changed parameter is checked, and its errors
// located, exactly as a model file's are.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "isolab/model/model_file.h"

namespace isolab::python {

class Model {
 public:
  // Throws InputError as model::LoadModelFile does.
  static Model Load(const std::string& path);
  // `name` stands for the file in messages; files the model names are found relative to its
  // folder (a name without one: the current directory).
  static Model FromTree(const YAML::Node& tree, const std::string& name);

  // A YAML::Node copy shares the tree and its `=` writes into it: a Model copy owns its tree.
  Model(const Model& other) : tree_(YAML::Clone(other.tree_)), model_(other.model_) {}
  Model& operator=(const Model& other) {
    tree_.reset(YAML::Clone(other.tree_));
    model_ = other.model_;
    return *this;
  }

  const model::ModelFile& file() const { return model_; }
  const YAML::Node& tree() const { return tree_; }

  // The node at a key path such as "isolation.components[0].qd" or, in a list of named entries,
  // "isolation.components.lrb.qd". Throws std::out_of_range when there is none.
  YAML::Node Get(const std::string& key_path) const;
  // Replaces (or adds) the value at `key_path` and reads the model again; on an InputError the
  // model is left as it was. Its text, and the lines errors name from then on, are the re-emitted
  // YAML (Model::text()); an error the change itself causes names the model and the key path set
  // ("m.yaml, set(\"isolation.components.lrb.qdd\"): ..."), no line.
  void Set(const std::string& key_path, const YAML::Node& value);

 private:
  Model(YAML::Node tree, model::ModelFile model)
      : tree_(std::move(tree)), model_(std::move(model)) {}

  YAML::Node tree_;
  model::ModelFile model_;
};

}  // namespace isolab::python
