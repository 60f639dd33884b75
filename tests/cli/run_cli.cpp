#include "run_cli.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace maquette::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempRoot {
  std::filesystem::path path;
  TempRoot() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "maquette-cli-XXXXXX").string();
    path = mkdtemp(tmpl.data());
  }
  ~TempRoot() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

TempRoot& root() {
  static TempRoot r;
  return r;
}

}  // namespace

std::string temp_dir() {
  static int counter = 0;
  const auto dir = root().path / ("d" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  return dir.string();
}

namespace {

// Runs `PREFIX maquette ARGS` through /bin/sh.
CliResult run_prefixed(const std::string& prefix, const std::string& args) {
  const std::string dir = temp_dir();
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  const std::string cmd =
      prefix + MAQUETTE_BIN_DIR + "/maquette " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// The sanitizer this build runs under, or nullptr (GCC defines these macros under -fsanitize).
const char* sanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return "AddressSanitizer";
#elif defined(__SANITIZE_THREAD__)
  return "ThreadSanitizer";
#else
  return nullptr;
#endif
}

}  // namespace

CliResult run_maquette(const std::string& args, const std::string& env) {
  return run_prefixed(env.empty() ? "" : "env " + env + " ", args);
}

std::string address_space_cap_unavailable() {
  if (sanitizer())
    return std::string("a build under ") + sanitizer() +
           " reserves terabytes of address space: no cap can hold it";
  return std::system("command -v prlimit >/dev/null") != 0 ? "no prlimit" : "";
}

std::string resident_memory_unmeasurable() {
  if (sanitizer())
    return std::string("a build under ") + sanitizer() +
           " keeps shadow memory (and freed blocks) resident";
  return "";
}

CliResult run_maquette_under(const std::string& wrapper, const std::string& args) {
  return run_prefixed(wrapper + " ", args);
}

CliResult run_maquette_limited(const std::string& args, int seconds) {
  return run_prefixed("timeout -s INT " + std::to_string(seconds) + " ", args);
}

CliResult run_maquette_traced(const std::string& args) {
  return run_maquette(args, "LD_DEBUG=files");
}

std::string start_trace() {
  const CliResult r = run_maquette_traced("--version");
  if (r.exit_code != 0) throw std::runtime_error("maquette --version failed: " + r.err);
  if (r.err.find("libmaquette.so") == std::string::npos)
    throw std::runtime_error("no loader trace: " + r.err);
  return r.err;
}

std::string plugin_path(const std::string& file) {
  return (std::filesystem::path(MAQUETTE_BIN_DIR).parent_path() / "lib" / file).string();
}

std::string install_without_plugins(const std::string& prefix) {
  namespace fs = std::filesystem;
  const fs::path build = fs::path(MAQUETTE_BIN_DIR).parent_path(), root(prefix);
  fs::create_directories(root / "bin");
  fs::create_directories(root / "lib");
  fs::copy_file(build / "bin" / "maquette", root / "bin" / "maquette");
  fs::create_symlink(build / "lib" / "libmaquette.so", root / "lib" / "libmaquette.so");
  return (root / "bin" / "maquette").string();
}

std::string shell_output(const std::string& command) {
  const std::string out = temp_dir() + "/stdout";
  [[maybe_unused]] const int status = std::system((command + " >" + out).c_str());  // see output
  return slurp(out);
}

int spawn_maquette(const std::string& args, const std::string& env) {
  const std::string prefix = env.empty() ? "" : "env " + env + " ";
  // exec, so that the pid is maquette's own and SIGKILL reaches it, not a shell.
  const std::string cmd =
      "exec " + prefix + MAQUETTE_BIN_DIR + "/maquette " + args + " >/dev/null 2>&1";
  const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
  pid_t pid = 0;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    return -1;
  return pid;
}

std::string file_fingerprint(const std::string& path) {
  if (!std::filesystem::exists(path)) return "";
  const std::string bytes = slurp(path);
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ULL;
  return std::to_string(bytes.size()) + ":" + std::to_string(h);
}

}  // namespace maquette::test
