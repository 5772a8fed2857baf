// Publishing a bench's finished sessions to the lab's store (lab/lab_store.h, docs/lab.md):
// `accelcal lab publish [SESSION...]`, and the wizard's offer at the end of a session.
//
// A session is published whole or not at all, keyed by its UUID: a second publish (a retry after
// a lost connection, a copy of the file, two benches racing) finds it and changes nothing. Once
// the store has committed it, the lab's certificate number is written back into the session
// (SessionStore::RecordLabCertificate) and the certificate beside the session
// (SESSION.report.html, .txt) is rewritten as the lab stored it, its number on it. A publisher
// killed between the two leaves the session unmarked: the next publish finds it in the store
// and writes the number then.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accelcal/lab/lab_store.h"
#include "accelcal/session/session_store.h"

namespace accelcal {

struct SessionPublishOutcome {
  enum class Kind {
    kPublished,         // taken by the store now
    kAlreadyPublished,  // the store held it already (its numbers written back if missing)
    kNotReady,          // not finished, or no calibration: nothing to publish yet
    kFailed,            // refused or cut off: nothing of it in the store; try again later
  };
  Kind kind = Kind::kFailed;
  std::string path;
  std::string name;
  std::vector<std::string> certificate_numbers;  // by sensor
  std::vector<std::string> files_written;        // the certificate beside the session
  std::string message;                           // plain words, one line
  bool lab_unreachable = false;                  // kFailed because the store cannot be reached
};

// Publishes the session `store` holds, opened read-write (the numbers are written back). Never
// throws for the session's own problems: they are the outcome's. `default_procedure_path` gives
// the certificate's limits and equipment as `accelcal report` does (app/report_metadata.h).
SessionPublishOutcome PublishSession(LabStore& lab, SessionStore& store,
                                     const std::string& default_procedure_path);

// Opens each session file read-write and publishes it, in order. Once the store is unreachable,
// the rest are not tried (each says so): a bench offline publishes its backlog next time.
std::vector<SessionPublishOutcome> PublishSessionFiles(LabStore& lab, const std::vector<std::string>& paths,
                                                       const std::string& default_procedure_path);

// The backlog of `dir`: its sessions that are finished, hold a calibration and carry no lab
// certificate number yet, by creation time. Throws accelcal::Error when `dir` cannot be read.
std::vector<std::string> UnpublishedSessions(const std::string& dir);

// The wizard's end: publishes the session just finished when this bench is pointed at a lab
// (LabConfigured()), given kLabQuickConnectTimeoutS to answer; nullopt when it is not. A store that cannot be reached is an outcome
// (kFailed, lab_unreachable), never an exception: the session waits in the backlog.
std::optional<SessionPublishOutcome> PublishIfLabConfigured(SessionStore& store,
                                                            const std::string& default_procedure_path);

// "published as LAB-000042", "already in the lab's register as LAB-000042", "not finished: ...",
// "not published: ..."; one line per outcome, for the command line and the wizard.
std::string DescribeOutcome(const SessionPublishOutcome& outcome);

}  // namespace accelcal
