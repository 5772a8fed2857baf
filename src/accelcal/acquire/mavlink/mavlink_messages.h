// The few MAVLink messages accelcal reads or sends, written from the published definitions
// (message_definitions/v1.0/common.xml and minimal.xml of the mavlink/mavlink repository): our
// own small table, no generated code. Each message's fields are listed in wire order, which is
// not the XML's: MAVLink sorts the base fields by type size (8-byte first, stable), then appends
// the extension fields in XML order, unsorted.
//
// CRC_EXTRA (the "seed" mixed into each frame's checksum so that two ends with different
// definitions of a message reject each other's frames): computed by mavgen's rule from the
// definition, an X.25 CRC over "NAME " and, per base field in wire order, "type name " and the
// array length byte of an array, folded to 8 bits as (crc & 0xFF) ^ (crc >> 8). The values in
// the table are those; tests/unit/mavlink_messages_test.cpp recomputes each from the field list
// here, and the e2e tests prove them against node-mavlink (an implementation generated
// elsewhere from the same XML), which checks every frame we send and sends every frame we read.
//
// Units as the XML gives them: HIGHRES_IMU accelerations float m/s^2, SCALED_IMU* int16 mG
// (milli standard gravity), RAW_IMU int16 in the sensor's own units, temperatures degC (float)
// or cdegC (int16, 0 meaning "not provided").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace accelcal::mavlink {

// Message ids (common.xml / minimal.xml).
enum MessageId : std::uint32_t {
  kHeartbeat = 0,
  kParamRequestRead = 20,
  kParamRequestList = 21,
  kParamValue = 22,
  kParamSet = 23,
  kScaledImu = 26,
  kRawImu = 27,
  kRequestDataStream = 66,
  kCommandLong = 76,
  kCommandAck = 77,
  kHighresImu = 105,
  kScaledImu2 = 116,
  kScaledImu3 = 129,
  kStatustext = 253,
};

// A field of a message as our table knows it.
struct FieldSpec {
  const char* type;  // "uint64_t", "float", "char", ...
  const char* name;
  int array_length;  // 0: not an array
  bool extension;    // after <extensions/> in the XML
};

struct MessageSpec {
  std::uint32_t id;
  const char* name;
  std::uint8_t crc_extra;
  std::vector<FieldSpec> fields;  // wire order
  int base_length;  // payload bytes without the extension fields (a v1 frame's exact length)
  int max_length;   // with them (a v2 frame's longest payload)
};

// The table entry of `id`; nullptr for a message accelcal does not read or send.
const MessageSpec* FindMessage(std::uint32_t id);
// Every entry, for tests.
const std::vector<MessageSpec>& KnownMessages();
// Bytes of one element of a MAVLink type ("float" -> 4).
int TypeSize(std::string_view type);
// CRC_EXTRA by mavgen's rule from a message's name and wire-ordered fields.
std::uint8_t ComputeCrcExtra(const MessageSpec& spec);

// MAV_AUTOPILOT values the vehicle's HEARTBEAT names (common.xml MAV_AUTOPILOT).
constexpr std::uint8_t kAutopilotGeneric = 0;
constexpr std::uint8_t kAutopilotArduPilot = 3;
constexpr std::uint8_t kAutopilotInvalid = 8;  // not a flight controller (a GCS, a companion)
constexpr std::uint8_t kAutopilotPx4 = 12;
// MAV_TYPE_GCS: what our own heartbeat says we are.
constexpr std::uint8_t kTypeGcs = 6;
// MAV_CMD_SET_MESSAGE_INTERVAL (common.xml): param1 message id, param2 interval in us.
constexpr std::uint16_t kCmdSetMessageInterval = 511;
// MAV_DATA_STREAM_RAW_SENSORS (REQUEST_DATA_STREAM's group with RAW_IMU and SCALED_IMU2/3).
constexpr std::uint8_t kDataStreamRawSensors = 1;
// MAV_PARAM_TYPE values.
constexpr std::uint8_t kParamTypeUint8 = 1, kParamTypeInt8 = 2, kParamTypeUint16 = 3,
                       kParamTypeInt16 = 4, kParamTypeUint32 = 5, kParamTypeInt32 = 6,
                       kParamTypeReal32 = 9;
