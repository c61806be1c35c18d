#include "record_attributes.h"

namespace isolab::io {

void WriteRecordAttributes(Hdf5File& file, const AppliedRecord& record, double gravity) {
  file.WriteAttribute("/", "record", record.path);
  file.WriteAttribute("/", "record_format", record.format);
  file.WriteAttribute("/", "record_units", record.units);
  file.WriteAttribute("/", "record_units_source", record.units_source);
  file.WriteAttribute("/", "record_dt", record.dt);
  file.WriteAttribute("/", "record_scale", record.scale);
  file.WriteAttribute("/", "record_pga", record.pga);
  file.WriteAttribute("/", "record_pga_g", record.pga / gravity);
}

}  // namespace isolab::io
