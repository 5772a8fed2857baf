// The manual pages written from the command line's definition (ui/cli/man_page.h): one page per
// visible command, the --help texts in roff, escaped, with their headings as sections.
#include <gtest/gtest.h>

#include "cli/man_page.h"

namespace accelcal::cli::man_page_test {
namespace {

bool Has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A command line shaped like accelcal's: a visible command with a positional, a choice, a flag
// and a footer of examples; a command with its own subcommand; a hidden command.
struct DemoApp {
  CLI::App app{"demo: try things out.\n\nMore words.", "demo"};
  std::string input, format = "text";
  bool quiet = false;
  DemoApp() {
    CLI::App* run = app.add_subcommand("run", "Run the thing: fast, on a file.\nSecond line.");
    run->add_option("input", input, "Input file")->required();
    run->add_option("--format", format, "text or json")->check(CLI::IsMember({"text", "json"}));
    run->add_flag("-q,--quiet", quiet, ".starts with a dot, and a back\\slash");
    run->footer("Examples:\n  demo run x.txt --format json\n  demo run -q y.txt");
    CLI::App* lab = app.add_subcommand("lab", "The lab's store.");
    lab->add_subcommand("add", "Add a bench.")->add_option("--name", input, "Bench name");
    app.add_subcommand("help-man", "hidden")->group("");
  }
};

TEST(ManPage, OnePagePerVisibleCommand) {
  DemoApp demo;
  const std::vector<ManPage> pages = ManPages(demo.app, {"demo 1.0", {"demo-format(5)"}});
  ASSERT_EQ(pages.size(), 3u);
  EXPECT_EQ(pages[0].name, "demo");
  EXPECT_EQ(pages[1].name, "demo-run");
  EXPECT_EQ(pages[2].name, "demo-lab");
  for (const ManPage& page : pages) {
    EXPECT_EQ(page.section, 1);
    EXPECT_TRUE(Has(page.roff, "\"demo 1.0\"")) << page.roff;
    EXPECT_TRUE(Has(page.roff, "\\fBdemo\\-format\\fR(5)")) << page.roff;
    EXPECT_FALSE(Has(page.roff, "help\\-man")) << page.roff;
  }
}

TEST(ManPage, CommandPageHoldsTheHelpTexts) {
  DemoApp demo;
  const std::string roff = ManPages(demo.app, {"demo 1.0", {}})[1].roff;
  EXPECT_TRUE(Has(roff, ".TH \"DEMO-RUN\" \"1\"")) << roff;
  EXPECT_TRUE(Has(roff, ".SH NAME\ndemo\\-run \\- Run the thing\n")) << roff;
  EXPECT_TRUE(Has(roff, ".SH SYNOPSIS\n\\fBdemo run [OPTIONS] input\\fR\n")) << roff;
  EXPECT_TRUE(Has(roff, ".SH DESCRIPTION\nRun the thing: fast, on a file.\nSecond line.\n")) << roff;
  // The option columns as --help prints them: names, then type, choices, REQUIRED.
  EXPECT_TRUE(Has(roff, ".SH ARGUMENTS\n.TP\n\\fBinput\\fR TEXT REQUIRED\nInput file\n")) << roff;
  EXPECT_TRUE(Has(roff, ".TP\n\\fB\\-\\-format\\fR TEXT:{text,json}\ntext or json\n")) << roff;
  EXPECT_TRUE(Has(roff, ".TP\n\\fB\\-q,\\-\\-quiet\\fR\n\\&.starts with a dot, and a back\\eslash\n")) << roff;
  // The footer's "Examples:" is a section; its lines are kept as typed.
  EXPECT_TRUE(Has(roff, ".SH EXAMPLES\n.nf\n  demo run x.txt \\-\\-format json\n  demo run \\-q y.txt\n.fi\n")) << roff;
  EXPECT_TRUE(Has(roff, ".SH SEE ALSO\n\\fBdemo\\fR(1)\n")) << roff;
}

TEST(ManPage, SubcommandsAreSectionsOfTheirCommandsPage) {
  DemoApp demo;
  const std::string roff = ManPages(demo.app, {"demo 1.0", {}})[2].roff;
  EXPECT_TRUE(Has(roff, ".SH COMMANDS\n.SS \"demo lab add\"\n")) << roff;
  EXPECT_TRUE(Has(roff, "\\fB\\-\\-name\\fR TEXT\nBench name\n")) << roff;
}

TEST(ManPage, RootPageListsTheCommands) {
  DemoApp demo;
  const std::string roff = ManPages(demo.app, {"demo 1.0", {}})[0].roff;
  EXPECT_TRUE(Has(roff, ".SH NAME\ndemo \\- try things out\n")) << roff;
  EXPECT_TRUE(Has(roff, ".TP\n\\fBrun\\fR\nRun the thing\n.br\nSee \\fBdemo\\-run\\fR(1).\n")) << roff;
  EXPECT_TRUE(Has(roff, "\\fBdemo\\-run\\fR(1),\n\\fBdemo\\-lab\\fR(1)\n")) << roff;
}

TEST(ManPage, TextBecomesParagraphsAndKeptLines) {
  EXPECT_EQ(RoffText("one\ntwo\n\nthree", true), "one\ntwo\n.PP\nthree\n");
  EXPECT_EQ(RoffText("Table:\n  a   1\n  b   2\nafter", true), ".SH TABLE\n.nf\n  a   1\n  b   2\n.fi\nafter\n");
  // A heading is only a short line followed by kept lines; in a subsection it stays text.
  EXPECT_EQ(RoffText("Write a file in another format:\n  csv  rows", true),
            "Write a file in another format:\n.nf\n  csv  rows\n.fi\n");
  EXPECT_EQ(RoffText("Examples:\n  x", false), "Examples:\n.nf\n  x\n.fi\n");
  EXPECT_EQ(RoffText("'quoted' `cmd` -x", true), "\\(aqquoted\\(aq \\(gacmd\\(ga \\-x\n");
}

TEST(ManPage, SummaryIsTheFirstSentence) {
  EXPECT_EQ(Summary("Guided calibration at the bench: level the table."), "Guided calibration at the bench");
  EXPECT_EQ(Summary("Run a scenario (a bench: static poses) and write it.\nMore."),
            "Run a scenario (a bench: static poses) and write it");
  EXPECT_EQ(Summary("Apply a calibration file to raw samples: reads"), "Apply a calibration file to raw samples");
  EXPECT_EQ(Summary("a file.txt name. Then"), "a file.txt name");
  EXPECT_EQ(Summary("No end"), "No end");
}

}  // namespace
}  // namespace accelcal::cli::man_page_test