// HIGHRES_IMU fields_updated bit of the temperature (HIGHRES_IMU_UPDATED_FLAGS).
constexpr std::uint16_t kHighresTemperatureUpdated = 4096;

// "MAV_RESULT_ACCEPTED" -> "accepted" etc. for a COMMAND_ACK's result.
std::string CommandResultText(std::uint8_t result);
// "ArduPilot", "PX4", "autopilot type 7".
std::string AutopilotName(std::uint8_t autopilot);
// The message's name ("HIGHRES_IMU"), or "message 12345" for one outside the table.
std::string MessageName(std::uint32_t id);

// ---- Decoded messages (payload already zero-filled to the message's full length). ----

struct Heartbeat {
  std::uint8_t type = 0, autopilot = 0, base_mode = 0, system_status = 0, mavlink_version = 0;
  std::uint32_t custom_mode = 0;
};

// One accelerometer reading of an IMU message, in the message's own units.
struct ImuReading {
  std::uint32_t message = 0;  // kHighresImu, kScaledImu, kScaledImu2, kScaledImu3, kRawImu
  int instance = 0;           // the IMU: the id field, or 0/1/2 for SCALED_IMU/2/3
  double time_s = 0.0;        // the vehicle's time stamp (time_usec or time_boot_ms), s
  std::array<double, 3> acc{};  // m/s^2 (HIGHRES), mG (SCALED), sensor units (RAW)
  double temp_c = 0.0;        // NaN when the message says none
};

struct ParamValue {
  std::string id;  // up to 16 characters
  float value = 0.0f;
  std::uint8_t type = 0;
  std::uint16_t count = 0;
  std::uint16_t index = 0;
};

struct CommandAck {
  std::uint16_t command = 0;
  std::uint8_t result = 0;
};

using Payload = std::vector<std::uint8_t>;

Heartbeat DecodeHeartbeat(const Payload& p);
// nullopt for a message that carries no IMU reading.
std::optional<ImuReading> DecodeImu(std::uint32_t message_id, const Payload& p);
ParamValue DecodeParamValue(const Payload& p);
CommandAck DecodeCommandAck(const Payload& p);
std::string DecodeStatustext(const Payload& p, std::uint8_t* severity);

// Encoders of what we send (full-length payloads; the frame writer trims trailing zeros in v2).
Payload EncodeHeartbeat(const Heartbeat& h);
Payload EncodeParamRequestRead(std::uint8_t system, std::uint8_t component, std::string_view id);
Payload EncodeParamRequestList(std::uint8_t system, std::uint8_t component);
Payload EncodeParamSet(std::uint8_t system, std::uint8_t component, std::string_view id,
                       float value, std::uint8_t type);
Payload EncodeCommandLong(std::uint8_t system, std::uint8_t component, std::uint16_t command,
                          const std::array<float, 7>& params);
Payload EncodeRequestDataStream(std::uint8_t system, std::uint8_t component,
                                std::uint8_t stream_id, std::uint16_t rate_hz, bool start);

// A parameter's value as a number: REAL32 as it is; integer types as ArduPilot sends them (the
// integer converted to float) unless `bytewise` (PX4's MAV_PROTOCOL_CAPABILITY_PARAM_ENCODE_
// BYTEWISE: the integer's bytes in the float's place).
double ParamNumber(const ParamValue& v, bool bytewise);
// The float to put in PARAM_SET for `value` of `type`, by the same rule.
float ParamWireFloat(double value, std::uint8_t type, bool bytewise);

}  // namespace accelcal::mavlink
