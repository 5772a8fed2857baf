// sensor_msgs/Imu, as accelcal reads it: the header's stamp and linear_acceleration (m/s^2, by
// the message's definition); orientation, angular velocity and the covariances are skipped.
//
// Two serializations (both decoded from their descriptions, by offsets, no generic decoder):
// - ROS 2 (sensor_msgs/msg/Imu), CDR as rmw writes it (XCDR1): a 4-byte encapsulation header
//   (CDR_BE 00 00 or CDR_LE 00 01), then header.stamp (int32 sec, uint32 nanosec),
//   header.frame_id (uint32 length counting its NUL, the bytes), padding to 8 (alignment counts
//   from after the encapsulation header), and 37 float64: orientation (4), its covariance (9),
//   angular_velocity (3), its covariance (9), linear_acceleration (3), its covariance (9).
// - ROS 1 (sensor_msgs/Imu), little-endian and packed: header.seq (uint32), header.stamp
//   (uint32 secs, uint32 nsecs), frame_id (uint32 length, the bytes), the same 37 float64.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "accelcal/bags/bag_file.h"

namespace accelcal::bags {

struct ImuReading {
  int64_t stamp_sec = 0;
  uint32_t stamp_nsec = 0;
  double linear_acceleration[3] = {0, 0, 0};  // m/s^2
};

enum class ImuEncoding { kCdr, kRos1 };

// sensor_msgs/Imu's MD5 in ROS 1 (the md5sum of its definition, as rosbag records it).
inline constexpr std::string_view kRos1ImuMd5 = "6a62c6daae103f4ff57a132d6f95cec2";

// "sensor_msgs/msg/Imu" (ROS 2) or "sensor_msgs/Imu" (ROS 1).
bool IsImuType(std::string_view type);

// How a connection's messages are decoded: from its encoding ("cdr", "ros1"); empty *why
// otherwise with the reason.
bool ImuEncodingOf(const BagConnection& connection, ImuEncoding* encoding, std::string* why);

// Empty when the connection's definition (when the bag holds one: MCAP's schema, ROS 1's
// message_definition and md5sum, Jazzy's message_definitions) is sensor_msgs/Imu as decoded
// here; otherwise what differs, in words.
std::string ImuSchemaMismatch(const BagConnection& connection, ImuEncoding encoding);

// Decodes one message; false with *why (what is wrong with it) for bytes that are not an Imu
// of that encoding, or whose linear_acceleration is not finite.
bool DecodeImu(ImuEncoding encoding, const uint8_t* data, size_t size, ImuReading* out,
               std::string* why);

}  // namespace accelcal::bags
