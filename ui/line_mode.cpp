// The plain line mode: prompts on a stream, one answer per line. For pipes, scripts and
// terminals without curses; `yes '' | accelcal wizard --plain` takes every default.
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "accelcal/base/duration_text.h"
#include "frontend.h"
#include "line_mode_help.h"

namespace accelcal::ui {
namespace {

// A view is busy while the engine works on its own (settling, capturing): poll, don't ask.
bool Busy(const WizardView& v) {
  return (v.screen == WizardScreen::kCapturing || v.screen == WizardScreen::kRecording) && !v.input;
}

// Record time between two progress lines of a record, s.
constexpr double kRecordLineS = 60.0;

Intent ToIntent(const std::string& answer, const WizardView& v) {
  if (answer == "q") return {IntentKind::kQuit, ""};
  if (answer == "r") return {IntentKind::kRetry, ""};
  if (answer == "s") return {IntentKind::kSkip, ""};
  if (answer == "b") return {IntentKind::kBack, ""};
  if (answer == "n" && !v.input) return {IntentKind::kAnswerNo, ""};
  if (answer == "d" && !v.input) return {IntentKind::kDetails, ""};
  if (v.input) return {IntentKind::kSubmitText, answer};
  return {IntentKind::kAccept, ""};
}

std::string TrimLine(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
  size_t start = 0;
  while (start < s.size() && (s[start] == ' ' || s[start] == '\t')) ++start;
  return s.substr(start);
}

// Prints only what changed since the last view, so a busy engine polled many times a second
// gives a few lines per capture, not one per poll.
class Printer {
 public:
  explicit Printer(std::ostream& out) : out_(out) {}

  // What the source noticed, in words, with its figures on a detail line under it. Also called
  // while a question waits: a notice that arrives then is said before the answer acknowledges it.
  // True when it said one.
  bool ShowSourceNotice(const WizardView& v) {
    if (v.source_notice == source_notice_) return false;
    source_notice_ = v.source_notice;
    if (v.source_notice.empty()) return false;
    out_ << "  source: " << v.source_notice << '\n';
    if (!v.source_detail.empty()) out_ << "    detail: " << v.source_detail << '\n';
    return true;
  }

  // A notice said while a question waits: the question's input line again under it, so the
  // output still ends with the question (what a technician, or a script, answers).
  void ShowNoticeWhileAsking(const WizardView& v) {
    if (!ShowSourceNotice(v)) return;
    PrintInputLine(v);
    out_.flush();
  }

  void Show(const WizardView& v) {
    if (v.step_index != step_index_ || v.step_title != step_title_) {
      step_index_ = v.step_index;
      step_title_ = v.step_title;
      out_ << fmt::format("\n[{}/{}] {}\n", v.step_index, v.step_count, v.step_title);
      prompt_.clear();
      progress_quarter_ = -1;
      record_minute_ = -1;
    }
    if (v.lines != lines_) {
      lines_ = v.lines;
      for (const std::string& line : v.lines) out_ << "  " << line << '\n';
    }
    if (v.notice != notice_) {
      notice_ = v.notice;
      if (!v.notice.empty()) out_ << "  " << v.notice << '\n';
    }
    ShowSourceNotice(v);
    if (v.problem != problem_) {
      problem_ = v.problem;
      if (!v.problem.empty()) out_ << "  problem: " << v.problem << '\n';
      if (!v.problem.empty() && !v.detail.empty()) out_ << "    detail: " << v.detail << '\n';
      if (!v.hint.empty()) out_ << "  hint: " << v.hint << '\n';
    }
    Busy(v) ? ShowBusy(v) : ShowQuestion(v);
    out_.flush();
  }

