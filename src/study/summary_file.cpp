#include "isolab/study/summary_file.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "isolab/io/atomic_file.h"
#include "isolab/io/csv.h"
#include "isolab/io/hdf5_file.h"

namespace isolab::study {
namespace {

using io::ExactNumber;

std::string StatisticStatus(std::size_t completed, std::size_t records) {
  if (completed == records) return "completed";
  return completed == 0 ? "failed" : "partial";
}

void WriteCsvRow(std::ostream& out, const std::vector<std::string>& fields) {
  out << io::CsvLine(fields);
}

std::string JoinWarnings(const std::vector<std::string>& warnings) {
  std::string text;
  for (const std::string& warning : warnings) text += (text.empty() ? "" : "; ") + warning;
  return text;
}

std::vector<std::string> RowStart(const StudyShape& shape, const std::string& variant,
                                  const std::string& record, double scale,
                                  const std::string& status, const QuantityValues& values,
                                  const QuantityValues& ratios) {
  std::vector<std::string> fields = {variant, record, fmt::format("{}", scale), status};
  for (const Quantity q : shape.quantities) {
    fields.push_back(ExactNumber(values[static_cast<std::size_t>(q)]));
  }
  for (const Quantity q : shape.quantities) {
    fields.push_back(ExactNumber(ratios[static_cast<std::size_t>(q)]));
  }
  return fields;
}

// Quantity q of every element of `items`, in order.
template <typename Item, typename Get>
std::vector<double> Column(const std::vector<Item>& items, std::size_t q, Get get) {
  std::vector<double> column;
  column.reserve(items.size());
  for (const Item& item : items) column.push_back(get(item)[q]);
  return column;
}

}  // namespace

void WriteSummaryCsv(const std::string& path, const Summary& summary) {
  const StudyShape& shape = summary.shape;
  io::WriteTextFileAtomically(path, [&](std::ostream& out) {
    std::vector<std::string> header = {"variant", "record", "scale", "status"};
    for (const Quantity q : shape.quantities) {
      header.push_back(
          fmt::format("{} [{}]", InfoOf(q).key, shape.units[static_cast<std::size_t>(q)]));
    }
    for (const Quantity q : shape.quantities) {
      header.push_back(fmt::format("ratio {}", InfoOf(q).key));
    }
    for (const char* name : {"message", "file", "record_units", "pga_g", "warnings"}) {
      header.push_back(name);
    }
    WriteCsvRow(out, header);

    const std::size_t R = shape.records.size(), S = shape.scales.size();
    for (const JobResult& run : summary.runs) {
      const std::size_t v = run.job / (R * S), r = run.job / S % R, s = run.job % S;
      std::vector<std::string> fields =
          RowStart(shape, shape.variants[v], shape.records[r], shape.scales[s],
                   run.completed ? "completed" : "failed", run.values, summary.ratios[run.job]);
      fields.push_back(run.message);
      fields.push_back(run.file);
      fields.push_back(run.record_units);
      fields.push_back(ExactNumber(run.pga));
      fields.push_back(JoinWarnings(run.warnings));
      WriteCsvRow(out, fields);
    }
    for (std::size_t v = 0; v < shape.variants.size(); ++v) {
      for (std::size_t s = 0; s < S; ++s) {
        const Statistic& statistic = summary.At(v, s);
        const std::string status = StatisticStatus(statistic.completed, R);
        const std::string over = statistic.completed == R
                                     ? ""
                                     : fmt::format("over the {} of {} records whose runs completed",
                                                   statistic.completed, R);
        for (const bool mean : {true, false}) {
          std::vector<std::string> fields =
              RowStart(shape, shape.variants[v], mean ? "mean" : "max", shape.scales[s], status,
                       mean ? statistic.mean : statistic.max,
                       mean ? statistic.mean_ratio : statistic.max_ratio);
          fields.push_back(over);
          fields.resize(header.size());
          WriteCsvRow(out, fields);
        }
      }
    }
  });
}

void WriteSummaryHdf5(const std::string& path, const Summary& summary, const std::string& study,
                      const std::string& version) {
  const StudyShape& shape = summary.shape;
  const std::size_t V = shape.variants.size(), R = shape.records.size(), S = shape.scales.size();
  const std::vector<std::size_t> run_dims = {V, R, S};
  const std::vector<std::size_t> statistic_dims = {V, S};
  io::Hdf5File file(path);

  file.WriteStrings("variants", {V}, shape.variants);
  file.WriteStrings("records", {R}, shape.records);
  if (shape.record_files.size() == R) file.WriteStrings("record_files", {R}, shape.record_files);
  file.WriteDoubles("scales", {S}, shape.scales, "");

  std::vector<std::int64_t> status;
  std::vector<std::string> messages, files, record_units, warnings;
  std::vector<double> pga;
  for (const JobResult& run : summary.runs) {
    status.push_back(run.completed ? 0 : 1);
    messages.push_back(run.message);
    files.push_back(run.file);
    record_units.push_back(run.record_units);
    pga.push_back(run.pga);
    warnings.push_back(JoinWarnings(run.warnings));
  }
  file.WriteIntegers("status", run_dims, status);
  file.WriteAttribute("status", "meaning", "0 completed, 1 failed");
  file.WriteStrings("message", run_dims, messages);
  file.WriteStrings("file", run_dims, files);
  file.WriteStrings("record_units", run_dims, record_units);
  file.WriteDoubles("pga", run_dims, pga, "g");
  file.WriteStrings("warnings", run_dims, warnings);
  std::vector<std::int64_t> completed;
  for (const Statistic& statistic : summary.statistics) {
    completed.push_back(static_cast<std::int64_t>(statistic.completed));
  }
  file.WriteIntegers("completed", statistic_dims, completed);

  const auto values = [](const JobResult& run) -> const QuantityValues& { return run.values; };
  const auto same = [](const QuantityValues& v) -> const QuantityValues& { return v; };
  for (const char* group : {"runs", "ratio", "mean", "max", "mean_ratio", "max_ratio"}) {
    file.CreateGroup(group);
  }
  for (const Quantity quantity : shape.quantities) {
    const auto q = static_cast<std::size_t>(quantity);
    const std::string key(InfoOf(quantity).key);
    const std::string& unit = shape.units[q];
    file.WriteDoubles("runs/" + key, run_dims, Column(summary.runs, q, values), unit);
    file.WriteDoubles("ratio/" + key, run_dims, Column(summary.ratios, q, same), "1");
    file.WriteDoubles("mean/" + key, statistic_dims,
                      Column(summary.statistics, q, [](const Statistic& s) { return s.mean; }),
                      unit);
    file.WriteDoubles("max/" + key, statistic_dims,
                      Column(summary.statistics, q, [](const Statistic& s) { return s.max; }),
                      unit);
    file.WriteDoubles(
        "mean_ratio/" + key, statistic_dims,
        Column(summary.statistics, q, [](const Statistic& s) { return s.mean_ratio; }), "1");
    file.WriteDoubles("max_ratio/" + key, statistic_dims,
                      Column(summary.statistics, q, [](const Statistic& s) { return s.max_ratio; }),
                      "1");
  }
  file.WriteAttribute("/", "study", study);
  file.WriteAttribute("/", "reference", shape.variants[shape.reference]);
  file.WriteAttribute("/", "isolab_version", version);
  std::string units;
  for (const Quantity q : shape.quantities) {
    units += fmt::format("{}{} {}", units.empty() ? "" : ", ", InfoOf(q).key,
                         shape.units[static_cast<std::size_t>(q)]);
  }
  file.WriteAttribute("/", "units", units);
  file.Commit();
}

}  // namespace isolab::study
