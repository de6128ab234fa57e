// The page `graspecmf view --out` writes, opened from a file:// URL in headless Chromium: the
// screenshot shows the shaded mug in the middle and green and red gripper markers, and the page
// logs nothing to the console (an uncaught script error is logged there as "Uncaught ...").
// Chromium is a test dependency (scripts/install-deps --tests); without it these tests fail.

#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::testing::CliRun;
using graspecmf::testing::read_file;
using graspecmf::testing::ScratchDir;

constexpr int kWidth = 800, kHeight = 600;

// The chromium executable on PATH, or an empty path.
fs::path find_chromium() {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder) / "chromium";
    if (!folder.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

struct Screenshot {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  std::array<int, 3> at(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

struct BrowserRun {
  Screenshot screenshot;
  std::vector<std::string> console;  // the page's console messages, one per line
};

// Opens `page` from its file:// URL in headless Chromium, kWidth × kHeight, lets it run for a few
// seconds of virtual time and takes a screenshot. Adds a test failure if Chromium is missing or
// fails.
BrowserRun open_in_chromium(const fs::path& page, const ScratchDir& dir) {
  const fs::path chromium = find_chromium();
  if (chromium.empty()) {
    ADD_FAILURE() << "chromium is not installed (no `chromium` on PATH). These tests open the "
                     "page of `graspecmf view` in a headless browser; install the test "
                     "dependencies with `scripts/install-deps --tests` (Debian package chromium).";
    return {};
  }
  const fs::path shot = dir / "screenshot.png", log = dir / "chromium.log";
  const std::string url = "file://" + fs::absolute(page).string();
  const std::string command =
      "timeout 60 " + chromium.string() +
      " --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run" +
      " --user-data-dir=" + (dir / "profile").string() +
      " --window-size=" + std::to_string(kWidth) + "," + std::to_string(kHeight) +
      " --virtual-time-budget=3000 --enable-logging=stderr --v=0 --screenshot=" + shot.string() +
      " " + url + " >" + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  BrowserRun run;
  const std::string output = read_file(log);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ADD_FAILURE() << "chromium failed (status " << status << "):\n" << output;
    return run;
  }
  // Console lines look like `[...:INFO:CONSOLE:1] "message", source: file:///.../view.html (1)`.
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(":CONSOLE") != std::string::npos) run.console.push_back(line);
  }
  int channels = 0;
  unsigned char* pixels =
      stbi_load(shot.c_str(), &run.screenshot.width, &run.screenshot.height, &channels, 3);
  if (pixels == nullptr) {
    ADD_FAILURE() << "no screenshot from chromium:\n" << output;
    return run;
  }
  run.screenshot.rgb.assign(pixels, pixels + 3 * run.screenshot.width * run.screenshot.height);
  stbi_image_free(pixels);
  return run;
}

// The page's surface shading: rgb(s, s, s + 25) with s in [60, 230], blended at triangle edges.
bool is_surface(const std::array<int, 3>& c) {
  return std::abs(c[0] - c[1]) <= 3 && c[2] - c[0] >= 15 && c[2] - c[0] <= 35 && c[0] >= 50 &&
         c[0] <= 235;
}
// The view command's label colours rgb(40, 160, 60) and rgb(200, 50, 50), allowing antialiasing.
bool is_green(const std::array<int, 3>& c) {
  return c[1] - c[0] > 60 && c[1] - c[2] > 50;
}
bool is_red(const std::array<int, 3>& c) {
  return c[0] - c[1] > 80 && c[0] - c[2] > 80;
}

struct PixelCounts {
  int surface_in_middle = 0;  // within w/8 and h/8 of the window's centre (1/16 of its area)
  int green = 0, red = 0, other = 0;
};

PixelCounts count_pixels(const Screenshot& s) {
  PixelCounts n;
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const auto c = s.at(x, y);
      const bool middle =
          std::abs(2 * x - s.width) < s.width / 4 && std::abs(2 * y - s.height) < s.height / 4;
      n.surface_in_middle += middle && is_surface(c);
      n.green += is_green(c);
      n.red += is_red(c);
    }
  }
  return n;
}

// Writes the view page of 40 of the sample's grasps into dir.
fs::path write_sample_page(const ScratchDir& dir) {
  const fs::path page = dir / "view.html";
  const CliRun r =
      graspecmf::testing::run("view " + graspecmf::testing::sample_grasp_file().string() +
                                  " --max 40 --out " + page.string(),
                              dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return page;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

TEST(BrowserView, TheSamplePageDrawsTheMugAndMarkersWithoutScriptErrors) {
  ScratchDir dir;
  const BrowserRun run = open_in_chromium(write_sample_page(dir), dir);
  ASSERT_FALSE(HasFailure());
  EXPECT_TRUE(run.console.empty()) << "the page logged to the console:\n" << joined(run.console);
  ASSERT_EQ(run.screenshot.width, kWidth);
  ASSERT_EQ(run.screenshot.height, kHeight);
  const PixelCounts n = count_pixels(run.screenshot);
  // The mug is centred in the canvas and spans about a third of it: more than half of the middle
  // region shows its shaded surface (about 70 % does, the rest is covered by markers).
  EXPECT_GT(n.surface_in_middle, kWidth * kHeight / 16 / 2);
  // 40 markers of four 1.5-pixel lines, each 5–11 cm long: about 10,000 pixels of each colour.
  EXPECT_GT(n.green, 2000);
  EXPECT_GT(n.red, 2000);
}

TEST(BrowserView, ABrokenPageFailsTheseChecks) {
  // The same page with its scene JSON made invalid: JSON.parse throws before anything is drawn.
  ScratchDir dir;
  std::string html = read_file(write_sample_page(dir));
  const std::size_t at = html.find("{\"vertices\":[");
  ASSERT_NE(at, std::string::npos);
  html.insert(at + 1, ",");
  const fs::path broken = dir / "broken.html";
  graspecmf::testing::write_file(broken, html);
  const BrowserRun run = open_in_chromium(broken, dir);
  ASSERT_FALSE(HasFailure());
  ASSERT_FALSE(run.console.empty());
  EXPECT_NE(joined(run.console).find("Uncaught SyntaxError"), std::string::npos)
      << joined(run.console);
  const PixelCounts n = count_pixels(run.screenshot);
  EXPECT_EQ(n.surface_in_middle, 0);
  EXPECT_EQ(n.green + n.red, 0);
}

}  // namespace
