#include "isolab/io/record_attributes.h"

namespace isolab::io {

void WriteRecordAttributes(Hdf5File& file, const AppliedRecord& record, double gravity,
                           const std::string& name) {
  file.WriteAttribute("/", name, record.path);
  file.WriteAttribute("/", name + "_format", record.format);
  file.WriteAttribute("/", name + "_units", record.units);
  file.WriteAttribute("/", name + "_units_source", record.units_source);
  file.WriteAttribute("/", name + "_dt", record.dt);
  file.WriteAttribute("/", name + "_scale", record.scale);
  file.WriteAttribute("/", name + "_scaled_to", record.scaled_to);
  file.WriteAttribute("/", name + "_pga", record.pga);
  file.WriteAttribute("/", name + "_pga_g", record.pga / gravity);
}

}  // namespace isolab::io
