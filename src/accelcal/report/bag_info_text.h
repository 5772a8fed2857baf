// `accelcal bag-info`'s text: a bag's topics (type, messages, rate, span, gaps of the receive
// times) and, for each IMU topic, its header stamps as accelcal reads them.
#pragma once

#include <string>

#include "accelcal/bags/bag_info.h"

namespace accelcal {

std::string FormatBagInfo(const bags::BagInfo& info);

}  // namespace accelcal
