// From a key to what the TUI does: the mapping of keys to intents, apart from curses so that
// tests drive it with plain codes (docs/STYLE.md: htop's HandlerResult, FTXUI's synthetic events).
//
// Keys: Enter accepts, or submits the typed answer when a value is asked (an empty answer takes
// the default); r retry, s skip, b back, n no, q save and quit. While a value is asked every
// printable key is typed into the answer, so the navigation there uses keys that cannot be
// typed: Esc back (it clears a typed answer first), Ctrl-N skip, Ctrl-X save and quit (Ctrl-S and
// Ctrl-Q are the terminal's flow control, Ctrl-B tmux's prefix); Backspace deletes a character.
// Ctrl-N and Ctrl-X work on every screen. ? and F1 show the help (the keys and what the step
// expects; in a text field too: ? is never part of an answer); any key closes it. PgUp/PgDn and
// the arrows scroll the text lines. On the final screen, any key other than scrolling leaves.
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
  kKeyF1,
};
// Control keys arrive as their ASCII codes.
inline constexpr int kKeyCtrlN = 14;
inline constexpr int kKeyCtrlX = 24;

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
  bool help = false;    // the help overlay is shown (any key closes it)
  bool details = false; // `d` shows the figures behind the capture's message
};

struct KeyOutcome {
  KeyResult result = KeyResult::kIgnored;
  std::optional<Intent> intent;
};

KeyOutcome HandleKey(const WizardView& view, EditState& state, int key);

// The key that sends a KeyHint's intent in the TUI, as the key bar names it: the engine names its
// keys by letter ("s", "b", "q"); in a text field (`text_field`) those letters are typed, so there
// it names the keys above ("Ctrl-N", "Esc", "Ctrl-X"), and nothing for a letter that has no such
// key (it would not work there).
std::string KeyName(const std::string& hint_key, bool text_field);

// Clears the answer and the scroll when `view` is about something else than before.
void SyncEditState(const WizardView& view, EditState& state);

}  // namespace accelcal::ui
