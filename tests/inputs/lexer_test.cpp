// SPDX-License-Identifier: MIT
// The line lexer: comments, continuation, delimiters, include, binary input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inputs/lexer.hpp"

using namespace tribex::inputs;
namespace fs = std::filesystem;

namespace {

std::vector<std::vector<std::string>> words_of(const std::string& text, DiagnosticSink& sink) {
  std::vector<std::vector<std::string>> out;
  for (const auto& line : lex_deck_text(text, "t.i", sink)) {
    out.emplace_back();
    for (const auto& w : line.words) out.back().push_back(w.text);
  }
  return out;
}

using Lines = std::vector<std::vector<std::string>>;

TEST(Lexer, CommentsNeedABlankBeforeThemMidLine) {
  DiagnosticSink sink;
  EXPECT_EQ(words_of("# whole line\n$ also\na = 1 # tail\nb=x#y $ tail\n", sink),
            (Lines{{"a", "=", "1"}, {"b", "=", "x#y"}}));
  EXPECT_TRUE(sink.empty());
}

TEST(Lexer, CommasTabsAndEqualsSigns) {
  DiagnosticSink sink;
  EXPECT_EQ(words_of("size=1,2\t3 nm\r\n", sink), (Lines{{"size", "=", "1", "2", "3", "nm"}}));
}

TEST(Lexer, ContinuationWithBackslashAndSierraForms) {
  DiagnosticSink sink;
  EXPECT_EQ(words_of("a = 1 \\\n  2\nb = 3 \\# comment\n 4\nc \\$\n= 5\n", sink),
            (Lines{{"a", "=", "1", "2"}, {"b", "=", "3", "4"}, {"c", "=", "5"}}));
}

TEST(Lexer, LocationsAreOneBasedLineAndColumn) {
  DiagnosticSink sink;
  const auto lines = lex_deck_text("\n  key = 7\n", "f.i", sink);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].where().str(), "f.i:2:3");
  EXPECT_EQ(lines[0].words[2].where.str(), "f.i:2:9");
}

TEST(Lexer, BinaryInputGivesOneError) {
  DiagnosticSink sink;
  std::string garbage = "begin sierra x\nab";
  for (int i = 0; i < 5000; ++i) garbage += static_cast<char>(i % 256);
  EXPECT_TRUE(words_of(garbage, sink).empty());
  EXPECT_EQ(sink.size(), 1u);
  try {
    sink.throw_if_any();
  } catch (const DeckError& e) {
    EXPECT_EQ(e.diagnostics()[0].where.str(), "t.i:2:3");
    EXPECT_NE(e.diagnostics()[0].message.find("byte offset 17"), std::string::npos);
  }
}

TEST(Lexer, Utf8Validation) {
  EXPECT_EQ(first_invalid_byte("1 \xC2\xB5m"), std::string_view::npos);  // µm
  EXPECT_EQ(first_invalid_byte("ab\xFF"), 2u);
  EXPECT_EQ(first_invalid_byte("a\xC0\x80"), 1u);   // overlong NUL
  EXPECT_EQ(first_invalid_byte("a\xED\xA0\x80"), 1u);  // surrogate
  EXPECT_EQ(first_invalid_byte("a\xE2\x82"), 1u);   // truncated
  EXPECT_EQ(first_invalid_byte(std::string_view("a\0b", 3)), 1u);
}

class IncludeFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tribex_lexer_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

TEST_F(IncludeFiles, SplicesRelativeToTheIncludingFile) {
  const std::string main = write("main.i", "a = 1\ninclude sub/part.inc\nd = 4\n");
  write("sub/part.inc", "b = 2\ninclude deeper.inc\n");
  write("sub/deeper.inc", "c = 3\n");
  DiagnosticSink sink;
  const auto lines = lex_deck_file(main, sink);
  EXPECT_TRUE(sink.empty());
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[1].words[0].text, "b");
  EXPECT_EQ(lines[1].where().file, (dir_ / "sub/part.inc").string());
  EXPECT_EQ(lines[2].where().file, (dir_ / "sub/deeper.inc").string());
  EXPECT_EQ(lines[2].where().line, 1);
  EXPECT_EQ(lines[3].words[0].text, "d");
}

TEST_F(IncludeFiles, MissingFileAndCycleAreErrorsAtTheIncludeLine) {
  const std::string a = write("a.i", "x = 1\ninclude b.inc\n");
  write("b.inc", "\ninclude a.i\ninclude nothing.inc\n");
  DiagnosticSink sink;
  lex_deck_file(a, sink);
  ASSERT_EQ(sink.size(), 2u);
  try {
    sink.throw_if_any();
  } catch (const DeckError& e) {
    EXPECT_EQ(e.diagnostics()[0].where.line, 2);
    EXPECT_EQ(e.diagnostics()[0].where.file, (dir_ / "b.inc").string());
    EXPECT_NE(e.diagnostics()[0].message.find("include cycle"), std::string::npos);
    EXPECT_EQ(e.diagnostics()[1].where.line, 3);
    EXPECT_NE(e.diagnostics()[1].message.find("no such file"), std::string::npos);
  }
}

TEST_F(IncludeFiles, DirectoriesAndDevicesAreNotDecks) {
  const std::string a = write("a.i", "include sub\ninclude /dev/zero\n");
  DiagnosticSink sink;
  lex_deck_file(a, sink);
  EXPECT_EQ(sink.size(), 2u);
}

}  // namespace

namespace {

TEST(Lexer, InputSizeIsBounded) {
  LexerLimits small;
  small.max_file_bytes = 100;
  small.max_total_bytes = 100;
  DiagnosticSink sink;
  EXPECT_TRUE(lex_deck_text(std::string(101, 'a'), "big.i", sink, small).empty());
  EXPECT_EQ(sink.size(), 1u);
}

}  // namespace

// Issue 29, item 4: a deck saved with a UTF-8 byte-order mark (some Windows editors) reads as without it.
TEST(Lexer, SkipsAUtf8ByteOrderMark) {
  DiagnosticSink sink;
  EXPECT_EQ(words_of("\xEF\xBB\xBF# deck\nbegin sierra s\n", sink), (Lines{{"begin", "sierra", "s"}}));
  EXPECT_TRUE(sink.empty());
  // Only at the start: elsewhere the bytes are part of the text as before.
  EXPECT_EQ(words_of("a = x\xEF\xBB\xBFy\n", sink), (Lines{{"a", "=", "x\xEF\xBB\xBFy"}}));
}
