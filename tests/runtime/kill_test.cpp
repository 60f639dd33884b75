// Resume after a real kill: a child process runs the pipeline and is killed with SIGKILL at
// several moments; the store must pass the integrity check, and --resume must end with tiles
// and artifacts bit-identical to an uninterrupted run.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "runtime/runner.h"
#include "store/store.h"
#include "test_util.h"

extern char** environ;

namespace maquette {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kChild = std::string(MAQUETTE_BIN_DIR) + "/runtime_kill_child";

pid_t start_child(const std::string& pipeline) {
  const std::string modules = test::fixture_dir("good");
  char* argv[] = {const_cast<char*>(kChild.c_str()), const_cast<char*>(pipeline.c_str()),
                  const_cast<char*>(modules.c_str()), nullptr};
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, kChild.c_str(), nullptr, nullptr, argv, environ), 0);
  return pid;
}

// Waits for the child; true when it was killed by a signal.
bool wait_child(pid_t pid, int* exit_code = nullptr) {
  int status = 0;
  waitpid(pid, &status, 0);
  if (exit_code != nullptr) *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return WIFSIGNALED(status);
}

// 64 cells, slowed down so that the run lasts a few hundred milliseconds.
const nlohmann::json kPipeline = test::demo_pipeline(3, 5);

TEST(Kill, ResumeAfterSigkillIsBitIdentical) {
  test::TempDir reference;
  const auto start = Clock::now();
  int exit_code = -1;
  wait_child(start_child(test::write_pipeline(reference, kPipeline)), &exit_code);
  ASSERT_EQ(exit_code, 0);
  const auto full = Clock::now() - start;
  const auto expected = test::snapshot(reference.file("out.mqt"));

  // Kills the run after `fraction` of the uninterrupted run's time, resumes it, and compares;
  // true when the kill interrupted a run with some cells done.
  const auto kill_and_resume = [&](double fraction) {
    SCOPED_TRACE("killed after " + std::to_string(fraction) + " of a run");
    test::TempDir dir;
    const std::string pipeline = test::write_pipeline(dir, kPipeline);
    const pid_t pid = start_child(pipeline);
    std::this_thread::sleep_for(std::chrono::duration_cast<Clock::duration>(full * fraction));
    kill(pid, SIGKILL);
    const bool killed = wait_child(pid);

    const std::string store_path = dir.file("out.mqt");
    if (std::filesystem::exists(store_path)) {
      // A store appears only complete (created under another name, then linked into place).
      const auto store = Store::open(store_path, Store::Mode::ReadOnly);
      EXPECT_TRUE(store->integrity_ok());
    }
    RunOptions options;
    options.threads = 2;
    options.quiet = true;
    options.resume = true;
    const RunSummary summary = run_pipeline(test::load_fixture_pipeline(pipeline), options);
    int64_t skipped = 0;
    for (const auto& s : summary.steps) skipped += s.skipped;
    EXPECT_EQ(test::first_difference(expected, test::snapshot(store_path)), "");
    return killed && summary.resumed && skipped > 0;
  };
  int killed_mid_run = 0;
  for (const double fraction : {0.02, 0.3, 0.5, 0.7, 0.9})
    killed_mid_run += kill_and_resume(fraction);
  // On a loaded machine a run's time varies, so the kills above may all miss the middle of a
  // run: a few more tries in the middle, until two interrupted runs were resumed.
  for (int extra = 0; extra < 8 && killed_mid_run < 2; ++extra) {
    killed_mid_run += kill_and_resume(0.3 + 0.05 * extra);
  }
  EXPECT_GE(killed_mid_run, 2) << "the kills should have interrupted runs with some cells done";
}

}  // namespace
}  // namespace maquette
