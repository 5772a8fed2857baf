// The welcome's equipment question: the procedure's [equipment] as the operator finds it on
// the bench, edited in one line. Empty or "keep" keeps the procedure's; otherwise items separated by
// ';', each a role (ruler, turntable, level, prism) and what changes: "id TEXT" (one word),
// "u NUMBER" in the procedure file's unit (mm, %, deg) and "cal TEXT" (one word: the item's
// calibration certificate, which makes it verified: session/equipment.h):
//     ruler id RUL-07 u 0.4 cal C-2291; turntable u 0.3
// Recorded as the welcome's input "equipment" (as typed), read again on a resume and by
// `accelcal report`, so every rendering lists the same items.
#pragma once

#include <string>
#include <vector>

#include "accelcal/session/equipment.h"

namespace accelcal {

struct EquipmentAnswer {
  std::vector<EquipmentItem> items;  // the procedure's with the edits applied
  std::string error;                 // empty when the answer was understood
  bool ok() const { return error.empty(); }
};

// `answer` applied to `items` (an item of a role the procedure does not list is added).
EquipmentAnswer ApplyEquipmentAnswer(const std::string& answer, std::vector<EquipmentItem> items);

// One line for the question's default: "ruler RUL-01 0.5 mm; turntable TT-01 0.2 %; ...".
std::string DescribeEquipment(const std::vector<EquipmentItem>& items);

// The welcome's question: the equipment the default answer gives (the procedure's, or the
// procedure's with `offered` applied: the virtual bench's lab), and that default ("keep" when
// nothing is offered).
struct EquipmentQuestionText {
  std::string label;
  std::string default_answer;
};
EquipmentQuestionText EquipmentQuestion(const std::vector<EquipmentItem>& procedure_items,
                                        const std::string& offered);

// What the session records for `typed` when `default_answer` was offered: an edit applies to
// what the question showed, so it is recorded after the default ("DEFAULT; TYPED": a later
// segment wins), and `accelcal report` re-applies the same to the procedure's list.
std::string EquipmentAnswerOver(const std::string& default_answer, const std::string& typed);

}  // namespace accelcal
