// Line mode reads the source while a question waits (issue 27, item 6): the answers come from a
// file descriptor waited on with a timeout, and the driver is polled meanwhile, as the full
// screen polls it; lines that arrive together are each answered in order without waiting.
#include <unistd.h>

#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "accelcal/app/wizard/wizard_driver.h"
#include "frontend.h"

namespace accelcal {
namespace {

// `questions` text questions in a row, then finished; counts the polls while each waited.
class Questions final : public WizardDriver {
 public:
  explicit Questions(int questions) : left_(questions) {}
  void Poll(double) override {
    if (left_ > 0) ++polls_;
  }
  void Handle(const Intent& intent) override {
    answers_.push_back(intent.text);
    polls_per_answer_.push_back(polls_);
    polls_ = 0;
    --left_;
  }
  WizardView View() const override {
    WizardView v;
    v.step_title = "question";
    v.prompt = "Answer, please";
    v.input = InputRequest{};
    v.finished = left_ <= 0;
    return v;
  }
  std::vector<std::string> answers_;
  std::vector<int> polls_per_answer_;

 private:
  int left_;
  int polls_ = 0;
};

struct Pipe {
  Pipe() { EXPECT_EQ(::pipe(fd), 0); }
  ~Pipe() {
    ::close(fd[0]);
    if (fd[1] >= 0) ::close(fd[1]);
  }
  void Write(const std::string& text) { EXPECT_EQ(::write(fd[1], text.data(), text.size()), static_cast<ssize_t>(text.size())); }
  int fd[2] = {-1, -1};
};

TEST(LineModeLive, TheSourceIsReadWhileAQuestionWaits) {
  Questions driver(1);
  Pipe pipe;
  std::thread technician([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    pipe.Write("turned\n");
  });
  std::ostringstream out;
  EXPECT_EQ(ui::RunLineModeOn(driver, pipe.fd[0], false, out), 0);
  technician.join();
  ASSERT_EQ(driver.answers_, std::vector<std::string>{"turned"});
  // 0.4 s at one poll per 0.05 s of waiting: the link was read all along (a loaded machine
  // may poll less often, never not at all).
  EXPECT_GE(driver.polls_per_answer_.at(0), 3) << out.str();
}

TEST(LineModeLive, LinesThatArriveTogetherAreAnsweredInOrderWithoutWaiting) {
  Questions driver(3);
  Pipe pipe;
  pipe.Write("one\ntwo\nthree");  // the last without its newline: the end of input ends it
  ::close(pipe.fd[1]);
  pipe.fd[1] = -1;
  std::ostringstream out;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(ui::RunLineModeOn(driver, pipe.fd[0], false, out), 0);
  EXPECT_EQ(driver.answers_, (std::vector<std::string>{"one", "two", "three"}));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

}  // namespace
}  // namespace accelcal