 private:
  void ShowBusy(const WizardView& v) {
    if (v.record) return ShowRecord(v, *v.record);
    // The state word and attempt (the prompt up to ':') change rarely; progress by quarters.
    // The message in words (stability_text) is part of the head: settling that turns into
    // "the bench is shaking" is said when it changes.
    const std::string head = v.prompt.substr(0, v.prompt.find(':')) + "|" + v.stability_text;
    const int quarter = std::isfinite(v.progress) ? static_cast<int>(v.progress * 4.0) : -1;
    const bool capturing = head.rfind("capturing", 0) == 0;
    if (head == prompt_ && (!capturing || quarter <= progress_quarter_)) return;
    prompt_ = head;
    progress_quarter_ = quarter;
    out_ << "  " << v.prompt << '\n';
    // The figures behind the words, and the time, under it; a normal wait (settling after the
    // prism is let go) has nothing to explain: its figures are not printed (issue 27, item 9).
    if (!v.detail.empty() && !v.waiting) out_ << "    detail: " << v.detail << '\n';
    if (!v.time_text.empty()) out_ << "    time: " << v.time_text << '\n';
  }

  // A record: its prompt once (resuming or starting), then one line per minute of record time
  // (a 12-hour record at 100 Hz is 4.3 million samples: never a line per sample or poll).
  void ShowRecord(const WizardView& v, const RecordView& r) {
    const std::string head = v.prompt.substr(0, v.prompt.find(';'));
    if (head != prompt_) {
      prompt_ = head;
      out_ << "  " << head << '\n';
    }
    const long minute = std::lround(std::floor(r.elapsed_s / kRecordLineS));
    if (r.samples == 0 || minute <= record_minute_) return;
    record_minute_ = minute;
    out_ << fmt::format("  recording {} of {} ({:.0f} %): {} samples, {} chunks, gaps {} ({:.0f} s), "
                        "movements {}\n",
                        FormatClock(r.elapsed_s), FormatClock(r.duration_s),
                        r.duration_s > 0 ? 100.0 * r.elapsed_s / r.duration_s : 0.0, r.samples,
                        r.chunks, r.gaps, r.gaps_s, r.bumps);
  }

  void ShowQuestion(const WizardView& v) {
    const std::string error = v.input ? v.input->error : "";
    if (v.prompt != prompt_ || error != error_) {
      prompt_ = v.prompt;
      error_ = error;
      if (!v.prompt.empty()) out_ << v.prompt << '\n';
      if (!v.time_text.empty()) out_ << "  time: " << v.time_text << '\n';
      if (!error.empty()) out_ << "  refused: " << error << '\n';
    }
    PrintInputLine(v);
  }

  void PrintInputLine(const WizardView& v) {
    if (v.input) {
      out_ << fmt::format("{} [{}]> ", v.input->label, v.input->default_text);
    } else if (!v.finished) {
      out_ << "> ";
    }
  }

  std::ostream& out_;
  int step_index_ = -1;
  std::string step_title_;
  std::string prompt_;
  std::string error_;
  std::string problem_;
  std::string notice_;
  std::string source_notice_;
  std::vector<std::string> lines_;
  int progress_quarter_ = -1;
  long record_minute_ = -1;
};

}  // namespace

namespace {

// How long line mode waits for a typed line before it reads the source again, s: while a
// question waits the link is read and what the question does not use dropped, as the full
// screen does, so samples never pile up to be judged by the next capture (issue 27, item 6).
constexpr double kQuestionPollS = 0.05;

// Where the answers come from: a stream (a script's string, always ready), or a file
// descriptor read directly (stdin, the terminal), so that line mode can wait for a line with a
// timeout: a stream's own buffer would hide lines already read from the descriptor.
class LineInput {
 public:
  virtual ~LineInput() = default;
  // A whole line (or the end of input) can be read now; waits up to `timeout_s` for one.
  virtual bool Wait(double timeout_s) = 0;
  // The next line, waiting for it; false at the end of input.
  virtual bool ReadLine(std::string* line) = 0;
};

class StreamInput final : public LineInput {
 public:
  explicit StreamInput(std::istream& in) : in_(in) {}
  bool Wait(double) override { return true; }
  bool ReadLine(std::string* line) override { return static_cast<bool>(std::getline(in_, *line)); }

