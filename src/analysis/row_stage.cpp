#include "row_stage.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace isolab::analysis {
namespace {

// `count` values from `in` to `out`, two at a time: GCC makes a plain copy loop a call to memmove,
// which costs more than the copy for the few values of most arrays' rows and runs.
[[gnu::always_inline]] inline void CopyFew(const double* __restrict in, std::size_t count,
                                           double* __restrict out) {
  std::size_t k = 0;
  for (; k + 2 <= count; k += 2) {
    const double first = in[k], second = in[k + 1];
    out[k] = first;
    out[k + 1] = second;
  }
  if (k < count) out[k] = in[k];
}

}  // namespace

std::size_t RowStage::StagedIndex(RowArray array, const structure::Structure& structure) {
  for (std::size_t k = 0; k < staged_.size(); ++k) {
    if (staged_[k].array == array) return k;
  }
  staged_.push_back({array, RowArrayWidth(array, structure), {}});
  return staged_.size() - 1;
}

RowStage::RowStage(std::span<const Series> series, const structure::Structure& structure,
                   std::size_t rows)
    : series_(series), whole_(series.size(), -1), blocks_(series.size()) {
  // An array is staged where the series read, a term a value, at least half as many values a row
  // as it holds: a roof's displacement alone is cheaper filled from the row than a 1000-story
  // building's displacements copied for it.
  std::array<std::size_t, kRowArrays> reads{};
  for (const Series& s : series) {
    for (const ColumnSource& source : s.sources) {
      reads[static_cast<std::size_t>(source.array)] += source.sum ? source.terms.size() : 1;
    }
  }
  const auto staged = [&](RowArray array) {
    return 2 * reads[static_cast<std::size_t>(array)] >= RowArrayWidth(array, structure);
  };
  for (std::uint32_t s = 0; s < series.size(); ++s) {
    const std::vector<ColumnSource>& sources = series[s].sources;
    if (!sources.empty() && sources.size() != series[s].width()) {
      throw std::logic_error(series[s].name + ": a source per column, or none");
    }
    if (sources.empty() || !std::all_of(sources.begin(), sources.end(),
                                        [&](const ColumnSource& c) { return staged(c.array); })) {
      computed_.push_back(s);
      continue;
    }
    if (const std::optional<RowArray> whole = WholeArray(series[s], structure)) {
      whole_[s] = static_cast<int>(StagedIndex(*whole, structure));
      continue;
    }
    for (std::uint32_t c = 0; c < sources.size(); ++c) {
      const ColumnSource& source = sources[c];
      const auto staged_index = static_cast<std::uint32_t>(StagedIndex(source.array, structure));
      if (source.sum) {
        const auto begin = static_cast<std::uint32_t>(terms_.size());
        terms_.insert(terms_.end(), source.terms.begin(), source.terms.end());
        sums_.push_back(
            {s, c, staged_index, begin, static_cast<std::uint32_t>(terms_.size()), source.factor});
        continue;
      }
      const auto index = static_cast<std::uint32_t>(source.index);
      if (!copies_.empty()) {
        Copy& last = copies_.back();
        if (last.series == s && last.staged == staged_index && last.column + last.count == c &&
            last.first + last.count == index) {
          ++last.count;
          continue;
        }
      }
      copies_.push_back({s, c, staged_index, index, 1});
    }
  }
  Resize(rows);
}

void RowStage::Resize(std::size_t rows) {
  for (Staged& staged : staged_) staged.rows.resize(rows * staged.width);
  for (std::size_t s = 0; s < series_.size(); ++s) {
    if (whole_[s] < 0) blocks_[s].resize(rows * series_[s].width());
  }
}

void RowStage::Keep(const integrators::ResponseRow& row, std::size_t at) {
  const RowArrays arrays(row);
  for (Staged& staged : staged_) {
    CopyFew(arrays[staged.array], staged.width, staged.rows.data() + at * staged.width);
  }
  for (const std::uint32_t s : computed_) {
    series_[s].fill(row, blocks_[s].data() + at * series_[s].width());
  }
}

void RowStage::Gather(std::size_t rows) {
  for (const Copy& copy : copies_) {
    const Staged& from = staged_[copy.staged];
    const std::size_t width = series_[copy.series].width();
    const double* in = from.rows.data() + copy.first;
    double* out = blocks_[copy.series].data() + copy.column;
    if (copy.count == 1) {  // a vector's, most often
      for (std::size_t r = 0; r < rows; ++r) out[r * width] = in[r * from.width];
      continue;
    }
    for (std::size_t r = 0; r < rows; ++r) {
      CopyFew(in + r * from.width, copy.count, out + r * width);
    }
  }
  for (const Sum& sum : sums_) {
    const Staged& from = staged_[sum.staged];
    const std::size_t width = series_[sum.series].width(), stride = from.width;
    const double* in = from.rows.data();
    double* out = blocks_[sum.series].data() + sum.column;
    const ColumnSource::Term* terms = terms_.data() + sum.begin;
    const double factor = sum.factor;
    // ColumnSource::Sum's arithmetic, with a deformation's one or two terms kept in registers.
    if (sum.end - sum.begin == 1) {
      const double c0 = terms[0].coefficient;
      const std::size_t i0 = static_cast<std::size_t>(terms[0].index);
      for (std::size_t r = 0; r < rows; ++r) {
        out[r * width] = factor * (0.0 + c0 * in[r * stride + i0]);
      }
    } else if (sum.end - sum.begin == 2) {
      const double c0 = terms[0].coefficient, c1 = terms[1].coefficient;
      const std::size_t i0 = static_cast<std::size_t>(terms[0].index);
      const std::size_t i1 = static_cast<std::size_t>(terms[1].index);
      for (std::size_t r = 0; r < rows; ++r) {
        const double* row = in + r * stride;
        out[r * width] = factor * ((0.0 + c0 * row[i0]) + c1 * row[i1]);
      }
    } else {
      const std::span<const ColumnSource::Term> own(terms, sum.end - sum.begin);
      for (std::size_t r = 0; r < rows; ++r) {
        out[r * width] = factor * ColumnSource::Sum(own, in + r * stride);
      }
    }
  }
}

void RowStage::Pad(std::size_t rows) {
  for (Staged& staged : staged_) {
    std::fill(staged.rows.begin() + static_cast<std::ptrdiff_t>(rows * staged.width),
              staged.rows.end(), 0.0);
  }
  for (std::size_t s = 0; s < series_.size(); ++s) {
    if (whole_[s] >= 0) continue;
    std::fill(blocks_[s].begin() + static_cast<std::ptrdiff_t>(rows * series_[s].width()),
              blocks_[s].end(), 0.0);
  }
}

std::span<const double> RowStage::Rows(std::size_t series) const {
  return whole_[series] >= 0 ? std::span<const double>(staged_[whole_[series]].rows)
                             : std::span<const double>(blocks_[series]);
}

}  // namespace isolab::analysis
