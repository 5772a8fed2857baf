// Random identifiers for things that must be told apart across computers (a session published to
// a lab's store from several benches): RFC 9562 version 4 UUIDs.
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// A new random UUID, lower-case text: "3f2b8c1e-9d4a-4e6b-8f0c-2a5d7e9b1c34". 122 random bits
// from the system's entropy source (std::random_device, /dev/urandom on Linux).
std::string NewRandomUuid();

// True when `text` is a UUID in that form (8-4-4-4-12 lower-case hex digits).
bool IsUuidText(std::string_view text);

}  // namespace accelcal
