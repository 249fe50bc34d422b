// A progress bar on stderr for long commands, drawn only when stderr is a terminal (so logs
// and pipes stay clean) and at most ten times a second.
#pragma once

#include <chrono>
#include <string>

namespace genmod::app {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();  // clears the bar
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Shows `fraction` (clamped to 0..1) done.
  void update(double fraction);

 private:
  void clear();

  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace genmod::app
