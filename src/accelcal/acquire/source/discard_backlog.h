// What a live source delivered before now and nobody has read (a link's buffers while a
// question waited on the screen), read and dropped, so that a capture begun now judges only
// samples taken after the technician's answer (issue 27, item 6). The virtual bench is left
// alone: it makes its samples when they are read, with the sensor already placed as asked.
#pragma once

#include "accelcal/acquire/source/sample_source.h"

namespace accelcal {

// Reads `source` without waiting until it has nothing more, `max_reads` times at most (a link
// that sends faster than it is read is not drained forever); returns the samples dropped.
long DiscardBacklog(SampleSource& source, int max_reads = 64);

}  // namespace accelcal
