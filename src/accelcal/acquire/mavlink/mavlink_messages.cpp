#include "accelcal/acquire/mavlink/mavlink_messages.h"

#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "accelcal/acquire/mavlink/x25_crc.h"

namespace accelcal::mavlink {
namespace {

// The fields in wire order, copied by hand from common.xml / minimal.xml (see the header for
// the ordering rule). The CRC_EXTRA beside each is what mavgen computes from the definition;
// ComputeCrcExtra recomputes it (tests), node-mavlink's magic-numbers table agrees (e2e).
std::vector<MessageSpec> BuildTable() {
  const FieldSpec kImu9[] = {
      {"int16_t", "xacc", 0, false},  {"int16_t", "yacc", 0, false},  {"int16_t", "zacc", 0, false},
      {"int16_t", "xgyro", 0, false}, {"int16_t", "ygyro", 0, false}, {"int16_t", "zgyro", 0, false},
      {"int16_t", "xmag", 0, false},  {"int16_t", "ymag", 0, false},  {"int16_t", "zmag", 0, false}};
  auto scaled = [&](std::uint32_t id, const char* name, std::uint8_t extra) {
    MessageSpec m{id, name, extra, {{"uint32_t", "time_boot_ms", 0, false}}, 0, 0};
    m.fields.insert(m.fields.end(), std::begin(kImu9), std::end(kImu9));
    m.fields.push_back({"int16_t", "temperature", 0, true});
    return m;
  };
  std::vector<MessageSpec> t;
  // minimal.xml
  t.push_back({kHeartbeat, "HEARTBEAT", 50,
               {{"uint32_t", "custom_mode", 0, false}, {"uint8_t", "type", 0, false},
                {"uint8_t", "autopilot", 0, false}, {"uint8_t", "base_mode", 0, false},
                {"uint8_t", "system_status", 0, false}, {"uint8_t", "mavlink_version", 0, false}},
               0, 0});
  // common.xml
  t.push_back({kParamRequestRead, "PARAM_REQUEST_READ", 214,
               {{"int16_t", "param_index", 0, false}, {"uint8_t", "target_system", 0, false},
                {"uint8_t", "target_component", 0, false}, {"char", "param_id", 16, false}},
               0, 0});
  t.push_back({kParamRequestList, "PARAM_REQUEST_LIST", 159,
               {{"uint8_t", "target_system", 0, false}, {"uint8_t", "target_component", 0, false}},
               0, 0});
  t.push_back({kParamValue, "PARAM_VALUE", 220,
               {{"float", "param_value", 0, false}, {"uint16_t", "param_count", 0, false},
                {"uint16_t", "param_index", 0, false}, {"char", "param_id", 16, false},
                {"uint8_t", "param_type", 0, false}},
               0, 0});
  t.push_back({kParamSet, "PARAM_SET", 168,
               {{"float", "param_value", 0, false}, {"uint8_t", "target_system", 0, false},
                {"uint8_t", "target_component", 0, false}, {"char", "param_id", 16, false},
                {"uint8_t", "param_type", 0, false}},
               0, 0});
  t.push_back(scaled(kScaledImu, "SCALED_IMU", 170));
  MessageSpec raw{kRawImu, "RAW_IMU", 144, {{"uint64_t", "time_usec", 0, false}}, 0, 0};
  raw.fields.insert(raw.fields.end(), std::begin(kImu9), std::end(kImu9));
  raw.fields.push_back({"uint8_t", "id", 0, true});
  raw.fields.push_back({"int16_t", "temperature", 0, true});
  t.push_back(raw);
  t.push_back({kRequestDataStream, "REQUEST_DATA_STREAM", 148,
               {{"uint16_t", "req_message_rate", 0, false}, {"uint8_t", "target_system", 0, false},
                {"uint8_t", "target_component", 0, false}, {"uint8_t", "req_stream_id", 0, false},
                {"uint8_t", "start_stop", 0, false}},
               0, 0});
  MessageSpec command{kCommandLong, "COMMAND_LONG", 152, {}, 0, 0};
  for (const char* p : {"param1", "param2", "param3", "param4", "param5", "param6", "param7"})
    command.fields.push_back({"float", p, 0, false});
  command.fields.push_back({"uint16_t", "command", 0, false});
  command.fields.push_back({"uint8_t", "target_system", 0, false});
  command.fields.push_back({"uint8_t", "target_component", 0, false});
  command.fields.push_back({"uint8_t", "confirmation", 0, false});
  t.push_back(command);
  t.push_back({kCommandAck, "COMMAND_ACK", 143,
               {{"uint16_t", "command", 0, false}, {"uint8_t", "result", 0, false},
                {"uint8_t", "progress", 0, true}, {"int32_t", "result_param2", 0, true},
                {"uint8_t", "target_system", 0, true}, {"uint8_t", "target_component", 0, true}},
               0, 0});
  MessageSpec highres{kHighresImu, "HIGHRES_IMU", 93, {{"uint64_t", "time_usec", 0, false}}, 0, 0};
  for (const char* f : {"xacc", "yacc", "zacc", "xgyro", "ygyro", "zgyro", "xmag", "ymag", "zmag",
                        "abs_pressure", "diff_pressure", "pressure_alt", "temperature"})
    highres.fields.push_back({"float", f, 0, false});
  highres.fields.push_back({"uint16_t", "fields_updated", 0, false});
  highres.fields.push_back({"uint8_t", "id", 0, true});
  t.push_back(highres);
  t.push_back(scaled(kScaledImu2, "SCALED_IMU2", 76));
  t.push_back(scaled(kScaledImu3, "SCALED_IMU3", 46));
  t.push_back({kStatustext, "STATUSTEXT", 83,
               {{"uint8_t", "severity", 0, false}, {"char", "text", 50, false},
                {"uint16_t", "id", 0, true}, {"uint8_t", "chunk_seq", 0, true}},
               0, 0});
  for (MessageSpec& m : t) {
    for (const FieldSpec& f : m.fields) {
      const int bytes = TypeSize(f.type) * (f.array_length > 0 ? f.array_length : 1);
      if (!f.extension) m.base_length += bytes;
      m.max_length += bytes;
    }
  }
  return t;
}

// Little-endian reads and writes at a byte offset of a payload (MAVLink is little-endian).
template <typename T>
T GetLe(const Payload& p, size_t offset) {
  T value{};
  if (offset + sizeof(T) <= p.size()) std::memcpy(&value, p.data() + offset, sizeof(T));
  return value;
}

template <typename T>
void PutLe(Payload* p, size_t offset, T value) {
  std::memcpy(p->data() + offset, &value, sizeof(T));
}

std::string GetText(const Payload& p, size_t offset, size_t max_chars) {
  std::string text;
  for (size_t i = 0; i < max_chars && offset + i < p.size() && p[offset + i] != 0; ++i)
    text += static_cast<char>(p[offset + i]);
  return text;
}

void PutText(Payload* p, size_t offset, std::string_view text, size_t max_chars) {
  for (size_t i = 0; i < max_chars && i < text.size(); ++i) (*p)[offset + i] = static_cast<std::uint8_t>(text[i]);
}

double CentiDegC(std::int16_t value) {
  return value == 0 ? std::numeric_limits<double>::quiet_NaN() : value / 100.0;
}

}  // namespace

const std::vector<MessageSpec>& KnownMessages() {
  static const std::vector<MessageSpec> table = BuildTable();
  return table;
}

const MessageSpec* FindMessage(std::uint32_t id) {
  for (const MessageSpec& m : KnownMessages())
    if (m.id == id) return &m;
  return nullptr;
}

int TypeSize(std::string_view type) {
  if (type == "uint64_t" || type == "int64_t" || type == "double") return 8;
  if (type == "uint32_t" || type == "int32_t" || type == "float") return 4;
  if (type == "uint16_t" || type == "int16_t") return 2;
  return 1;  // uint8_t, int8_t, char
}

std::uint8_t ComputeCrcExtra(const MessageSpec& spec) {
  X25Crc crc;
  crc.Add(std::string(spec.name) + " ");
  for (const FieldSpec& f : spec.fields) {
    if (f.extension) continue;
    crc.Add(std::string(f.type) + " " + f.name + " ");
    if (f.array_length > 0) crc.Add(static_cast<std::uint8_t>(f.array_length));
  }
  return static_cast<std::uint8_t>((crc.value() & 0xFF) ^ (crc.value() >> 8));
}

std::string CommandResultText(std::uint8_t result) {
  switch (result) {  // common.xml MAV_RESULT
    case 0: return "accepted";
    case 1: return "temporarily rejected";
    case 2: return "denied";
    case 3: return "unsupported";
    case 4: return "failed";
    case 5: return "in progress";
    case 6: return "cancelled";
  }
  return fmt::format("result {}", result);
}

std::string AutopilotName(std::uint8_t autopilot) {
  switch (autopilot) {
    case kAutopilotGeneric: return "a generic autopilot";
    case kAutopilotArduPilot: return "ArduPilot";
    case kAutopilotPx4: return "PX4";
    case kAutopilotInvalid: return "not an autopilot";
  }
  return fmt::format("autopilot type {}", autopilot);
}

std::string MessageName(std::uint32_t id) {
  const MessageSpec* m = FindMessage(id);
  return m != nullptr ? std::string(m->name) : fmt::format("message {}", id);
}

Heartbeat DecodeHeartbeat(const Payload& p) {
  Heartbeat h;
  h.custom_mode = GetLe<std::uint32_t>(p, 0);
  h.type = GetLe<std::uint8_t>(p, 4);
  h.autopilot = GetLe<std::uint8_t>(p, 5);
  h.base_mode = GetLe<std::uint8_t>(p, 6);
  h.system_status = GetLe<std::uint8_t>(p, 7);
  h.mavlink_version = GetLe<std::uint8_t>(p, 8);
  return h;
}

std::optional<ImuReading> DecodeImu(std::uint32_t message_id, const Payload& p) {
  ImuReading r;
  r.message = message_id;
  switch (message_id) {
    case kHighresImu:
      r.time_s = static_cast<double>(GetLe<std::uint64_t>(p, 0)) / 1e6;
      for (int j = 0; j < 3; ++j) r.acc[static_cast<size_t>(j)] = GetLe<float>(p, 8 + 4 * static_cast<size_t>(j));
      r.temp_c = (GetLe<std::uint16_t>(p, 60) & kHighresTemperatureUpdated) != 0
                     ? static_cast<double>(GetLe<float>(p, 56))
                     : std::numeric_limits<double>::quiet_NaN();
      r.instance = GetLe<std::uint8_t>(p, 62);
      return r;
    case kScaledImu:
    case kScaledImu2:
    case kScaledImu3:
      r.time_s = GetLe<std::uint32_t>(p, 0) / 1e3;
      for (int j = 0; j < 3; ++j) r.acc[static_cast<size_t>(j)] = GetLe<std::int16_t>(p, 4 + 2 * static_cast<size_t>(j));
      r.temp_c = CentiDegC(GetLe<std::int16_t>(p, 22));
      r.instance = message_id == kScaledImu ? 0 : message_id == kScaledImu2 ? 1 : 2;
      return r;
    case kRawImu:
      r.time_s = static_cast<double>(GetLe<std::uint64_t>(p, 0)) / 1e6;
      for (int j = 0; j < 3; ++j) r.acc[static_cast<size_t>(j)] = GetLe<std::int16_t>(p, 8 + 2 * static_cast<size_t>(j));
      r.instance = GetLe<std::uint8_t>(p, 26);
      r.temp_c = CentiDegC(GetLe<std::int16_t>(p, 27));
      return r;
  }
  return std::nullopt;
}

ParamValue DecodeParamValue(const Payload& p) {
  ParamValue v;
  v.value = GetLe<float>(p, 0);
  v.count = GetLe<std::uint16_t>(p, 4);
  v.index = GetLe<std::uint16_t>(p, 6);
  v.id = GetText(p, 8, 16);
  v.type = GetLe<std::uint8_t>(p, 24);
  return v;
}

CommandAck DecodeCommandAck(const Payload& p) {
  return {GetLe<std::uint16_t>(p, 0), GetLe<std::uint8_t>(p, 2)};
}

std::string DecodeStatustext(const Payload& p, std::uint8_t* severity) {
  if (severity != nullptr) *severity = GetLe<std::uint8_t>(p, 0);
  return GetText(p, 1, 50);
}

Payload EncodeHeartbeat(const Heartbeat& h) {
  Payload p(9, 0);
  PutLe(&p, 0, h.custom_mode);
  p[4] = h.type;
  p[5] = h.autopilot;
  p[6] = h.base_mode;
  p[7] = h.system_status;
  p[8] = h.mavlink_version;
  return p;
}

Payload EncodeParamRequestRead(std::uint8_t system, std::uint8_t component, std::string_view id) {
  Payload p(20, 0);
  PutLe<std::int16_t>(&p, 0, -1);  // by name, not by index
  p[2] = system;
  p[3] = component;
  PutText(&p, 4, id, 16);
  return p;
}

Payload EncodeParamRequestList(std::uint8_t system, std::uint8_t component) {
  return {system, component};
}

Payload EncodeParamSet(std::uint8_t system, std::uint8_t component, std::string_view id,
                       float value, std::uint8_t type) {
  Payload p(23, 0);
  PutLe(&p, 0, value);
  p[4] = system;
  p[5] = component;
  PutText(&p, 6, id, 16);
  p[22] = type;
  return p;
}

Payload EncodeCommandLong(std::uint8_t system, std::uint8_t component, std::uint16_t command,
                          const std::array<float, 7>& params) {
  Payload p(33, 0);
  for (size_t i = 0; i < 7; ++i) PutLe(&p, 4 * i, params[i]);
  PutLe(&p, 28, command);
  p[30] = system;
  p[31] = component;
  p[32] = 0;  // confirmation
  return p;
}

Payload EncodeRequestDataStream(std::uint8_t system, std::uint8_t component,
                                std::uint8_t stream_id, std::uint16_t rate_hz, bool start) {
  Payload p(6, 0);
  PutLe(&p, 0, rate_hz);
  p[2] = system;
  p[3] = component;
  p[4] = stream_id;
  p[5] = start ? 1 : 0;
  return p;
}

double ParamNumber(const ParamValue& v, bool bytewise) {
  if (v.type == kParamTypeReal32 || !bytewise) return static_cast<double>(v.value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v.value, sizeof bits);
  switch (v.type) {
    case kParamTypeUint8: return static_cast<std::uint8_t>(bits);
    case kParamTypeInt8: return static_cast<std::int8_t>(bits);
    case kParamTypeUint16: return static_cast<std::uint16_t>(bits);
    case kParamTypeInt16: return static_cast<std::int16_t>(bits);
    case kParamTypeUint32: return bits;
    case kParamTypeInt32: return static_cast<std::int32_t>(bits);
  }
  return static_cast<double>(v.value);
}

float ParamWireFloat(double value, std::uint8_t type, bool bytewise) {
  if (type == kParamTypeReal32 || !bytewise) return static_cast<float>(value);
  std::uint32_t bits = 0;
  switch (type) {
    case kParamTypeUint8: bits = static_cast<std::uint8_t>(std::lround(value)); break;
    case kParamTypeInt8: bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(static_cast<std::int8_t>(std::lround(value)))) & 0xFFu; break;
    case kParamTypeUint16: bits = static_cast<std::uint16_t>(std::lround(value)); break;
    case kParamTypeInt16: bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(static_cast<std::int16_t>(std::lround(value)))) & 0xFFFFu; break;
    case kParamTypeUint32: bits = static_cast<std::uint32_t>(std::llround(value)); break;
    default: bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::llround(value))); break;
  }
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace accelcal::mavlink
