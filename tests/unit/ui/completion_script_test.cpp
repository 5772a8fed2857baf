// What the bash completion offers for each option, decided from the option itself
// (ui/cli/completion_script.h), and the script's tables written from the command line.
#include <gtest/gtest.h>

#include "cli/cli_checks.h"
#include "cli/completion_script.h"
#include "cli/shipped_files.h"

namespace accelcal::cli::completion_script_test {
namespace {

bool Has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Options {
  CLI::App app{"demo", "demo"};
  std::string text;
  double number = 0;
  unsigned count = 0;
  bool flag = false;
  std::vector<std::string> many;
};

TEST(CompletionScript, ValueKindComesFromTheOption) {
  Options o;
  CLI::App* sub = o.app.add_subcommand("run", "Run");
  const auto kind = [](const CLI::Option* opt) { return ValueSpecOf(*opt).kind; };
  EXPECT_EQ(kind(sub->add_flag("--plain", o.flag, "")), ValueKind::kFlag);
  EXPECT_EQ(kind(sub->add_option("--source", o.text, "")), ValueKind::kSource);
  EXPECT_EQ(kind(sub->add_option("--session", o.text, "")), ValueKind::kSession);
  EXPECT_EQ(kind(sub->add_option("session", o.text, "")), ValueKind::kSession);
  EXPECT_EQ(kind(sub->add_option("--sessions-dir", o.text, "")), ValueKind::kDirectory);
  EXPECT_EQ(kind(sub->add_option("--speed", o.number, "")->check(NonNegative())), ValueKind::kNone);
  EXPECT_EQ(kind(sub->add_option("--seed", o.count, "")), ValueKind::kNone);
  EXPECT_EQ(kind(sub->add_option("--device", o.text, "")), ValueKind::kNone);
  EXPECT_EQ(kind(sub->add_option("-o,--output", o.text, "")), ValueKind::kFile);
  EXPECT_EQ(kind(sub->add_option("captures", o.text, "")), ValueKind::kFile);
  EXPECT_EQ(kind(sub->add_option("--procedure", o.text, "")->transform(ShippedFile(kShippedProcedures))),
            ValueKind::kProcedure);
  EXPECT_EQ(kind(sub->add_option("scenario", o.text, "")->transform(ShippedFile(kShippedScenarios))),
            ValueKind::kScenario);
  const CLI::Option* format = sub->add_option("--format", o.text, "")->check(CLI::IsMember({"text", "m/s^2"}));
  EXPECT_EQ(ValueSpecOf(*format).kind, ValueKind::kChoices);
  EXPECT_EQ(ValueSpecOf(*format).choices, (std::vector<std::string>{"text", "m/s^2"}));
}

TEST(CompletionScript, SourceFormsAreTheParsersOwn) {
  const std::vector<std::string> forms = SourceForms();
  for (const char* form : {"sim", "file:PATH", "serial:DEVICE@BAUD", "tcp:HOST:PORT", "-"})
    EXPECT_NE(std::find(forms.begin(), forms.end(), form), forms.end()) << form;
}

TEST(CompletionScript, TablesWalkTheCommandLine) {
  Options o;
  CLI::App* run = o.app.add_subcommand("run", "Run");
  run->add_option("input", o.text, "");
  run->add_option("more", o.many, "");
  run->add_option("--to", o.text, "")->check(CLI::IsMember({"a", "b"}));
  run->add_flag("-q,--quiet", o.flag, "");
  o.app.add_subcommand("lab", "Lab")->add_subcommand("add", "Add")->add_option("--name", o.text, "");
  o.app.add_subcommand("help-man", "hidden")->group("");
  const std::string script = BashCompletionScript(o.app, "demo");
  EXPECT_TRUE(Has(script, "    'commands:') REPLY='run lab' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'options:run') REPLY='-h --help --to -q --quiet' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'positionals:run') REPLY='file file...' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'value:run:--to') REPLY='choices a b' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'value:run:-q') REPLY='flag' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'commands:lab') REPLY='add' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'value:lab add:--name') REPLY='file' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "    'sources') REPLY='sim file:PATH serial:DEVICE@BAUD tcp:HOST:PORT mavlink:LINK iio:NAME -' ;;\n")) << script;
  EXPECT_TRUE(Has(script, "\ncomplete -F _accelcal demo\n")) << script;
  EXPECT_FALSE(Has(script, "help-man")) << script;
}

}  // namespace
}  // namespace accelcal::cli::completion_script_test
