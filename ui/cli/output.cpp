#include "cli/output.h"

#include <iostream>

#include "accelcal/base/error.h"
#include "accelcal/io/atomic_write.h"
#include "cli/shipped_files.h"

namespace accelcal::cli {

void WriteOutputText(const std::string& path, const std::string& text) {
  if (!path.empty()) {
    WriteFileAtomically(path, text);
    return;
  }
  std::cout << text;
  std::cout.flush();
  if (!std::cout) throw Error("cannot write to standard output");
}

std::string ShippedProcedurePath(const std::string& file_name) {
  return (ShippedDir(kShippedProcedures) / file_name).string();
}

}  // namespace accelcal::cli
