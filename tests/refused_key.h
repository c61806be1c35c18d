// The key of the InvalidParameter a call throws: what a test of a refusal checks.
#pragma once

#include <string>

#include "isolab/core/errors.h"

namespace isolab::testing {

// The violated key, or "" when `call` throws none.
template <typename Call>
std::string RefusedKey(Call call) {
  try {
    call();
  } catch (const InvalidParameter& error) {
    return error.violation().key;
  }
  return "";
}

}  // namespace isolab::testing
