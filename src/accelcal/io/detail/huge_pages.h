// Asking the kernel for transparent huge pages under a large buffer about to be filled (the
// samples of a long recording): one fault per 2 MiB instead of one per 4 KiB. On this project's
// virtual machines a page fault costs microseconds; filling the 144 MB of samples of a 1-hour
// 1 kHz recording took 35 000 of them, about half of `fit --recording`'s time. Advice only:
// ignored where the kernel does not offer huge pages (or for buffers under 2 MiB).
#pragma once

#include <cstddef>

namespace accelcal::detail {

void AdviseHugePages(const void* data, std::size_t bytes);

}  // namespace accelcal::detail
