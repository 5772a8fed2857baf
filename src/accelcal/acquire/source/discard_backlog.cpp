#include "accelcal/acquire/source/discard_backlog.h"

#include <vector>

namespace accelcal {

long DiscardBacklog(SampleSource& source, int max_reads) {
  if (source.bench() != nullptr) return 0;
  long dropped = 0;
  std::vector<Sample> chunk;
  for (int i = 0; i < max_reads; ++i) {
    chunk.clear();
    source.Read(0.0, &chunk);
    if (chunk.empty()) break;
    dropped += static_cast<long>(chunk.size());
  }
  return dropped;
}

}  // namespace accelcal
