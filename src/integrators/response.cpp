#include "isolab/integrators/response.h"

#include <algorithm>

namespace isolab::integrators {

void ResponseHistory::Resize(int rows, int dofs, int connections, int laws, int bearings) {
  time.assign(rows, 0.0);
  displacement.setZero(rows, dofs);
  velocity.setZero(rows, dofs);
  acceleration.setZero(rows, dofs);
  absolute_acceleration.setZero(rows, dofs);
  connection_force.setZero(rows, connections);
  law_force.setZero(rows, laws);
  axial_load.setZero(rows, bearings);
  energies.assign(rows, Energies{});
  rows_written = 0;
}

ResponseRow ResponseHistory::Row(int row) const {
  const auto view = [row](const RowMatrix& matrix) {
    return std::span<const double>(matrix.row(row).data(), static_cast<std::size_t>(matrix.cols()));
  };
  return {row * output_every,     time[row],          view(displacement),
          view(velocity),         view(acceleration), view(absolute_acceleration),
          view(connection_force), view(law_force),    energies[row],
          view(axial_load)};
}

HistoryRecorder::HistoryRecorder(ResponseHistory* history, const TimeGrid& grid, int dofs,
                                 int connections, int laws, int bearings)
    : history_(*history) {
  const int every = std::max(grid.output_every, 1);
  history_.Resize(grid.steps / every + 1, dofs, connections, laws, bearings);
  history_.output_every = every;
}

void HistoryRecorder::Observe(const ResponseRow& row) {
  if (row.step % history_.output_every != 0) return;
  const int r = row.step / history_.output_every;
  const auto copy = [r](std::span<const double> values, RowMatrix* matrix) {
    std::copy(values.begin(), values.end(), matrix->row(r).data());
  };
  history_.time[r] = row.time;
  copy(row.displacement, &history_.displacement);
  copy(row.velocity, &history_.velocity);
  copy(row.acceleration, &history_.acceleration);
  copy(row.absolute_acceleration, &history_.absolute_acceleration);
  copy(row.connection_force, &history_.connection_force);
  copy(row.law_force, &history_.law_force);
  if (history_.axial_load.cols() > 0) copy(row.axial_load, &history_.axial_load);
  history_.energies[r] = row.energies;
  history_.rows_written = r + 1;
}

HistoryRecorder RecordHistory(const structure::Structure& structure, const TimeGrid& grid,
                              ResponseHistory* response) {
  return HistoryRecorder(response, grid, structure.dofs(),
                         static_cast<int>(structure.force_columns()),
                         static_cast<int>(structure.law_count()),
                         static_cast<int>(structure.axial_loads().bearings.size()));
}

}  // namespace isolab::integrators
