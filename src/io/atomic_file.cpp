#include "isolab/io/atomic_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "isolab/core/errors.h"

namespace isolab::io {

void WriteTextFileAtomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write) {
  const std::string temporary = path + ".tmp";
  try {
    {
      std::ofstream stream(temporary, std::ios::trunc);
      if (!stream) {
        throw InputError({path}, fmt::format("cannot create ({})", std::strerror(errno)));
      }
      write(stream);
      stream.flush();
      if (!stream) throw InputError({path}, "write failed");
    }
    std::filesystem::rename(temporary, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

}  // namespace isolab::io
