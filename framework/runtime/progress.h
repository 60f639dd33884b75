// Progress of one step: a bar on stderr when it is a terminal, otherwise a log line every 10% or
// 5 seconds, with cells done/total and the rate. Thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace maquette {

class Progress {
 public:
  Progress(std::string label, int64_t total, bool quiet);
  ~Progress();  // finish() if not done
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(int64_t cells = 1);
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void report(bool final);  // called with mutex_ held

  std::string label_;
  int64_t total_;
  bool quiet_, tty_;
  bool finished_ = false;
  int64_t done_ = 0;
  int64_t next_log_done_ = 0;  // log mode: next 10% mark
  Clock::time_point start_, last_report_;
  std::mutex mutex_;
};

}  // namespace maquette
