// --specimen of `isolab fit` and `isolab diagnose`: whether the tests are one specimen tested in
// order (identification/cyclic_data.h) or fresh specimens; empty: the data's header decides.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace isolab::cli {

inline void AddSpecimenOption(CLI::App* command, std::string* specimen) {
  command
      ->add_option("--specimen", *specimen,
                   "sequential: the tests are one specimen in the given order, each starting "
                   "from the state the previous left; independent: fresh specimens (default: "
                   "the data's '# specimen:' header, else independent)")
      ->check(CLI::IsMember({"sequential", "independent"}));
}

}  // namespace isolab::cli
