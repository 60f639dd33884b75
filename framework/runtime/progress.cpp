#include "runtime/progress.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

namespace maquette {
namespace {

constexpr auto kBarInterval = std::chrono::milliseconds(100);
constexpr auto kLogInterval = std::chrono::seconds(5);
constexpr int kBarWidth = 30;

}  // namespace

Progress::Progress(std::string label, int64_t total, bool quiet)
    : label_(std::move(label)),
      total_(total),
      quiet_(quiet),
      tty_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      last_report_(start_) {
  next_log_done_ = (total_ + 9) / 10;
}

Progress::~Progress() { finish(); }

void Progress::advance(int64_t cells) {
  std::lock_guard lock(mutex_);
  done_ += cells;
  if (quiet_) return;
  const auto now = Clock::now();
  // The last line is finish()'s.
  if (tty_ ? now - last_report_ >= kBarInterval
           : done_ < total_ && (done_ >= next_log_done_ || now - last_report_ >= kLogInterval))
    report(false);
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (!quiet_) report(true);
}

void Progress::report(bool final) {
  const auto now = Clock::now();
  last_report_ = now;
  while (next_log_done_ <= done_ && next_log_done_ < total_) next_log_done_ += (total_ + 9) / 10;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0 ? double(done_) / seconds : 0.0;
  const int percent = total_ > 0 ? int(100 * done_ / total_) : 100;
  if (tty_) {
    const int filled = kBarWidth * percent / 100;
    std::fprintf(stderr, "\r%s [%s%s] %3d%% %lld/%lld cells, %.1f cells/s%s", label_.c_str(),
                 std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kBarWidth - filled), '.').c_str(), percent,
                 static_cast<long long>(done_), static_cast<long long>(total_), rate,
                 final ? "\n" : "");
    std::fflush(stderr);
  } else {
    if (final)
      spdlog::info("{}: {}/{} cells in {:.1f} s, {:.1f} cells/s", label_, done_, total_, seconds,
                   rate);
    else
      spdlog::info("{}: {}/{} cells ({}%), {:.1f} cells/s", label_, done_, total_, percent, rate);
  }
}

}  // namespace maquette