 private:
  std::istream& in_;
};

class DescriptorInput final : public LineInput {
 public:
  explicit DescriptorInput(int fd) : fd_(fd) {}

  bool Wait(double timeout_s) override {
    if (Ready()) return true;
    pollfd p{fd_, POLLIN, 0};
    const int rc = ::poll(&p, 1, static_cast<int>(std::lround(std::max(0.0, timeout_s) * 1000.0)));
    if (rc < 0 && errno == EINTR) return false;
    if (rc != 0) Fill();  // readable, hung up, or an error (which read() then reports)
    return Ready();
  }

  bool ReadLine(std::string* line) override {
    while (!Wait(1.0)) {
    }
    const size_t end = buffer_.find('\n');
    if (end == std::string::npos && buffer_.empty()) return false;  // the end of input
    *line = buffer_.substr(0, end);
    buffer_.erase(0, end == std::string::npos ? buffer_.size() : end + 1);
    return true;
  }

 private:
  bool Ready() const { return ended_ || buffer_.find('\n') != std::string::npos; }
  void Fill() {
    char bytes[4096];
    const ssize_t n = ::read(fd_, bytes, sizeof bytes);
    if (n > 0) buffer_.append(bytes, static_cast<size_t>(n));
    else if (n == 0 || (errno != EINTR && errno != EAGAIN)) ended_ = true;
  }

  int fd_;
  std::string buffer_;
  bool ended_ = false;
};

// While busy: `q` quits at once; other lines are ignored (said once), so that an Enter pressed
// during a capture does not answer the next question. False at the end of input.
bool ReadWhileBusy(WizardDriver& driver, LineInput& in, std::ostream& out, bool* told) {
  std::string answer;
  if (!in.ReadLine(&answer)) return false;
  if (TrimLine(answer) == "q") {
    driver.Handle({IntentKind::kQuit, ""});
  } else if (!*told) {
    *told = true;
    out << "  (busy: only q is read until the wizard asks)\n";
  }
  return true;
}

// The loop. `read_while_busy`: lines are read while the wizard is busy (a terminal, where `q`
// must be read at once); else only when a question is asked (a pipe: the answers keep order).
int Run(WizardDriver& driver, LineInput& in, std::ostream& out, bool read_while_busy) {
  bool told_busy = false;
  Printer printer(out);
  out << driver.View().procedure << '\n' << "session: " << driver.View().session << '\n';
  while (true) {
    const WizardView v = driver.View();
    printer.Show(v);
    if (v.finished) return 0;
    if (Busy(v)) {
      if (read_while_busy && in.Wait(0.0) && !ReadWhileBusy(driver, in, out, &told_busy))
        read_while_busy = false;  // end of input: the wizard goes on, and quits at its next question
      driver.Poll(0.1);
      continue;
    }
    // A question waits: the source is read meanwhile, so the next capture starts fresh.
    while (!in.Wait(kQuestionPollS)) {
      driver.Poll(0.0);
      printer.ShowNoticeWhileAsking(driver.View());
    }
    std::string answer;
    if (!in.ReadLine(&answer)) {
      // End of input: save and leave (everything accepted is already in the journal).
      out << '\n';
      driver.Handle({IntentKind::kQuit, ""});
      continue;
    }
    out << '\n';
    if (IsHelpRequest(TrimLine(answer))) {
      PrintLineModeHelp(v, out);  // the question is asked again
      continue;
    }
    driver.Handle(ToIntent(TrimLine(answer), v));
    driver.Poll(0.0);
  }
}

}  // namespace

int RunLineMode(WizardDriver& driver, std::istream& in, std::ostream& out) {
  StreamInput input(in);
  return Run(driver, input, out, false);
}

int RunLineModeOn(WizardDriver& driver, int fd, bool terminal, std::ostream& out) {
  DescriptorInput input(fd);
  return Run(driver, input, out, terminal);
}

}  // namespace accelcal::ui
