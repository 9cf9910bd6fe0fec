// Progress of a long run on stderr: steps done of a known total with an ETA from the time per step so
// far; a bar redrawn in place on a terminal, one plain line per step otherwise (logs, CI).
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace app {

class Progress {
 public:
  Progress(std::string command, int total)
      : command_(std::move(command)), total_(total), start_(std::chrono::steady_clock::now()), terminal_(isatty(2)) {}
  void step(const std::string& what) {
    ++done_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = done_ > 0 ? elapsed / done_ * (total_ - done_) : 0;
    if (terminal_) {
      const int width = 30, filled = total_ ? width * std::min(done_, total_) / total_ : width;
      std::fprintf(stderr, "\r[%s%s] %d/%d steps, ETA %ds  %-40s", std::string(filled, '#').c_str(),
                   std::string(width - filled, ' ').c_str(), done_, total_, int(eta), what.c_str());
      if (done_ == total_) std::fprintf(stderr, "\n");
    } else {
      std::fprintf(stderr, "%s: %d/%d steps (ETA %ds) %s\n", command_.c_str(), done_, total_, int(eta), what.c_str());
    }
  }

 private:
  std::string command_;
  int total_, done_ = 0;
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
};

}  // namespace app
