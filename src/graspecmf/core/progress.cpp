#include "graspecmf/core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace graspecmf {

std::string format_duration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  if (s < 60) {
    std::snprintf(text, sizeof(text), "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof(text), "%ldm %02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ldh %02ldm", s / 3600, (s % 3600) / 60);
  }
  return text;
}

ProgressLine::ProgressLine(std::string label, std::size_t total, std::FILE* stream)
    : label_(std::move(label)),
      total_(total),
      stream_(stream),
      terminal_(::isatty(::fileno(stream)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void ProgressLine::update(std::size_t done) {
  done_ = done;
  const auto now = std::chrono::steady_clock::now();
  const std::size_t decile = total_ == 0 ? 10 : 10 * done / total_;
  if (terminal_ ? now - last_draw_ >= std::chrono::milliseconds(100) : decile > last_decile_) {
    last_draw_ = now;
    last_decile_ = decile;
    draw(done);
  }
}

void ProgressLine::finish() {
  if (terminal_ || last_decile_ < 10) draw(done_);  // off a terminal, 100 % is already printed
  if (terminal_) std::fputc('\n', stream_);
}

void ProgressLine::draw(std::size_t done) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction =
      total_ == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total_);
  const std::string eta =
      done == 0 ? "?" : format_duration(elapsed * (1.0 - fraction) / std::max(fraction, 1e-12));
  std::fprintf(stream_, "%s%s  %zu/%zu  %5.1f %%  elapsed %s  ETA %s%s", terminal_ ? "\r" : "",
               label_.c_str(), done, total_, 100.0 * fraction, format_duration(elapsed).c_str(),
               eta.c_str(), terminal_ ? "\033[K" : "\n");
  std::fflush(stream_);
}

}  // namespace graspecmf
