// From a key to what the TUI does: the mapping of keys to intents, apart from curses so that
// tests drive it with plain codes (STYLE.md: htop's HandlerResult, FTXUI's synthetic events).
//
// Keys: Enter accepts, or submits the typed answer when a value is asked (an empty answer takes
// the default); r retry, s skip, b back, n no; q saves and quits at any moment. While a value is
// asked, letters are typed into the answer, so q quits only while the answer is empty (Esc
// clears it first; Backspace deletes a character). PgUp/PgDn and the arrows scroll the text
// lines. On the final screen, any key other than scrolling leaves.
#pragma once

#include <optional>
#include <string>

#include "accelcal/app/wizard/wizard_view.h"

namespace accelcal::ui {

// Codes for the keys that are not printable ASCII (ui/tui/term.cpp translates curses' codes).
enum Key : int {
  kKeyNone = -1,  // no key before the timeout
  kKeyEnter = 0x1000,
  kKeyEscape,
  kKeyBackspace,
  kKeyUp,
  kKeyDown,
  kKeyPageUp,
  kKeyPageDown,
  kKeyHome,
  kKeyEnd,
  kKeyResize,
};

// What the loop does after a key.
enum class KeyResult {
  kIgnored,  // nothing
  kRedraw,   // the front end's own state changed (answer text, scroll, size): draw again
  kIntent,   // send the intent to the driver
  kExit,     // leave the loop (the final screen was seen)
};

// The front end's own state: the answer being typed and the scroll of the text lines. It is
// reset when the step, the screen or the value asked changes (SyncEditState).
struct EditState {
  std::string text;
  int scroll = 0;
  int page = 10;        // rows the text lines get, for PgUp/PgDn (set by the loop)
  int width = 0;        // the screen's width, to count the wrapped text lines (set by the loop)
  std::string context;  // what the state belongs to
};

struct KeyOutcome {
  KeyResult result = KeyResult::kIgnored;
  std::optional<Intent> intent;
};

KeyOutcome HandleKey(const WizardView& view, EditState& state, int key);

// Clears the answer and the scroll when `view` is about something else than before.
void SyncEditState(const WizardView& view, EditState& state);

}  // namespace accelcal::ui
