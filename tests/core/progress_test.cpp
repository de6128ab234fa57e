#include "graspecmf/core/progress.hpp"

#include <gtest/gtest.h>

#include <string>

#include "test_support.hpp"

namespace graspecmf {
namespace {

TEST(Progress, FormatsDurations) {
  EXPECT_EQ(format_duration(42.4), "42 s");
  EXPECT_EQ(format_duration(188), "3m 08s");
  EXPECT_EQ(format_duration(7500), "2h 05m");
  EXPECT_EQ(format_duration(-3), "0 s");
}

TEST(Progress, OffATerminalPrintsOneLinePerTenPercent) {
  testing::ScratchDir dir;
  std::FILE* file = std::fopen((dir / "log.txt").c_str(), "w");
  ASSERT_NE(file, nullptr);
  {
    ProgressLine progress("labelling", 200, file);
    for (std::size_t i = 1; i <= 200; ++i) progress.update(i);
    progress.finish();
  }
  std::fclose(file);
  const std::string log = testing::read_file(dir / "log.txt");
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 10) << log;
  EXPECT_NE(log.find("labelling  200/200  100.0 %"), std::string::npos) << log;
  EXPECT_NE(log.find("labelling  20/200   10.0 %"), std::string::npos) << log;
}

}  // namespace
}  // namespace graspecmf
