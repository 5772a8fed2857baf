// What goes wrong with the lab's store, with PostgreSQL's own SQLSTATE (appendix A of its
// manual) kept, so that a caller and a test can tell a refusal by the database (42501: a grant,
// a row-level security policy or one of the schema's rules said no) from a store that cannot be
// reached (class 08) or anything else. what() is one line for the technician.
#pragma once

#include <string>

#include "accelcal/base/error.h"

namespace accelcal {

// SQLSTATEs accelcal tells apart.
inline constexpr const char* kSqlStateRefused = "42501";         // insufficient_privilege
inline constexpr const char* kSqlStateUnreachable = "08001";     // could not connect (set by us)
inline constexpr const char* kSqlStateConnectionLost = "08006";  // connection failure mid-way

class LabError : public Error {
 public:
  LabError(const std::string& message, std::string sqlstate)
      : Error(message), sqlstate_(std::move(sqlstate)) {}

  // Five characters; empty when the failure is not the database's (a malformed reply).
  const std::string& sqlstate() const { return sqlstate_; }
  // The database refused: a role without the grant, a row the policy does not allow, a rule.
  bool refused() const { return sqlstate_ == kSqlStateRefused; }
  // No answer from the store, before or during the work (class 08: connection exceptions).
  bool unreachable() const { return sqlstate_.rfind("08", 0) == 0; }

 private:
  std::string sqlstate_;
};

}  // namespace accelcal
