// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tools' progress line: one line on a terminal, redrawn in
// place with \r ten times a second, shown only once the work has taken a
// second (short runs print nothing), erased by finish().  Off when the
// stream is not a terminal (isatty), so logs keep their plain lines.

#ifndef CGAL_FDT3_TOOLS_PROGRESS_BAR_H
#define CGAL_FDT3_TOOLS_PROGRESS_BAR_H

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace fdt3_tools {

// update() only records the state (callers may be the library's worker
// threads, calling every few thousand points); a thread of its own draws
// it every 0.1 s, so the elapsed time also moves during a phase that
// reports nothing (the sort, the write).
class Progress_bar
{
public:
  // `enabled` is also cleared when `stream` is not a terminal.
  Progress_bar(std::FILE* stream, bool enabled) : stream_(stream), enabled_(enabled && isatty(fileno(stream)))
  {
    if(enabled_) drawer_ = std::thread([this] { draw_until_finished(); });
  }
  ~Progress_bar() { finish(); }
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  bool enabled() const { return enabled_; }

  // "phase [#######.......]  42%  3.1 s": done of total.
  void update(const char* phase, std::size_t done, std::size_t total)
  {
    if(!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = phase;
    fraction_ = total == 0 ? 1.0 : std::min(1.0, double(done) / double(total));
    text_.clear();
  }
  // "phase  text  3.1 s": for work without a known total.
  void update(const char* phase, const std::string& text)
  {
    if(!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = phase;
    fraction_ = -1;
    text_ = text;
  }
  // Stops the drawing and erases the line (the next output starts at the
  // left margin).
  void finish()
  {
    if(!drawer_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished_ = true;
    }
    wake_.notify_one();
    drawer_.join();
    if(last_length_ > 0) {
      std::fprintf(stream_, "\r%*s\r", int(last_length_), "");
      std::fflush(stream_);
    }
  }

private:
  typedef std::chrono::steady_clock Clock;

  void draw_until_finished()
  {
    const Clock::time_point start = Clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    // Nothing for the first second: short runs print no progress at all.
    if(wake_.wait_until(lock, start + std::chrono::seconds(1), [this] { return finished_; })) return;
    while(!finished_) {
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      char line[240];
      if(phase_.empty()) {
        line[0] = '\0';
      } else if(fraction_ >= 0) {
        const int width = 40, filled = int(fraction_ * width + 0.5);
        std::snprintf(line, sizeof(line), "%-7s [%s%s] %3d%%  %.1f s", phase_.c_str(),
                      std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                      int(fraction_ * 100), seconds);
      } else {
        std::snprintf(line, sizeof(line), "%-7s %s  %.1f s", phase_.c_str(), text_.c_str(), seconds);
      }
      const std::size_t length = std::string(line).size();
      std::fprintf(stream_, "\r%s%*s", line, int(last_length_ > length ? last_length_ - length : 0), "");
      std::fflush(stream_);
      last_length_ = length;
      wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return finished_; });
    }
  }

  std::FILE* stream_;
  bool enabled_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread drawer_;
  bool finished_ = false;
  std::string phase_, text_;
  double fraction_ = -1;
  std::size_t last_length_ = 0; // written by the drawer only, read after it stopped
};

} // namespace fdt3_tools

#endif // CGAL_FDT3_TOOLS_PROGRESS_BAR_H
