// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tools' progress line: one line on a terminal, redrawn in
// place with \r at most ten times a second, shown only once the work has
// taken a second (short runs print nothing), erased by finish().  Off when
// the stream is not a terminal (isatty), so logs keep their plain lines.

#ifndef CGAL_FDT3_TOOLS_PROGRESS_BAR_H
#define CGAL_FDT3_TOOLS_PROGRESS_BAR_H

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace fdt3_tools {

class Progress_bar
{
public:
  // `enabled` is also cleared when `stream` is not a terminal.
  Progress_bar(std::FILE* stream, bool enabled) : stream_(stream), enabled_(enabled && isatty(fileno(stream))) {}
  ~Progress_bar() { finish(); }
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  bool enabled() const { return enabled_; }

  // "phase [#######.......]  42%  3.1 s": done of total.
  void update(const char* phase, std::size_t done, std::size_t total)
  {
    if(!due(done >= total)) return;
    const double fraction = total == 0 ? 1.0 : std::min(1.0, double(done) / double(total));
    const int width = 40, filled = int(fraction * width + 0.5);
    char line[160];
    std::snprintf(line, sizeof(line), "%-7s [%s%s] %3d%%  %.1f s", phase, std::string(filled, '#').c_str(),
                  std::string(width - filled, '.').c_str(), int(fraction * 100), elapsed());
    draw(line);
  }
  // "phase  text  3.1 s": for work without a known total.
  void update(const char* phase, const std::string& text)
  {
    if(!due(false)) return;
    char line[200];
    std::snprintf(line, sizeof(line), "%-7s %s  %.1f s", phase, text.c_str(), elapsed());
    draw(line);
  }
  // Erases the line (the next output starts at the left margin).
  void finish()
  {
    if(!shown_) return;
    std::fprintf(stream_, "\r%*s\r", int(last_length_), "");
    std::fflush(stream_);
    shown_ = false;
  }

private:
  typedef std::chrono::steady_clock Clock;
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  // Whether to redraw now: after the first second, then every 0.1 s (and
  // at the end of a phase, so that 100% shows).
  bool due(bool phase_end)
  {
    if(!enabled_) return false;
    const Clock::time_point now = Clock::now();
    if(now - start_ < std::chrono::seconds(1)) return false;
    if(!phase_end && shown_ && now - last_draw_ < std::chrono::milliseconds(100)) return false;
    last_draw_ = now;
    return true;
  }
  void draw(const char* line)
  {
    const std::size_t length = std::string(line).size();
    std::fprintf(stream_, "\r%s%*s", line, int(last_length_ > length ? last_length_ - length : 0), "");
    std::fflush(stream_);
    last_length_ = length;
    shown_ = true;
  }

  std::FILE* stream_;
  bool enabled_;
  bool shown_ = false;
  std::size_t last_length_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_;
};

} // namespace fdt3_tools

#endif // CGAL_FDT3_TOOLS_PROGRESS_BAR_H
