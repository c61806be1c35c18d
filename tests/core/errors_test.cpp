#include "isolab/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isolab {
namespace {

TEST(ParameterViolation, DescribesKeyValueAndRule) {
  EXPECT_EQ((ParameterViolation{"k1", 1.3, "must be < k0 = 1"}.Describe()),
            "k1 = 1.3 (must be < k0 = 1)");
  EXPECT_EQ((ParameterViolation{"uy", NAN, "is required"}.Describe()), "uy (is required)");
}

TEST(InputError, PrefixesFileLineAndColumn) {
  EXPECT_STREQ(InputError({"m.yaml", 14, 5}, "bad").what(), "m.yaml:14:5: bad");
  EXPECT_STREQ(InputError({"m.yaml", 3, 0}, "bad").what(), "m.yaml:3: bad");
  EXPECT_STREQ(InputError({"m.yaml"}, "bad").what(), "m.yaml: bad");
}

}  // namespace
}  // namespace isolab
