#include "isolab/study/job_result.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace isolab::study {
namespace {

// Fixed-size fields copied as their bytes: every rank runs the same binary on the same kind of
// machine, and a double must arrive bit for bit.
template <typename T>
void Put(std::vector<char>* bytes, const T& value) {
  const std::size_t at = bytes->size();
  bytes->resize(at + sizeof(T));
  std::memcpy(bytes->data() + at, &value, sizeof(T));
}

void PutString(std::vector<char>* bytes, const std::string& text) {
  Put(bytes, static_cast<std::uint64_t>(text.size()));
  const std::size_t at = bytes->size();
  bytes->resize(at + text.size());
  if (!text.empty()) std::memcpy(bytes->data() + at, text.data(), text.size());
}

class Reader {
 public:
  explicit Reader(std::span<const char> bytes) : bytes_(bytes) {}

  template <typename T>
  T Get() {
    T value;
    std::memcpy(&value, Take(sizeof(T)), sizeof(T));
    return value;
  }
  std::string GetString() {
    const auto size = Get<std::uint64_t>();
    const char* begin = Take(size);
    return std::string(begin, begin + size);
  }
  bool AtEnd() const { return offset_ == bytes_.size(); }

 private:
  const char* Take(std::size_t size) {
    if (size > bytes_.size() - offset_) throw std::runtime_error("truncated job result");
    const char* at = bytes_.data() + offset_;
    offset_ += size;
    return at;
  }

  std::span<const char> bytes_;
  std::size_t offset_ = 0;
};

}  // namespace

std::vector<char> Serialize(const JobResult& result) {
  std::vector<char> bytes;
  Put(&bytes, static_cast<std::uint64_t>(result.job));
  Put(&bytes, static_cast<std::uint8_t>(result.completed ? 1 : 0));
  for (const double value : result.values) Put(&bytes, value);
  Put(&bytes, result.wall_seconds);
  Put(&bytes, result.output_seconds);
  Put(&bytes, result.pga);
  PutString(&bytes, result.message);
  PutString(&bytes, result.file);
  PutString(&bytes, result.record_units);
  Put(&bytes, static_cast<std::uint64_t>(result.warnings.size()));
  for (const std::string& warning : result.warnings) PutString(&bytes, warning);
  Put(&bytes, static_cast<std::uint64_t>(result.parts.size()));
  for (const PartPeak& part : result.parts) {
    Put(&bytes, static_cast<std::uint8_t>(part.quantity));
    PutString(&bytes, part.part);
    Put(&bytes, part.value);
  }
  return bytes;
}

JobResult Deserialize(std::span<const char> bytes) {
  Reader reader(bytes);
  JobResult result;
  result.job = static_cast<std::size_t>(reader.Get<std::uint64_t>());
  result.completed = reader.Get<std::uint8_t>() != 0;
  for (double& value : result.values) value = reader.Get<double>();
  result.wall_seconds = reader.Get<double>();
  result.output_seconds = reader.Get<double>();
  result.pga = reader.Get<double>();
  result.message = reader.GetString();
  result.file = reader.GetString();
  result.record_units = reader.GetString();
  const auto warnings = reader.Get<std::uint64_t>();
  for (std::uint64_t k = 0; k < warnings; ++k) result.warnings.push_back(reader.GetString());
  const auto parts = reader.Get<std::uint64_t>();
  for (std::uint64_t k = 0; k < parts; ++k) {
    PartPeak part;
    const auto quantity = reader.Get<std::uint8_t>();
    if (quantity >= kPartQuantityCount) throw std::runtime_error("job result with a bad part");
    part.quantity = static_cast<PartQuantity>(quantity);
    part.part = reader.GetString();
    part.value = reader.Get<double>();
    result.parts.push_back(std::move(part));
  }
  if (!reader.AtEnd()) throw std::runtime_error("job result with trailing bytes");
  return result;
}

}  // namespace isolab::study
