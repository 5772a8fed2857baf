#include "tui/term.h"

#include <csignal>
#include <cstdlib>

#include <curses.h>

#include "tui/keys.h"

namespace accelcal::ui {

namespace {

// Signals after which the process must not leave the terminal in curses mode. SIGWINCH is not
// among them: curses turns it into KEY_RESIZE.
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGSEGV, SIGBUS, SIGFPE, SIGILL,
                            SIGABRT};
struct sigaction g_previous[sizeof(kSignals) / sizeof(kSignals[0])];

// Restores the terminal and dies of the same signal (SA_RESETHAND put back the default
// action), so the parent sees the true cause. endwin is what htop's handler calls as well.
void OnFatalSignal(int signal_number) {
  endwin();
  std::raise(signal_number);
}

void InstallSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = OnFatalSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  for (size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &action, &g_previous[i]);
}

void RestoreSignalHandlers() {
  for (size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

// One colour pair per role (pair number = role + 1), foreground on the default background.
void InitColorPairs() {
  start_color();
  use_default_colors();
  init_pair(1 + static_cast<int>(Role::kNormal), -1, -1);
  init_pair(1 + static_cast<int>(Role::kTitle), COLOR_WHITE, COLOR_BLUE);
  init_pair(1 + static_cast<int>(Role::kPrompt), COLOR_CYAN, -1);
  init_pair(1 + static_cast<int>(Role::kPass), COLOR_GREEN, -1);
  init_pair(1 + static_cast<int>(Role::kFail), COLOR_RED, -1);
  init_pair(1 + static_cast<int>(Role::kWarn), COLOR_YELLOW, -1);
  init_pair(1 + static_cast<int>(Role::kDim), -1, -1);
}

attr_t ColorAttr(Role role) {
  const attr_t pair = COLOR_PAIR(1 + static_cast<int>(role));
  switch (role) {
    case Role::kTitle:
    case Role::kFail:
    case Role::kWarn:
    case Role::kPrompt: return pair | A_BOLD;
    case Role::kDim: return pair | A_DIM;
    default: return pair;
  }
}

// Monochrome: bold, reverse and underline only; the text markers carry the meaning.
attr_t MonoAttr(Role role) {
  switch (role) {
    case Role::kTitle: return A_REVERSE;
    case Role::kPrompt:
    case Role::kFail: return A_BOLD;
    case Role::kWarn: return A_UNDERLINE;
    default: return A_NORMAL;
  }
}

int Translate(int key) {
  switch (key) {
    case ERR: return kKeyNone;
    case '\n':
    case '\r':
    case KEY_ENTER: return kKeyEnter;
    case 27: return kKeyEscape;
    case KEY_BACKSPACE:
    case 127:
    case 8: return kKeyBackspace;
    case KEY_UP: return kKeyUp;
    case KEY_DOWN: return kKeyDown;
    case KEY_PPAGE: return kKeyPageUp;
    case KEY_NPAGE: return kKeyPageDown;
    case KEY_HOME: return kKeyHome;
    case KEY_END: return kKeyEnd;
    case KEY_RESIZE: return kKeyResize;
    case KEY_F(1): return kKeyF1;
    case kKeyCtrlN:
    case kKeyCtrlX: return key;
    default: return (key >= 32 && key < 127) ? key : kKeyNone;
  }
}

}  // namespace

bool ColorRequested() {
  const char* no_color = std::getenv("NO_COLOR");
  return no_color == nullptr || no_color[0] == '\0';
}

CursesTerminal::CursesTerminal(bool color) {
  InstallSignalHandlers();
  initscr();
  cbreak();
  noecho();
  keypad(stdscr, TRUE);
  set_escdelay(25);  // Esc alone should not wait a second for an escape sequence
  curs_set(0);
  color_ = color && has_colors();
  if (color_) InitColorPairs();
}

CursesTerminal::~CursesTerminal() {
  endwin();
  RestoreSignalHandlers();
}

int CursesTerminal::ReadKey(int timeout_ms) {
  timeout(timeout_ms);
  return Translate(getch());
}

int CursesTerminal::Width() const { return COLS; }
int CursesTerminal::Height() const { return LINES; }

void CursesTerminal::Draw(const ScreenModel& screen) {
  if (screen.width() != drawn_width_ || screen.height() != drawn_height_) {
    clearok(stdscr, TRUE);  // after a resize, repaint everything
    drawn_width_ = screen.width();
    drawn_height_ = screen.height();
  }
  erase();
  for (int row = 0; row < screen.height() && row < LINES; ++row) {
    for (int col = 0; col < screen.width() && col < COLS; ++col) {
      const Role role = screen.RoleAt(row, col);
      const attr_t attr = color_ ? ColorAttr(role) : MonoAttr(role);
      // The bottom-right cell is skipped: writing it would scroll the window.
      if (row == LINES - 1 && col == COLS - 1) continue;
      mvaddch(row, col, static_cast<chtype>(static_cast<unsigned char>(screen.CharAt(row, col))) | attr);
    }
  }
  refresh();
}

}  // namespace accelcal::ui
