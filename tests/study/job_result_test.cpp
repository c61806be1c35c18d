// A JobResult crosses between MPI ranks as bytes: every field must come back, doubles bit for bit.
#include "isolab/study/job_result.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace isolab::study {
namespace {

TEST(JobResult, RoundTripsThroughBytes) {
  JobResult result;
  result.job = 123456789012ULL;
  result.completed = true;
  result.values = {0.1 + 0.2, std::numeric_limits<double>::quiet_NaN(), -0.0,
                   std::numeric_limits<double>::denorm_min(), 1e300};
  result.message = "with, commas and \"quotes\"\nand a newline";
  result.file = "runs/thm1/rec_x1.5.h5";
  result.record_units = "cm/s^2";
  result.pga = 0.1 + 0.7;
  result.warnings = {"first", "", "third, with a comma"};
  result.wall_seconds = 0.25;
  result.parts = {{PartQuantity::kLeastAxialLoad, "tfp_1", -0.0},
                  {PartQuantity::kStoryShear, "story 2", 0.1 + 0.2}};
  const JobResult back = Deserialize(Serialize(result));
  EXPECT_EQ(back.job, result.job);
  EXPECT_EQ(back.completed, result.completed);
  EXPECT_EQ(std::memcmp(back.values.data(), result.values.data(), sizeof(result.values)), 0);
  EXPECT_EQ(back.message, result.message);
  EXPECT_EQ(back.file, result.file);
  EXPECT_EQ(back.record_units, result.record_units);
  EXPECT_EQ(back.pga, result.pga);
  EXPECT_EQ(back.warnings, result.warnings);
  EXPECT_EQ(back.wall_seconds, result.wall_seconds);
  ASSERT_EQ(back.parts.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back.parts[k].quantity, result.parts[k].quantity);
    EXPECT_EQ(back.parts[k].part, result.parts[k].part);
  }
  EXPECT_TRUE(std::signbit(back.parts[0].value));
  EXPECT_EQ(back.parts[1].value, result.parts[1].value);
}

TEST(JobResult, RejectsTruncatedOrPaddedBytes) {
  std::vector<char> bytes = Serialize(JobResult{});
  bytes.push_back('x');
  EXPECT_THROW(Deserialize(bytes), std::runtime_error);
  bytes.resize(bytes.size() - 3);
  EXPECT_THROW(Deserialize(bytes), std::runtime_error);
}

}  // namespace
}  // namespace isolab::study
