#include "tui/keys.h"

#include <algorithm>
#include <cctype>

#include "tui/capture_blocks.h"
#include "tui/text_util.h"

namespace accelcal::ui {

namespace {

KeyOutcome Send(IntentKind kind, std::string text = {}) {
  return {KeyResult::kIntent, Intent{kind, std::move(text)}};
}

bool IsPrintable(int key) { return key >= 32 && key < 127; }

// Scrolling works on every screen; returns nothing for other keys.
std::optional<KeyOutcome> Scroll(const WizardView& view, EditState& state, int key) {
  const int last = std::max(static_cast<int>(ScreenTextLines(view, state.width).size()) - 1, 0);
  int to = state.scroll;
  switch (key) {
    case kKeyUp: to -= 1; break;
    case kKeyDown: to += 1; break;
    case kKeyPageUp: to -= std::max(state.page - 1, 1); break;
    case kKeyPageDown: to += std::max(state.page - 1, 1); break;
    case kKeyHome: to = 0; break;
    case kKeyEnd: to = last; break;
    default: return std::nullopt;
  }
  state.scroll = std::clamp(to, 0, last);
  return KeyOutcome{KeyResult::kRedraw, std::nullopt};
}

// Keys that mean the same on every screen, text field or not; nothing for other keys.
std::optional<KeyOutcome> AnywhereKey(EditState& state, int key) {
  switch (key) {
    case kKeyF1:
    case '?':
      state.help = true;
      return KeyOutcome{KeyResult::kRedraw, std::nullopt};
    case kKeyCtrlN: return Send(IntentKind::kSkip);
    case kKeyCtrlX: return Send(IntentKind::kQuit);
    default: return std::nullopt;
  }
}

KeyOutcome EditKey(EditState& state, int key) {
  switch (key) {
    case kKeyEnter: {
      std::string text = std::move(state.text);
      state.text.clear();
      return Send(IntentKind::kSubmitText, std::move(text));
    }
    case kKeyEscape:
      if (state.text.empty()) return Send(IntentKind::kBack);
      state.text.clear();
      return {KeyResult::kRedraw, std::nullopt};
    case kKeyBackspace:
      if (!state.text.empty()) state.text.pop_back();
      return {KeyResult::kRedraw, std::nullopt};
    default: break;
  }
  if (IsPrintable(key)) {
    state.text += static_cast<char>(key);
    return {KeyResult::kRedraw, std::nullopt};
  }
  return {};
}

KeyOutcome CommandKey(int key) {
  if (key == kKeyEnter) return Send(IntentKind::kAccept);
  if (!IsPrintable(key)) return {};
  switch (std::tolower(key)) {
    case 'q': return Send(IntentKind::kQuit);
    case 'r': return Send(IntentKind::kRetry);
    case 's': return Send(IntentKind::kSkip);
    case 'b': return Send(IntentKind::kBack);
    case 'n': return Send(IntentKind::kAnswerNo);
    case 'd': return Send(IntentKind::kDetails);
    default: return {};
  }
}

}  // namespace

KeyOutcome HandleKey(const WizardView& view, EditState& state, int key) {
  if (key == kKeyNone) return {};
  if (key == kKeyResize) return {KeyResult::kRedraw, std::nullopt};
  if (state.help) {
    state.help = false;  // the key only closes the help
    return {KeyResult::kRedraw, std::nullopt};
  }
  if (auto scrolled = Scroll(view, state, key)) return *scrolled;
  if (view.finished) return {KeyResult::kExit, std::nullopt};
  if (auto anywhere = AnywhereKey(state, key)) return *anywhere;
  // The figures behind a message (std, limits, sigmas): one key away, never on the main line.
  // A toggle that holds from screen to screen, so a key pressed as the screen changes still
  // counts (the keys line offers it only where there are figures).
  // Where the engine offers d itself (the statistics behind the diagnosis), it goes to the engine.
  const bool engine_d = std::any_of(view.keys.begin(), view.keys.end(),
                                    [](const KeyHint& hint) { return hint.key == "d"; });
  if (!view.input && !engine_d && (key == 'd' || key == 'D')) {
    state.details = !state.details;
    return {KeyResult::kRedraw, std::nullopt};
  }
  return view.input ? EditKey(state, key) : CommandKey(key);
}

std::string KeyName(const std::string& hint_key, bool text_field) {
  if (!text_field || hint_key == "Enter") return hint_key;
  if (hint_key == "s") return "Ctrl-N";
  if (hint_key == "b") return "Esc";
  if (hint_key == "q") return "Ctrl-X";
  return "";
}

void SyncEditState(const WizardView& view, EditState& state) {
  std::string context = std::to_string(view.step_index) + "/" +
                        std::string(WizardScreenToString(view.screen)) + "/" +
                        (view.input ? view.input->key : std::string("-"));
  if (context == state.context) return;
  state.context = std::move(context);
  state.text.clear();
  state.scroll = 0;
  state.help = false;
}

}  // namespace accelcal::ui
