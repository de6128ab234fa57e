#pragma once
// A text progress line for long jobs: "label  120/2000   6.0 %  elapsed 12 s  ETA 3m 08s", redrawn
// in place on a terminal, or printed every ~10 % when the stream is not a terminal.

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace graspecmf {

class ProgressLine {
 public:
  // Reports on `stream` (stderr by default); total must be > 0.
  ProgressLine(std::string label, std::size_t total, std::FILE* stream = stderr);
  // Records that `done` of total items are finished; redraws at most ~10 times per second.
  void update(std::size_t done);
  // Draws the final state and ends the line.
  void finish();

 private:
  void draw(std::size_t done);

  std::string label_;
  std::size_t total_;
  std::FILE* stream_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::size_t last_decile_ = 0;
  std::size_t done_ = 0;
};

// "42 s", "3m 08s" or "2h 05m".
std::string format_duration(double seconds);

}  // namespace graspecmf
